//! `qsic`: exact classification of the intersection curve of two quadric surfaces.
//! The command line is defined here; the work is done by the `qsic_cli` library.
//!
//! Exit codes: 0 success; 1 bad input (single query) or at least one failed line (batch);
//! 2 usage error, unreadable input file or an I/O error.

use clap::{Args, CommandFactory, Parser, Subcommand};
use qsic::param::sample::SampleOptions;
use qsic::Quadric;
use qsic_cli::floats::{rewrite_floats, FloatReading};
use qsic_cli::motion::{self, TimeRange};
use qsic_cli::{batch, contact, input, nurbs, output, param, plot, sample};
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
  A polynomial of degree 1 (\"z - 1\") is a plane, read as its double plane: the answer
  describes the section counted twice, and \"affine\" names the surface \"plane\".
  A polynomial starting with '-' is accepted as is, or after '--'.

BATCH (--batch FILE, or --batch - for standard input):
  JSON Lines in: {\"id\": ..., \"A\": ..., \"B\": ...}, each quadric a polynomial string or a
  4x4 array of numbers or number strings; other fields are ignored. JSON Lines out on
  standard output: one line per non-blank input line, in input order, with the same id
  (null if missing): the result object, or
  {\"id\": ..., \"error\": {\"line\": n, \"message\": \"...\"}} with n the 1-based input line.
  Blank lines are skipped but counted in line numbers. Lines longer than 1 MiB are
  answered with an error without being stored. A line over its work budget
  (--line-budget) is answered with an error. All cores are used; each answer is written
  as soon as it and every answer before it are done. A progress spinner appears on stderr if it is a terminal.

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
    /// The work budget of one query or one batch line, in work units (about one word
    /// operation of the exact arithmetic each; this machine kind does 10^8 to 10^9 a
    /// second): a computation over it stops with an error ("over the work budget"), a batch
    /// answers the other lines. An integer or a power like 1e9; default 1e12.
    #[arg(
        long,
        global = true,
        value_name = "UNITS",
        default_value = "1e12",
        value_parser = batch::parse_budget
    )]
    line_budget: u64,

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
    /// The instants where the intersection of two moving quadrics A(t), B(t) changes type,
    /// and the type on every interval between them, exactly.
    Motion(MotionArgs),
    /// First contact of two moving quadrics A(t), B(t), and the relation of the solids
    /// (separated, touching, overlapping, inside) along the motion when both are ellipsoids.
    Contact(ContactArgs),
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
    /// Draw the real curve in a 3D view as SVG (-o FILE), and the eigencurve (--eigencurve).
    ///
    /// Each real piece in its own colour, isolated points as dots, singular points marked
    /// with their kind, the two surfaces faintly as their sections by planes x, y, z = const,
    /// unbounded branches clipped to a box; the legend names the class and the affine view.
    Plot(PlotArgs),
    /// Every real piece of the curve as a NURBS curve: JSON, STEP (--format step) or text.
    ///
    /// Rational components (lines, conics, cubics, nodal and cuspidal quartics) are exact
    /// rational B-splines, cut at singular points and at infinity; unbounded pieces are
    /// clipped to a box (--box, default around the bounded parts, the singular points and
    /// the surfaces' centres) at rational parameters just outside it.
    Nurbs(NurbsArgs),
}

/// Output formats of `qsic nurbs`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
enum NurbsFormatArg {
    Text,
    Json,
    Step,
}

/// Arguments of `qsic nurbs`.
#[derive(Args, Debug)]
#[command(after_help = "Input forms, batch format and exit codes as for 'qsic classify --help'.")]
struct NurbsArgs {
    #[command(flatten)]
    input: PairArgs,

    /// Print one JSON object (the same as --format json; batch output is always JSON).
    #[arg(long, conflicts_with = "format")]
    json: bool,

    /// The output: text (a summary), json, or step (ISO 10303-21).
    #[arg(long, value_enum, value_name = "FORMAT", default_value_t = NurbsFormatArg::Text)]
    format: NurbsFormatArg,

    /// The box unbounded pieces are clipped to: six exact numbers X0,Y0,Z0,X1,Y1,Z1.
    #[arg(
        long = "box",
        value_name = "X0,Y0,Z0,X1,Y1,Z1",
        allow_hyphen_values = true
    )]
    bounds: Option<String>,

    /// The distance bound of approximated quartic branches to both surfaces (a positive
    /// number; default 1e-9 of each branch's size).
    #[arg(long, value_name = "DISTANCE")]
    tolerance: Option<f64>,
}

const PLOT_HELP: &str = "\
PICTURE:
  The curve in the affine chart (--chart, default w = 0 at infinity) seen by an orthographic
  camera (--view AZIMUTH,ELEVATION in degrees, default 35,25) looking at a cube: around the
  bounded part of the curve (bounded pieces, isolated and singular points) if there is one,
  else around the unbounded branches' points nearest the origin, else around the surfaces.
  Unbounded branches are clipped to the cube (stated in the legend). Points come from the
  exact parameterization (as 'qsic sample'), never from marching.

EIGENCURVE (--eigencurve):
  A second panel: det(lambda*A - B - u*I) = 0 in the (lambda, u) plane, the index (number of
  positive eigenvalues of lambda*A - B - u*I) in each region, the exact index function on
  u = 0, and the real roots of det(lambda*A - B) from the exact pencil analysis.

EXIT STATUS:
  0  the picture was written; 1 bad input or a class not covered; 2 usage or I/O error

EXAMPLES:
  qsic plot \"x^2+y^2+z^2-4\" \"(x-1)^2+y^2-1\" -o viviani.svg
  qsic plot \"x^2+y^2-1\" \"x^2+z^2-1\" -o cylinders.svg --view 60,20 --eigencurve";

/// Arguments of `qsic plot`.
#[derive(Args, Debug)]
#[command(after_long_help = PLOT_HELP, after_help = "See 'qsic plot --help' for the picture, the eigencurve and the exit codes.")]
struct PlotArgs {
    /// First quadric: a polynomial in x, y, z, w, or a 4x4 JSON matrix.
    #[arg(value_name = "A", allow_hyphen_values = true)]
    a: String,

    /// Second quadric: a polynomial in x, y, z, w, or a 4x4 JSON matrix.
    #[arg(value_name = "B", allow_hyphen_values = true)]
    b: String,

    /// The SVG file to write.
    #[arg(short = 'o', long = "output", value_name = "FILE")]
    output: PathBuf,

    /// At least N points per piece.
    #[arg(long, value_name = "N", default_value_t = 64)]
    points: usize,

    /// The plane at infinity, "a*x+b*y+c*z+d*w" (default "w").
    #[arg(long, value_name = "PLANE", allow_hyphen_values = true)]
    chart: Option<String>,

    /// The camera direction: azimuth about z from the x axis, elevation, in degrees.
    #[arg(long, value_name = "AZIMUTH,ELEVATION", allow_hyphen_values = true)]
    view: Option<String>,

    /// Add a panel with the eigenvalue curve det(lambda*A - B - u*I) = 0.
    #[arg(long)]
    eigencurve: bool,
}

/// Arguments of `qsic contact`.
#[derive(Args, Debug)]
#[command(
    after_help = "A and B: read as by 'qsic motion': quadratic forms in x, y, z, w (or affine \
x, y, z) whose coefficients are rational functions of t, e.g. \"(x - t)^2 + y^2 + z^2 - 1\" (a \
linear one is a moving plane, read as its double plane), or 4x4 JSON arrays of numbers and \
such functions as strings, or quadrics under rigid motions, JSON objects {\"quadric\", \
\"rotate\": {\"axis\" | \"quaternion\", \"center\"}, \"translate\"} (see 'qsic motion --help'). \
--range as for 'qsic motion'; the solids' relation is reported on the range only. Instants are \
exact: rationals, or roots of a polynomial in t.\n\
The first contact comes with the common points there (\"contact\" in --json): exact \
homogeneous coordinates (w = 1 for an affine point; numbers of degree > 2 named a1, … with \
their polynomial) and decimals, each isolated or a singular point of the curve; the number of \
real curve pieces in common, and whether the quadrics already meet at the start of the range.\n\
Examples: qsic contact \"x^2+y^2+z^2-4\" \"(x-t)^2+y^2+z^2-1\" --range -10 10\n\
  qsic contact '{\"quadric\": \"(x-2)^2+y^2+z^2-1\", \"rotate\": {\"axis\": [0,0,1]}, \"translate\": [0,0,\"t\"]}' \
\"(x+6/5)^2+(y-8/5)^2+(z-5)^2-4\""
)]
struct ContactArgs {
    /// First moving quadric.
    #[arg(
        value_name = "A",
        allow_hyphen_values = true,
        required_unless_present = "batch"
    )]
    a: Option<String>,
    /// Second moving quadric.
    #[arg(
        value_name = "B",
        allow_hyphen_values = true,
        required_unless_present = "batch"
    )]
    b: Option<String>,
    /// Answer the JSON Lines {"id", "A", "B"} of FILE ('-' for standard input), one JSON
    /// line each (the --json object with the line's id first), in order.
    #[arg(long, value_name = "FILE", conflicts_with_all = ["a", "b"])]
    batch: Option<PathBuf>,
    /// Only t in the closed range [T0, T1] (exact numbers, -oo/oo for an open side), as for motion.
    #[arg(long, num_args = 2, value_names = ["T0", "T1"], allow_hyphen_values = true)]
    range: Option<Vec<String>>,
    /// Print one JSON object instead of the text report.
    #[arg(long)]
    json: bool,
    /// Only the first contact instant: no common points there and no solids' timeline (the
    /// JSON object stops after "first_contact"), for loops over many pairs and time steps.
    #[arg(long)]
    first_only: bool,
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

    /// Leave out the affine data (each conic's type, centre, axes; the "affine" object of
    /// the pair in R^3).
    #[arg(long)]
    projective: bool,

    /// The plane at infinity of the affine data, a linear form "a*x+b*y+c*z+d*w"
    /// (default "w"); lengths use the Euclidean metric of the chart's coordinates.
    #[arg(long, value_name = "FORM", allow_hyphen_values = true)]
    chart: Option<String>,
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

    /// Largest chord deviation in the affine chart: a positive finite number.
    #[arg(long, value_name = "T", value_parser = sample::parse_tolerance)]
    tolerance: Option<f64>,

    /// The plane at infinity, "a*x+b*y+c*z+d*w" (default "w").
    #[arg(long, value_name = "PLANE", allow_hyphen_values = true)]
    chart: Option<String>,

    /// Output format (batch: json only).
    #[arg(long, value_enum, default_value_t = Format::Json)]
    format: Format,

    /// Leave out the "affine" object of the pair in R^3 (JSON).
    #[arg(long)]
    projective: bool,
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

    /// How JSON floats in matrices are read: text (as written, exactly), shortest (the
    /// shortest decimal that rounds to the same double: 0.089999999999999997 is 9/100) or
    /// binary (the double's exact value: 0.1 is 3602879701896397/2^55).
    #[arg(long, value_enum, value_name = "READING", default_value_t = FloatReading::Text)]
    floats: FloatReading,
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

    /// Leave out the affine view ("affine": surfaces, curves in R^3, solids), which builds
    /// the curve and costs far more than the classification.
    #[arg(long)]
    projective: bool,

    /// The plane at infinity of the affine view, a linear form "a*x+b*y+c*z+d*w"
    /// (default "w"); solids are given in the default chart only.
    #[arg(long, value_name = "FORM", allow_hyphen_values = true)]
    chart: Option<String>,

    /// How JSON floats in matrices are read: text (as written, exactly), shortest (the
    /// shortest decimal that rounds to the same double: 0.089999999999999997 is 9/100) or
    /// binary (the double's exact value: 0.1 is 3602879701896397/2^55).
    #[arg(long, value_enum, value_name = "READING", default_value_t = FloatReading::Text)]
    floats: FloatReading,
}

const MOTION_HELP: &str = "\
MOVING QUADRICS:
  A(t), B(t): a quadratic form in x, y, z, w (or affine in x, y, z) whose coefficients are
  rational functions of t, e.g. \"(x - t)^2 + y^2 + z^2 - 1\" or \"x^2 + (1-t^2)/(1+t^2)*y*w\";
  or a symmetric 4x4 JSON array of numbers and strings of rational functions of t, e.g.
  '[[\"1\",0,0,\"-t\"],[0,1,0,0],[0,0,1,0],[\"-t\",0,0,\"t^2-1\"]]'. A form of degree 1
  in x, y, z, w (\"z - t\") is a moving plane, read as its double plane, as in 'qsic classify'.
  Denominators are cleared (at a pole the quadric is the limit), and so is a factor common
  to all entries (\"t*x^2 - t\" is x^2 - w^2 at every t, t = 0 included).
  Bounds (qsic::limits): entries of degree <= 16 in t once denominators are cleared,
  coefficients of <= 512 bits; each number <= 10000 digits.

RIGID MOTIONS:
  A(t) or B(t) may be a quadric under a rigid motion, a JSON object:
    {\"quadric\": Q, \"rotate\": {\"axis\": [a1,a2,a3]} , \"translate\": [c1,c2,c3]}
  Q: a quadric as above (a string or a 4x4 array; it may itself depend on t). A point x
  moves to R(t)(x - p) + p + c(t):
    \"rotate\": {\"axis\": [a1,a2,a3]}          the Cayley rotation about the axis a: angle
                                          theta with tan(theta/2) = t*|a| (\"cayley\": true
                                          may be added); entries of degree 4 over (1+|a|^2 t^2)^2
    \"rotate\": {\"quaternion\": [q0,q1,q2,q3]}  the rotation of the quaternion path
                                          q0 + q1 i + q2 j + q3 k (polynomials in t)
    \"center\": [p1,p2,p3] (in \"rotate\")      a point of the axis (default the origin)
    \"translate\": [c1,c2,c3]                 then the translation, polynomials in t
  a and p are rational numbers (JSON numbers or strings \"1/3\"), q and c numbers or strings
  \"2*t^2 - 1/2\". A screw motion: an axis rotation and a translation along the axis.
  Exact: the moved matrix is T^-T A T^-1 with T^-1 rational in t. Also as \"A\"/\"B\" of
  --batch lines.

OUTPUT:
  A timeline: the open intervals of t with a rational sample and their type, and the
  instants between them where the type differs from a neighbour's. An instant is exact:
  a rational, or a root of a square-free integer polynomial in an isolating interval.
  --json: {\"instants\": [{\"t\", \"pencil\", \"case\", \"complex_type\", \"real_type\"}],
  \"intervals\": [{\"from\", \"to\", \"sample_t\", \"pencil\", \"case\", \"complex_type\",
  \"real_type\"}]}; t is \"p/q\" or {\"poly\", \"interval\": [\"a\", \"b\"], \"approx\"}; from/to
  null for -oo/+oo.

RANGE (--range T0 T1):
  Analyse the closed range [T0, T1] only (exact numbers; -oo or oo, also -inf, inf, +oo,
  +inf, for an open side). A range that cannot be read or is empty (T0 above T1, T0 = oo,
  T1 = -oo) is a usage error, as for 'qsic contact'.
  The intervals cover (T0, T1): the first starts at T0, the last ends at T1. The instants
  strictly inside are reported as without a range; T0 (T1) is reported as a first (last)
  instant only if its type differs from that of the interval beside it. T0 = T1 gives no
  interval and the one instant.

PLOT (--plot FILE):
  Also write the timeline as an SVG picture: a t axis over the range (for an open side, a
  window holding every instant with margins, and an arrow to -oo/+oo), one coloured band
  per interval labelled \"case k: real_type\", one tick per instant labelled with its exact
  value (p/q, or a decimal marked algebraic) and type, and a legend of the colours; below,
  a small picture of the real curve at the sample t of each interval (as 'qsic plot', the
  first 20 intervals), framed in the interval's colour. Not with --batch (a usage error);
  an unwritable FILE exits 2.

BATCH (--batch FILE, or - for standard input):
  JSON Lines {\"id\", \"A\", \"B\"} in; one JSON line out per non-blank line, in order:
  {\"id\", \"instants\", \"intervals\"} or {\"id\", \"error\": {\"line\", \"message\"}}, as for
  'qsic classify --batch'. --range applies to every line.

EXIT STATUS:
  0  success; 1 bad input (or a batch line failed); 2 usage or I/O error

EXAMPLES:
  qsic motion \"x^2+y^2+z^2-4\" \"(x-t)^2+y^2+z^2-1\"
  qsic motion --json --range 0 2 \"x^2+y^2-z^2-w^2\" \"(x^2+y^2+(z+t*w)^2)/2-w^2\"
  qsic motion --batch moving.jsonl
  qsic motion '{\"quadric\": \"x^2/4+y^2+z^2-1\", \"rotate\": {\"axis\": [0,0,1]}}' \"(x-3)^2+(y-4)^2+z^2-9\"";

/// Arguments of `qsic motion`.
#[derive(Args, Debug)]
#[command(after_long_help = MOTION_HELP, after_help = "See 'qsic motion --help' for input forms, output, range and batch.")]
struct MotionArgs {
    /// First moving quadric: a form in x, y, z, w with coefficients in t, or a 4x4 JSON matrix.
    #[arg(
        value_name = "A",
        allow_hyphen_values = true,
        required_unless_present = "batch"
    )]
    a: Option<String>,

    /// Second moving quadric, as A.
    #[arg(
        value_name = "B",
        allow_hyphen_values = true,
        required_unless_present = "batch"
    )]
    b: Option<String>,

    /// Analyse the JSON Lines of FILE ('-' for standard input) and write JSON Lines.
    #[arg(long, value_name = "FILE", conflicts_with_all = ["a", "b"])]
    batch: Option<PathBuf>,

    /// Only t in the closed range [T0, T1] (exact numbers, -oo/oo for an open side).
    #[arg(long, num_args = 2, value_names = ["T0", "T1"], allow_hyphen_values = true)]
    range: Option<Vec<String>>,

    /// Print one JSON object instead of the text timeline (batch output is always JSON).
    #[arg(long)]
    json: bool,

    /// Also draw the timeline as an SVG picture into FILE (not with --batch).
    #[arg(long, value_name = "FILE", conflicts_with = "batch")]
    plot: Option<PathBuf>,
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let units = cli.line_budget;
    match cli.command {
        Command::Motion(args) => run_motion(&args, units),
        Command::Param(args) => run_param(&args, units),
        Command::Sample(args) => run_sample(&args, units),
        Command::Plot(args) => run_plot(&args),
        Command::Nurbs(args) => run_nurbs(&args, units),
        Command::Classify(args) => {
            let chart = match args.chart.as_deref().map(classify_chart).transpose() {
                Ok(chart) => chart,
                Err(message) => {
                    eprintln!("error: --chart: {message}");
                    return ExitCode::from(2);
                }
            };
            match (&args.batch, &args.a, &args.b) {
                (Some(path), _, _) => run_batch_with(
                    path,
                    &batch::Classify {
                        projective_only: args.projective,
                        chart,
                    },
                    args.floats,
                    units,
                ),
                (None, Some(a), Some(b)) => run_single(
                    (a, b),
                    args.floats,
                    args.json,
                    args.projective,
                    chart.as_ref(),
                    units,
                ),
                _ => {
                    // clap's `required_unless_present` makes this unreachable; answer as a usage error.
                    let mut cmd = Cli::command();
                    cmd.error(
                        clap::error::ErrorKind::MissingRequiredArgument,
                        "two quadrics A and B, or --batch FILE, are required",
                    )
                    .exit()
                }
            }
        }
        Command::Contact(args) => run_contact(&args, units),
    }
}

/// `qsic contact A B`: exit 0 with the report, or 1 with the error on stderr; or a batch.
/// The query or each line may spend `units` work units.
fn run_contact(args: &ContactArgs, units: u64) -> ExitCode {
    let range = range_arg(args.range.as_deref());
    if let Some(path) = &args.batch {
        return run_batch(path, |line: &batch::RawLine| {
            contact::answer_contact_line(line, &range, units, args.first_only)
        });
    }
    let (Some(a), Some(b)) = (&args.a, &args.b) else {
        let mut cmd = Cli::command();
        cmd.error(
            clap::error::ErrorKind::MissingRequiredArgument,
            "two moving quadrics A and B, or --batch FILE, are required",
        )
        .exit()
    };
    let result = (|| {
        let a = motion::moving_from_arg(a).map_err(|e| format!("A: {e}"))?;
        let b = motion::moving_from_arg(b).map_err(|e| format!("B: {e}"))?;
        contact::report_within(a, b, range, &qsic::Budget::new(units), args.first_only)
            .map_err(|e| format!("A and B: {e}"))
    })();
    let report = match result {
        Ok(r) => r,
        Err(message) => {
            eprintln!("error: {message}");
            return ExitCode::from(1);
        }
    };
    let text = if args.json {
        contact::report_to_json_line(&report) + "\n"
    } else {
        contact::human_report(&report)
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

/// `qsic classify A B`: exit 0 with the report, or 1 with `error: A: …` on stderr.
/// The chart of `--chart`: the parsed form and its text.
fn classify_chart(text: &str) -> Result<(qsic::affine::Chart, String), String> {
    let form = sample::parse_chart(text)?;
    let chart = qsic::affine::Chart::new(form).map_err(|e| e.to_string())?;
    Ok((chart, text.to_owned()))
}

fn run_single(
    (a, b): (&str, &str),
    floats: FloatReading,
    json: bool,
    projective: bool,
    chart: Option<&(qsic::affine::Chart, String)>,
    units: u64,
) -> ExitCode {
    let budget = qsic::Budget::new(units);
    let default = (qsic::affine::Chart::default(), "w".to_owned());
    let (chart, chart_text) = chart.unwrap_or(&default);
    let read = |name: &str, text: &str| read_surface(name, text, floats);
    let result = read("A", a).and_then(|sa| {
        let sb = read("B", b)?;
        let planes = [sa.plane, sb.plane];
        let (qa, qb) = (sa.quadric, sb.quadric);
        let c = match (&qa, &qb) {
            (Some(a), Some(b)) => {
                qsic::classify_within(a, b, &budget).map_err(|e| e.to_string())?
            }
            _ => qsic::classify_allowing_zero(qa.as_ref(), qb.as_ref())
                .map_err(|e| format!("A and B: both are zero: {e}"))?,
        };
        let view = (!projective)
            .then(|| {
                qsic::affine::affine_view_within(qa.as_ref(), qb.as_ref(), chart, planes, &budget)
            })
            .transpose()
            .map_err(|e| e.to_string())?;
        Ok((c, view))
    });
    let (classification, view) = match result {
        Ok(c) => c,
        Err(message) => {
            eprintln!("error: {message}");
            return ExitCode::from(1);
        }
    };
    let text = if json {
        let mut line = output::classification_to_json_line(&classification);
        if let Some(view) = &view {
            // the object's closing brace last: the affine object goes before it
            line.pop();
            line.push_str(",\"affine\":");
            line.push_str(&qsic_cli::affine::to_json(view, chart_text).to_string());
            line.push('}');
        }
        line + "\n"
    } else {
        output::classify_report(&classification, view.as_ref(), chart_text)
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

/// `--range T0 T1` of `qsic motion` and `qsic contact`, read by the library's one reader
/// ([`TimeRange::parse`]); the whole line without it. A range that cannot be read or is
/// empty is a usage error (exit 2).
fn range_arg(range: Option<&[String]>) -> TimeRange {
    match range {
        Some([t0, t1]) => match TimeRange::parse(t0, t1) {
            Ok(r) => r,
            Err(e) => {
                let mut cmd = Cli::command();
                cmd.error(
                    clap::error::ErrorKind::ValueValidation,
                    format!("--range: {e}"),
                )
                .exit()
            }
        },
        _ => TimeRange::all(),
    }
}

/// `qsic motion`: a single pair (exit 0, or 1 with `error: …`) or a batch; the query or
/// each line may spend `units` work units.
fn run_motion(args: &MotionArgs, units: u64) -> ExitCode {
    let range = range_arg(args.range.as_deref());
    if let Some(path) = &args.batch {
        return run_batch(path, |line: &batch::RawLine| {
            motion::answer_motion_line(line, &range, units)
        });
    }
    let (Some(a), Some(b)) = (&args.a, &args.b) else {
        let mut cmd = Cli::command();
        cmd.error(
            clap::error::ErrorKind::MissingRequiredArgument,
            "two moving quadrics A and B, or --batch FILE, are required",
        )
        .exit()
    };
    let read =
        |name: &str, text: &str| motion::moving_from_arg(text).map_err(|e| format!("{name}: {e}"));
    let result = read("A", a).and_then(|ma| {
        let mb = read("B", b)?;
        // the plot's snapshots need the moving quadrics again
        let pair = args.plot.is_some().then(|| (ma.clone(), mb.clone()));
        let m = motion::analyze_within(ma, mb, &range, &qsic::Budget::new(units))
            .map_err(|e| format!("A and B: {e}"))?;
        Ok((m, pair))
    });
    if let (Ok((m, Some((ma, mb)))), Some(path)) = (&result, &args.plot) {
        let svg = qsic_cli::motion_plot::motion_with_snapshots_to_svg(m, &range, ma, mb);
        if let Err(e) = qsic_cli::file::write_atomically(path, svg.as_bytes()) {
            return io_failure(&format!("writing the plot {}", path.display()), &e);
        }
    }
    let text = match result {
        Ok((m, _)) if args.json => motion::motion_to_json_line(&m) + "\n",
        Ok((m, _)) => motion::human_timeline(&m),
        Err(message) => {
            eprintln!("error: {message}");
            return ExitCode::from(1);
        }
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

/// `qsic classify --batch FILE` (or `motion`, with its `answer`): exit 0 if every line
/// succeeded, 1 if any failed, 2 on I/O errors.
fn run_batch<F: Fn(&batch::RawLine) -> (String, bool) + Sync>(
    path: &std::path::Path,
    answer: F,
) -> ExitCode {
    run_batch_by(path, |input, output, progress| {
        batch::run_with(input, output, progress, answer)
    })
}

/// A batch from `path` (`-`: standard input) to standard output by `run`, and its exit code.
fn run_batch_by(
    path: &std::path::Path,
    run: impl FnOnce(
        &mut dyn io::Read,
        io::BufWriter<io::Stdout>,
        bool,
    ) -> Result<batch::Summary, batch::BatchError>,
) -> ExitCode {
    let progress = io::stderr().is_terminal();
    let stdout = io::BufWriter::with_capacity(1 << 20, io::stdout());
    let result = if path.as_os_str() == "-" {
        run(&mut io::stdin().lock(), stdout, progress)
    } else {
        match File::open(path) {
            Ok(mut file) => run(&mut file, stdout, progress),
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

/// A batch of any [`batch::Answer`] on the line's quadrics (`param`, `sample`), JSON floats
/// read by `floats`, `units` of work a line.
fn run_batch_with<A: batch::Answer>(
    path: &std::path::Path,
    answer: &A,
    floats: FloatReading,
    units: u64,
) -> ExitCode {
    run_batch(path, |line: &batch::RawLine| {
        batch::answer_line_reading(line, answer, floats, units)
    })
}

/// A quadric argument, its JSON floats read by `floats`; the error names the argument.
fn read_surface(name: &str, text: &str, floats: FloatReading) -> Result<input::Surface, String> {
    let text = rewrite_floats(text, floats, None).map_err(|e| format!("{name}: {e}"))?;
    input::surface_from_arg(&text).map_err(|e| format!("{name}: {e}"))
}

/// The two quadrics of a single query (`None`: the zero form) and whether each was given as a
/// plane, or exit 1 with the message.
type Pair = (Option<Quadric>, Option<Quadric>, [bool; 2]);
fn read_pair(a: &str, b: &str, floats: FloatReading) -> Result<Pair, ExitCode> {
    let read = |name: &str, text: &str| read_surface(name, text, floats);
    match read("A", a).and_then(|sa| {
        let sb = read("B", b)?;
        Ok((sa.quadric, sb.quadric, [sa.plane, sb.plane]))
    }) {
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
fn run_param(args: &ParamArgs, units: u64) -> ExitCode {
    let chart = match args.chart.as_deref().map(classify_chart).transpose() {
        Ok(chart) => chart,
        Err(message) => {
            eprintln!("error: --chart: {message}");
            return ExitCode::from(2);
        }
    };
    let answer = param::Param {
        projective_only: args.projective,
        chart,
    };
    let (a, b) = match (&args.input.batch, &args.input.a, &args.input.b) {
        (Some(path), _, _) => return run_batch_with(path, &answer, args.input.floats, units),
        (None, Some(a), Some(b)) => (a, b),
        _ => return usage_error("two quadrics A and B, or --batch FILE, are required"),
    };
    let (qa, qb, planes) = match read_pair(a, b, args.input.floats) {
        Ok(pair) => pair,
        Err(code) => return code,
    };
    let curve = match param::curve_within(qa.as_ref(), qb.as_ref(), &qsic::Budget::new(units)) {
        Ok(c) => c,
        Err(message) => {
            eprintln!("error: {message}");
            return ExitCode::from(1);
        }
    };
    let default = (qsic::affine::Chart::default(), "w".to_owned());
    let (chart, chart_text) = answer.chart.as_ref().unwrap_or(&default);
    let ctx = param::AffineContext {
        a: qa.as_ref(),
        b: qb.as_ref(),
        chart,
        chart_text,
        planes,
    };
    let json = param::ParamJson::new(&curve, (!args.projective).then_some(&ctx));
    let text = if args.json {
        format!("{{{}}}\n", param::fields_of(&json))
    } else {
        param::human_report(&json)
    };
    write_out(&text)
}

/// `qsic nurbs`.
fn run_nurbs(args: &NurbsArgs, units: u64) -> ExitCode {
    let bounds = match args.bounds.as_deref().map(nurbs::parse_box).transpose() {
        Ok(b) => b,
        Err(message) => {
            eprintln!("error: --box: {message}");
            return ExitCode::from(2);
        }
    };
    if let Some(t) = args.tolerance.filter(|t| !(t.is_finite() && *t > 0.0)) {
        eprintln!("error: --tolerance must be a positive finite number, not {t}");
        return ExitCode::from(2);
    }
    let options = qsic::nurbs::NurbsOptions {
        bounds,
        tolerance: args.tolerance,
    };
    let (a, b) = match (&args.input.batch, &args.input.a, &args.input.b) {
        (Some(path), _, _) => {
            let answer = nurbs::NurbsAnswer { options };
            return run_batch_with(path, &answer, args.input.floats, units);
        }
        (None, Some(a), Some(b)) => (a, b),
        _ => return usage_error("two quadrics A and B, or --batch FILE, are required"),
    };
    let (qa, qb, _) = match read_pair(a, b, args.input.floats) {
        Ok(pair) => pair,
        Err(code) => return code,
    };
    let format = match (args.json, args.format) {
        (true, _) | (_, NurbsFormatArg::Json) => nurbs::NurbsFormat::Json,
        (_, NurbsFormatArg::Step) => nurbs::NurbsFormat::Step,
        (_, NurbsFormatArg::Text) => nurbs::NurbsFormat::Text,
    };
    let budget = qsic::Budget::new(units);
    match nurbs::render(qa.as_ref(), qb.as_ref(), &options, &budget, format) {
        Ok(text) => write_out(&text),
        Err(message) => {
            eprintln!("error: {message}");
            ExitCode::from(1)
        }
    }
}

/// `qsic sample`.
fn run_sample(args: &SampleArgs, units: u64) -> ExitCode {
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
        (Some(path), _, _) => {
            let answer = sample::Sample {
                options,
                projective_only: args.projective,
                chart_text: args.chart.clone().unwrap_or_else(|| "w".to_owned()),
            };
            let floats = args.input.floats;
            // the one dispatch between the two batch routes (module `large`)
            if answer.is_large() {
                return run_batch_by(path, |input, output, progress| {
                    qsic_cli::large::run_large(input, output, progress, &answer, floats, units)
                });
            }
            return run_batch_with(path, &answer, floats, units);
        }
        (None, Some(a), Some(b)) => (a, b),
        _ => return usage_error("two quadrics A and B, or --batch FILE, are required"),
    };
    let (qa, qb, planes) = match read_pair(a, b, args.input.floats) {
        Ok(pair) => pair,
        Err(code) => return code,
    };
    let sample::Sampling {
        curve,
        sampled,
        surfaces,
    } = match sample::sample_within(
        qa.as_ref(),
        qb.as_ref(),
        &options,
        &qsic::Budget::new(units),
    ) {
        Ok(r) => r,
        Err(message) => {
            eprintln!("error: {message}");
            return ExitCode::from(1);
        }
    };
    let text = match args.format {
        Format::Json => {
            let chart = match qsic::affine::Chart::new(options.chart.clone()) {
                Ok(c) => c,
                Err(e) => {
                    eprintln!("error: --chart: {e}");
                    return ExitCode::from(2);
                }
            };
            let chart_text = args.chart.clone().unwrap_or_else(|| "w".to_owned());
            let ctx = param::AffineContext {
                a: qa.as_ref(),
                b: qb.as_ref(),
                chart: &chart,
                chart_text: &chart_text,
                planes,
            };
            let affine = (!args.projective).then_some(&ctx);
            let json = sample::SampleJson::with_affine(&curve, &sampled, &surfaces, affine);
            drop((curve, sampled));
            // serialized straight into the output: a million points are 140 MB of text
            let mut stdout = io::BufWriter::with_capacity(1 << 20, io::stdout().lock());
            let written = serde_json::to_writer(&mut stdout, &json)
                .map_err(io::Error::from)
                .and_then(|()| stdout.write_all(b"\n"))
                .and_then(|()| stdout.flush());
            return match written {
                Ok(()) => ExitCode::SUCCESS,
                Err(e) => io_failure("writing the output", &e),
            };
        }
        Format::Csv => sample::to_csv(&sampled),
        Format::Obj => sample::to_obj(&sampled),
    };
    write_out(&text)
}

/// `qsic plot`: exit 0 with the picture written, 1 on bad input, 2 on a usage or I/O error.
fn run_plot(args: &PlotArgs) -> ExitCode {
    let mut options = plot::PlotOptions {
        points: args.points,
        eigencurve: args.eigencurve,
        ..plot::PlotOptions::default()
    };
    let settings = (|| {
        if let Some(text) = &args.chart {
            options.chart = sample::parse_chart(text)?;
        }
        if let Some(text) = &args.view {
            options.view = plot::parse_view(text)?;
        }
        Ok::<(), String>(())
    })();
    if let Err(message) = settings {
        eprintln!("error: {message}");
        return ExitCode::from(2);
    }
    let read =
        |name: &str, text: &str| input::surface_from_arg(text).map_err(|e| format!("{name}: {e}"));
    let result = read("A", &args.a).and_then(|sa| {
        let sb = read("B", &args.b)?;
        let (Some(qa), Some(qb)) = (&sa.quadric, &sb.quadric) else {
            return Err("A and B: a zero form has no curve to draw".to_string());
        };
        plot::plot_to_svg(qa, qb, [sa.plane, sb.plane], &options)
    });
    let svg = match result {
        Ok(svg) => svg,
        Err(message) => {
            eprintln!("error: {message}");
            return ExitCode::from(1);
        }
    };
    match qsic_cli::file::write_atomically(&args.output, svg.as_bytes()) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => io_failure(&format!("writing the plot {}", args.output.display()), &e),
    }
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
            panic!("classify parsed as another command");
        };
        assert_eq!(args.a.as_deref(), Some("-x^2+y^2-w^2"));
        assert!(args.json);
        assert!(Cli::try_parse_from(["qsic", "classify", "--batch", "f", "x^2", "y^2"]).is_err());
        assert!(Cli::try_parse_from(["qsic", "classify", "x^2"]).is_err());
        assert!(Cli::try_parse_from(["qsic", "classify", "--batch", "-"]).is_ok());
    }

    #[test]
    fn contact_arguments() {
        let cli = Cli::try_parse_from(["qsic", "contact", "-x^2", "y^2", "--range", "-3", "1/2"])
            .expect("negative range ends");
        let Command::Contact(args) = cli.command else {
            panic!("contact parsed as another command")
        };
        assert_eq!(args.a.as_deref(), Some("-x^2"));
        assert_eq!(args.range, Some(vec!["-3".to_string(), "1/2".to_string()]));
        assert!(Cli::try_parse_from(["qsic", "contact", "x^2", "y^2", "--range", "1"]).is_err());
    }
}
