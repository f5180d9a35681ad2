//! `qsic`: exact classification of the intersection curve of two quadric surfaces.
//! The command line is defined here; the work is done by the `qsic_cli` library.
//!
//! Exit codes: 0 success; 1 bad input (single query) or at least one failed line (batch);
//! 2 usage error, unreadable input file or an I/O error.

use clap::{Args, CommandFactory, Parser, Subcommand};
use qsic::param::sample::SampleOptions;
use qsic::Quadric;
use qsic_cli::{batch, input, output, param, sample};
use std::fs::File;
use std::io::{self, IsTerminal, Write};
use std::path::PathBuf;
use std::process::ExitCode;

const CLASSIFY_HELP: &str = "\
QUADRICS:
  A polynomial of degree 2 in x, y, z, w: homogeneous (\"x^2+y^2+z^2-w^2\") or affine in
  x, y, z (\"x^2+y^2+z^2-1\", homogenized with w). Operators + - * / ^ (or **), parentheses,
  exact numbers: 3, 3/4, 0.1, 2.5e-3 (0.1 is one tenth, never a float).
  Or a symmetric 4x4 matrix as a JSON array of rows, e.g.
  \"[[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,-1]]\"; entries are numbers or strings (\"3/4\").
  One of A and B may be the zero form \"0\": the pencil is then the other quadric alone.
  A polynomial starting with '-' is accepted as is, or after '--'.

BATCH (--batch FILE, or --batch - for standard input):
  JSON Lines in: {\"id\": ..., \"A\": ..., \"B\": ...}, each quadric a polynomial string or a
  4x4 array of numbers or number strings; other fields are ignored. JSON Lines out on
  standard output: one line per non-blank input line, in input order, with the same id
  (null if missing): the result object, or
  {\"id\": ..., \"error\": {\"line\": n, \"message\": \"...\"}} with n the 1-based input line.
  Blank lines are skipped but counted in line numbers. Lines longer than 1 MiB are
  answered with an error without being stored. All cores are used; output is written
  and flushed chunk by chunk. A progress spinner appears on stderr if it is a terminal.

EXIT STATUS:
  0  success (batch: every line classified)
  1  bad input (single query: message on stderr) or, in a batch, at least one error line
  2  usage error, unreadable input file, or an I/O error

EXAMPLES:
  qsic classify \"x^2+y^2+z^2-w^2\" \"2*x^2+4*y^2-w^2\"
  qsic classify --json \"x^2+y^2+z^2-4\" \"(x-1)^2+y^2+z^2-4\"
  qsic classify --batch cases.jsonl > results.jsonl
  cat cases.jsonl | qsic classify --batch -";

/// Exact classification of the intersection curve of two quadric surfaces.
///
/// Reads two quadrics exactly (rational arithmetic, no floating point), and reports the
/// kind of their pencil, the case among the 35 of Tu, Wang, Mourrain and Wang (2009),
/// the Segre characteristic, signature and index sequences, and the complex and real
/// type of the intersection curve with its real components.
#[derive(Parser, Debug)]
#[command(
    name = "qsic",
    version,
    arg_required_else_help = true,
    after_help = "Run 'qsic classify --help' for the input forms, the batch format and the exit codes."
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// Classify the intersection of two quadrics A and B, or of many pairs (--batch).
    ///
    /// Prints the pencil kind (regular, singular or single), the case number, the Segre
    /// characteristic, the signature and index sequences, the complex and real type, a
    /// one-line summary, and the real components and singular points of the curve.
    Classify(ClassifyArgs),
    /// The exact curve: every component's parameterization, singular points (--json, --batch).
    ///
    /// Each real component is given exactly: a point, X(u) with u over the real projective
    /// line, or Levin's X(u) ± d(u)·sqrt(s(u)); numbers are integers, fractions, square
    /// roots, or named algebraic numbers listed under "numbers".
    Param(ParamArgs),
    /// Real points on every real component: polylines in projective and affine coordinates.
    ///
    /// Points come from the exact parameterization, ordered along each piece, consecutive
    /// unit vectors at most 0.1 rad apart; the affine chart splits pieces at infinity.
    Sample(SampleArgs),
}

/// Arguments of `qsic param`.
#[derive(Args, Debug)]
#[command(after_help = "Input forms, batch format and exit codes as for 'qsic classify --help'.")]
struct ParamArgs {
    #[command(flatten)]
    input: PairArgs,

    /// Print one JSON object instead of the text report (batch output is always JSON).
    #[arg(long)]
    json: bool,
}

/// Output formats of `qsic sample`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
enum Format {
    Json,
    Csv,
    Obj,
}

/// Arguments of `qsic sample`.
#[derive(Args, Debug)]
#[command(after_help = "Input forms, batch format and exit codes as for 'qsic classify --help'.")]
struct SampleArgs {
    #[command(flatten)]
    input: PairArgs,

    /// At least N points per piece.
    #[arg(long, value_name = "N", default_value_t = 64)]
    points: usize,

    /// Largest chord deviation in the affine chart.
    #[arg(long, value_name = "T")]
    tolerance: Option<f64>,

    /// The plane at infinity, "a*x+b*y+c*z+d*w" (default "w").
    #[arg(long, value_name = "PLANE", allow_hyphen_values = true)]
    chart: Option<String>,

    /// Output format (batch: json only).
    #[arg(long, value_enum, default_value_t = Format::Json)]
    format: Format,
}

/// Two quadrics or a batch file.
#[derive(Args, Debug)]
struct PairArgs {
    /// First quadric: a polynomial in x, y, z, w, or a 4x4 JSON matrix.
    #[arg(
        value_name = "A",
        allow_hyphen_values = true,
        required_unless_present = "batch"
    )]
    a: Option<String>,

    /// Second quadric: a polynomial in x, y, z, w, or a 4x4 JSON matrix.
    #[arg(
        value_name = "B",
        allow_hyphen_values = true,
        required_unless_present = "batch"
    )]
    b: Option<String>,

    /// Answer the JSON Lines of FILE ('-' for standard input) with JSON Lines.
    #[arg(long, value_name = "FILE", conflicts_with_all = ["a", "b"])]
    batch: Option<PathBuf>,
}

/// Arguments of `qsic classify`.
#[derive(Args, Debug)]
#[command(after_long_help = CLASSIFY_HELP, after_help = "See 'qsic classify --help' for input forms, batch format and exit codes.")]
struct ClassifyArgs {
    /// First quadric: a polynomial in x, y, z, w, or a 4x4 JSON matrix.
    #[arg(
        value_name = "A",
        allow_hyphen_values = true,
        required_unless_present = "batch"
    )]
    a: Option<String>,

    /// Second quadric: a polynomial in x, y, z, w, or a 4x4 JSON matrix.
    #[arg(
        value_name = "B",
        allow_hyphen_values = true,
        required_unless_present = "batch"
    )]
    b: Option<String>,

    /// Classify the JSON Lines of FILE ('-' for standard input) and write JSON Lines.
    #[arg(long, value_name = "FILE", conflicts_with_all = ["a", "b"])]
    batch: Option<PathBuf>,

    /// Print one JSON object instead of the text report (batch output is always JSON).
    #[arg(long)]
    json: bool,
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    match cli.command {
        Command::Param(args) => run_param(&args),
        Command::Sample(args) => run_sample(&args),
        Command::Classify(args) => match (&args.batch, &args.a, &args.b) {
            (Some(path), _, _) => run_batch(path),
            (None, Some(a), Some(b)) => run_single(a, b, args.json),
            _ => {
                // clap's `required_unless_present` makes this unreachable; answer as a usage error.
                let mut cmd = Cli::command();
                cmd.error(
                    clap::error::ErrorKind::MissingRequiredArgument,
                    "two quadrics A and B, or --batch FILE, are required",
                )
                .exit()
            }
        },
    }
}

/// `qsic classify A B`: exit 0 with the report, or 1 with `error: A: …` on stderr.
fn run_single(a: &str, b: &str, json: bool) -> ExitCode {
    let read =
        |name: &str, text: &str| input::quadric_from_arg(text).map_err(|e| format!("{name}: {e}"));
    let result = read("A", a).and_then(|qa| {
        let qb = read("B", b)?;
        qsic::classify_allowing_zero(qa.as_ref(), qb.as_ref())
            .map_err(|e| format!("A and B: both are zero: {e}"))
    });
    let classification = match result {
        Ok(c) => c,
        Err(message) => {
            eprintln!("error: {message}");
            return ExitCode::from(1);
        }
    };
    let text = if json {
        output::classification_to_json_line(&classification) + "\n"
    } else {
        output::human_report(&classification)
    };
    let mut stdout = io::stdout().lock();
    match stdout
        .write_all(text.as_bytes())
        .and_then(|()| stdout.flush())
    {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => io_failure("writing the output", &e),
    }
}

/// `qsic classify --batch FILE`: exit 0 if every line succeeded, 1 if any failed, 2 on I/O errors.
fn run_batch(path: &std::path::Path) -> ExitCode {
    run_batch_with(path, &batch::Classify)
}

/// A batch of any command (exit codes as [`run_batch`]).
fn run_batch_with<A: batch::Answer>(path: &std::path::Path, answer: &A) -> ExitCode {
    let progress = io::stderr().is_terminal();
    let stdout = io::BufWriter::with_capacity(1 << 20, io::stdout().lock());
    let result = if path.as_os_str() == "-" {
        batch::run_with(io::stdin().lock(), stdout, progress, answer)
    } else {
        match File::open(path) {
            Ok(file) => batch::run_with(file, stdout, progress, answer),
            Err(e) => {
                eprintln!("error: cannot open {}: {e}", path.display());
                return ExitCode::from(2);
            }
        }
    };
    match result {
        Ok(summary) if summary.failed == 0 => ExitCode::SUCCESS,
        Ok(_) => ExitCode::from(1),
        Err(batch::BatchError::Read(e)) => io_failure(&format!("reading {}", path.display()), &e),
        Err(batch::BatchError::Write(e)) => io_failure("writing the output", &e),
    }
}

/// The two quadrics of a single query (`None`: the zero form), or exit 1 with the message.
fn read_pair(a: &str, b: &str) -> Result<(Option<Quadric>, Option<Quadric>), ExitCode> {
    let read =
        |name: &str, text: &str| input::quadric_from_arg(text).map_err(|e| format!("{name}: {e}"));
    match read("A", a).and_then(|qa| Ok((qa, read("B", b)?))) {
        Ok(pair) => Ok(pair),
        Err(message) => {
            eprintln!("error: {message}");
            Err(ExitCode::from(1))
        }
    }
}

/// Writes `text` to standard output: exit 0, or 2 on an I/O error.
fn write_out(text: &str) -> ExitCode {
    let mut stdout = io::stdout().lock();
    match stdout
        .write_all(text.as_bytes())
        .and_then(|()| stdout.flush())
    {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => io_failure("writing the output", &e),
    }
}

fn usage_error(message: &str) -> ExitCode {
    let mut cmd = Cli::command();
    cmd.error(clap::error::ErrorKind::ArgumentConflict, message)
        .exit()
}

/// `qsic param`.
fn run_param(args: &ParamArgs) -> ExitCode {
    let (a, b) = match (&args.input.batch, &args.input.a, &args.input.b) {
        (Some(path), _, _) => return run_batch_with(path, &param::Param),
        (None, Some(a), Some(b)) => (a, b),
        _ => return usage_error("two quadrics A and B, or --batch FILE, are required"),
    };
    let (qa, qb) = match read_pair(a, b) {
        Ok(pair) => pair,
        Err(code) => return code,
    };
    let curve = match param::curve_of(qa.as_ref(), qb.as_ref()) {
        Ok(c) => c,
        Err(message) => {
            eprintln!("error: {message}");
            return ExitCode::from(1);
        }
    };
    let json = param::ParamJson::from(&curve);
    let text = if args.json {
        format!("{{{}}}\n", param::fields_of(&json))
    } else {
        param::human_report(&json)
    };
    write_out(&text)
}

/// `qsic sample`.
fn run_sample(args: &SampleArgs) -> ExitCode {
    let mut options = SampleOptions {
        points: args.points,
        tolerance: args.tolerance,
        ..SampleOptions::default()
    };
    if let Some(text) = &args.chart {
        match sample::parse_chart(text) {
            Ok(chart) => options.chart = chart,
            Err(message) => {
                eprintln!("error: {message}");
                return ExitCode::from(2);
            }
        }
    }
    let (a, b) = match (&args.input.batch, &args.input.a, &args.input.b) {
        (Some(_), _, _) if args.format != Format::Json => {
            return usage_error("--batch writes JSON Lines: --format csv and obj need A and B")
        }
        (Some(path), _, _) => return run_batch_with(path, &sample::Sample(options)),
        (None, Some(a), Some(b)) => (a, b),
        _ => return usage_error("two quadrics A and B, or --batch FILE, are required"),
    };
    let (qa, qb) = match read_pair(a, b) {
        Ok(pair) => pair,
        Err(code) => return code,
    };
    let (curve, sampled) = match sample::sample_of(qa.as_ref(), qb.as_ref(), &options) {
        Ok(r) => r,
        Err(message) => {
            eprintln!("error: {message}");
            return ExitCode::from(1);
        }
    };
    let text = match args.format {
        Format::Json => format!(
            "{{{}}}\n",
            param::fields_of(&sample::SampleJson::new(&curve, &sampled))
        ),
        Format::Csv => sample::to_csv(&sampled, &options),
        Format::Obj => sample::to_obj(&sampled),
    };
    write_out(&text)
}

/// Exit 2 after an I/O error; a closed output pipe (`| head`) ends quietly.
fn io_failure(what: &str, e: &io::Error) -> ExitCode {
    if e.kind() != io::ErrorKind::BrokenPipe {
        eprintln!("error: {what}: {e}");
    }
    ExitCode::from(2)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn command_line_definition_is_consistent() {
        Cli::command().debug_assert();
    }

    #[test]
    fn hyphen_polynomials_and_batch_conflicts() {
        let cli = Cli::try_parse_from(["qsic", "classify", "-x^2+y^2-w^2", "x^2", "--json"])
            .expect("a leading '-' is a polynomial");
        let Command::Classify(args) = cli.command else {
            panic!("classify")
        };
        assert_eq!(args.a.as_deref(), Some("-x^2+y^2-w^2"));
        assert!(args.json);
        assert!(Cli::try_parse_from(["qsic", "classify", "--batch", "f", "x^2", "y^2"]).is_err());
        assert!(Cli::try_parse_from(["qsic", "classify", "x^2"]).is_err());
        assert!(Cli::try_parse_from(["qsic", "classify", "--batch", "-"]).is_ok());
    }
}
