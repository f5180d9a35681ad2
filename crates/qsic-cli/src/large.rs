//! Batches whose answers are too large to hold as text (`qsic sample --points 1000000`): the
//! lines are answered one at a time, in input order, and each answer is serialized straight
//! into the output as it is written, never built as a string.
//!
//! **Memory.** One line's computation (its points as floats: a few tens of bytes a point)
//! and a buffer, none of its text: a million points are about 140 MB of JSON, which would
//! otherwise be held (and copied) before being written. So memory is that of the largest
//! line, whatever the number of lines. The price is one core: where the answer is this
//! large, writing its text is most of the work, and two lines at once would hold two.
//! [`crate::stream`] serves every other batch.

use crate::batch::{
    error_record, line_work, progress_bar, reread_floats, BatchError, LineFailure, Summary,
    MAX_LINE_BYTES,
};
use crate::floats::FloatReading;
use crate::reader::{LineReader, RawLine};
use qsic::{Budget, Quadric};
use std::io::{self, Read, Write};

/// An answer computed whole in its own form, then written as the fields of the result
/// object (without braces and `id`, as [`crate::batch::Answer`] gives them).
pub trait LargeAnswer: Sync {
    /// What the answer holds between its computation and its writing.
    type Prepared;

    /// Computes the answer of a pair (`None`: the zero form; `planes[i]`: the input was a
    /// plane), spending `budget`.
    ///
    /// # Errors
    /// The message of the line's error.
    fn prepare(
        &self,
        a: Option<&Quadric>,
        b: Option<&Quadric>,
        planes: [bool; 2],
        budget: &Budget,
    ) -> Result<Self::Prepared, String>;

    /// Writes the fields of `prepared` to `out`.
    ///
    /// # Errors
    /// The output's.
    fn write_fields(&self, prepared: &Self::Prepared, out: &mut dyn Write) -> io::Result<()>;
}

/// Answers every non-blank line of `input` by `answer`, one at a time, its JSON floats read
/// by `floats`, with a budget of `units` a line, and writes each answer to `output` as it is
/// serialized, then flushes (module docs). The lines and errors are those of
/// [`crate::batch::run`].
///
/// # Errors
/// As [`crate::batch::run`].
pub fn run_large<R: Read, W: Write, A: LargeAnswer>(
    input: R,
    mut output: W,
    progress: bool,
    answer: &A,
    floats: FloatReading,
    units: u64,
) -> Result<Summary, BatchError> {
    let bar = progress_bar(progress);
    let mut reader = LineReader::new(input, MAX_LINE_BYTES);
    let (mut answered, mut failed) = (0, 0);
    loop {
        let line = match reader.next_line() {
            Ok(Some(line)) => line,
            Ok(None) => break,
            Err(e) => {
                bar.finish_and_clear();
                return Err(BatchError::Read(e));
            }
        };
        if line.is_blank() {
            continue;
        }
        let ok = match reread_floats(&line, floats) {
            Ok(None) => write_line(&line, answer, units, &mut output),
            Ok(Some(rewritten)) => write_line(&rewritten, answer, units, &mut output),
            Err(message) => {
                let record = error_record(&line, &LineFailure::without_id(message));
                output
                    .write_all(record.as_bytes())
                    .and_then(|()| output.write_all(b"\n"))
                    .map(|()| false)
            }
        }
        .map_err(BatchError::Write)?;
        answered += 1;
        failed += u64::from(!ok);
        bar.set_position(answered);
    }
    bar.finish_and_clear();
    Ok(Summary {
        lines: reader.lines_read(),
        answered,
        failed,
    })
}

/// Writes the answer of `line` and a newline, and flushes; whether it is not an error.
fn write_line<A: LargeAnswer, W: Write>(
    line: &RawLine,
    answer: &A,
    units: u64,
    out: &mut W,
) -> io::Result<bool> {
    let work = line_work(line, |a, b, planes| {
        answer.prepare(a, b, planes, &Budget::new(units))
    });
    let ok = match work {
        Ok((id, prepared)) => {
            out.write_all(b"{\"id\":")?;
            out.write_all(id.unwrap_or("null").as_bytes())?;
            out.write_all(b",")?;
            answer.write_fields(&prepared, out)?;
            out.write_all(b"}")?;
            true
        }
        Err(failure) => {
            out.write_all(error_record(line, &failure).as_bytes())?;
            false
        }
    };
    out.write_all(b"\n")?;
    out.flush()?;
    Ok(ok)
}

/// Writes a JSON object's serialization without its braces: the first byte (`{`) is
/// dropped and the last one (`}`) held back until [`Unbraced::finish`] drops it.
pub struct Unbraced<'w> {
    out: &'w mut dyn Write,
    started: bool,
    last: Option<u8>,
}

impl<'w> Unbraced<'w> {
    /// A writer into `out`.
    pub fn new(out: &'w mut dyn Write) -> Unbraced<'w> {
        Unbraced {
            out,
            started: false,
            last: None,
        }
    }

    /// Ends the object: the held-back byte, which must be its `}`, is dropped.
    ///
    /// # Errors
    /// `InvalidData` if what was written was not an object.
    pub fn finish(self) -> io::Result<()> {
        match self.last {
            Some(b'}') => Ok(()),
            _ => Err(io::Error::new(
                io::ErrorKind::InvalidData,
                "a serialized answer is not a JSON object",
            )),
        }
    }
}

impl Write for Unbraced<'_> {
    fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
        let mut rest = buf;
        if !self.started {
            match rest.split_first() {
                Some((b'{', tail)) => rest = tail,
                Some(_) => {
                    return Err(io::Error::new(
                        io::ErrorKind::InvalidData,
                        "a serialized answer is not a JSON object",
                    ))
                }
                None => return Ok(0),
            }
            self.started = true;
        }
        if let Some((&end, body)) = rest.split_last() {
            if let Some(held) = self.last.replace(end) {
                self.out.write_all(&[held])?;
            }
            self.out.write_all(body)?;
        }
        Ok(buf.len())
    }

    fn flush(&mut self) -> io::Result<()> {
        self.out.flush()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_object_is_written_without_its_braces_whatever_the_pieces() {
        let json = r#"{"a":[1,2,{"b":"}"}],"c":{}}"#;
        for cut in 0..json.len() {
            let mut out = Vec::new();
            let mut w = Unbraced::new(&mut out);
            w.write_all(&json.as_bytes()[..cut]).unwrap();
            w.write_all(&json.as_bytes()[cut..]).unwrap();
            w.finish().unwrap();
            assert_eq!(String::from_utf8(out).unwrap(), &json[1..json.len() - 1]);
        }
    }

    #[test]
    fn what_is_not_an_object_is_an_error() {
        let mut out = Vec::new();
        assert!(Unbraced::new(&mut out).write_all(b"[1]").is_err());
        let mut w = Unbraced::new(&mut out);
        w.write_all(b"{\"a\":1").unwrap();
        assert!(w.finish().is_err());
    }
}
