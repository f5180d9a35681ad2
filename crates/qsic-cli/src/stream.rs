//! Ordered streaming of a batch: lines answered in parallel, answers written in input order
//! as soon as each one and every one before it are done.
//!
//! The calling thread reads lines and hands each non-blank one to the rayon pool; a writer
//! thread puts the answers back in order and writes each as soon as its predecessors are
//! written, flushing once no further answer has come for [`FLUSH_AFTER`]. A slow line holds
//! back only the answers after it.
//!
//! **Memory.** A line is *pending* from the moment it is read until its answer is written.
//! The reader takes no new line while [`Window::lines`] lines or [`Window::bytes`] bytes
//! (input text and finished answers) are pending: memory is bounded by the window, plus the
//! answers being computed (at most one per thread), whatever the number of lines.

use crate::reader::{LineReader, RawLine};
use indicatif::ProgressBar;
use std::collections::BTreeMap;
use std::io::{self, Read, Write};
use std::sync::mpsc::{self, Receiver, TryRecvError};
use std::sync::{Condvar, Mutex};
use std::time::Duration;

/// The most pending lines and bytes (module docs).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Window {
    /// Pending lines.
    pub lines: usize,
    /// Pending bytes: input text and answers waiting to be written.
    pub bytes: usize,
}

/// How long the writer waits for the next answer before it flushes what it wrote: answers
/// reach the output at most about this late, and a fast batch is not written line by line.
const FLUSH_AFTER: Duration = Duration::from_millis(2);

/// Most consecutive lines answered by one job (lines already read in, taken without waiting
/// for the input): one spawn and one window update for them.
const GROUP_LINES: usize = 256;

/// What the reader and the writer share: the pending counts, and whether to stop reading.
struct Pending {
    state: Mutex<State>,
    changed: Condvar,
    /// Half the window: where a waiting reader is woken.
    low: (usize, usize),
}

#[derive(Default)]
struct State {
    lines: usize,
    bytes: usize,
    stopped: bool,
    /// The reader waits for room (only then is it woken: a wake is a system call).
    waiting: bool,
}

impl Pending {
    fn lock(&self) -> std::sync::MutexGuard<'_, State> {
        self.state.lock().unwrap_or_else(|e| e.into_inner())
    }

    /// Waits until the window has room and gives the lines free; `None` when the writer
    /// asked to stop. Once full,
    /// it waits until half the window is free, so that a reader far ahead of the answers
    /// is woken once per half window, not once per line written.
    fn wait_for_room(&self, window: Window) -> Option<usize> {
        let mut s = self.lock();
        if s.lines >= window.lines || s.bytes >= window.bytes {
            while !s.stopped && (s.lines > window.lines / 2 || s.bytes > window.bytes / 2) {
                s.waiting = true;
                s = self.changed.wait(s).unwrap_or_else(|e| e.into_inner());
            }
        }
        s.waiting = false;
        (!s.stopped).then(|| window.lines - s.lines)
    }

    fn add(&self, lines: usize, bytes: usize) {
        let mut s = self.lock();
        s.lines += lines;
        s.bytes += bytes;
    }

    fn release(&self, lines: usize, bytes: usize) {
        let mut s = self.lock();
        s.lines -= lines;
        s.bytes -= bytes;
        if s.waiting && s.lines <= self.low.0 && s.bytes <= self.low.1 {
            self.changed.notify_all();
        }
    }

    fn stop(&self) {
        self.lock().stopped = true;
        self.changed.notify_all();
    }
}

/// One finished line: its position among the non-blank lines, its answer and whether it
/// succeeded, and the input bytes it held.
struct Done {
    seq: u64,
    text: String,
    ok: bool,
    held: usize,
    /// Its answer's bytes were added to the pending bytes (it had to wait).
    counted: bool,
}

/// What a streamed batch did.
#[derive(Debug)]
pub struct Streamed {
    /// Input lines read, blank ones included.
    pub lines: u64,
    /// Answers written.
    pub answered: u64,
    /// Answers that are errors.
    pub failed: u64,
    /// The read error that ended the input, if any.
    pub read_error: Option<io::Error>,
    /// The write error that stopped the output, if any.
    pub write_error: Option<io::Error>,
}

/// Answers every non-blank line of `reader` by `answer` on the rayon pool and writes the
/// answers to `output` in input order, each followed by a newline (module docs). `progress`
/// counts the answers written.
pub fn stream<R, W, F>(
    mut reader: LineReader<R>,
    output: W,
    window: Window,
    progress: &ProgressBar,
    answer: &F,
) -> Streamed
where
    R: Read,
    W: Write + Send,
    F: Fn(&RawLine) -> (String, bool) + Sync,
{
    let pending = Pending {
        state: Mutex::default(),
        changed: Condvar::new(),
        low: (window.lines / 2, window.bytes / 2),
    };
    let (tx, rx) = mpsc::channel::<Done>();
    let mut read_error = None;
    let ((answered, failed, write_error), ()) = std::thread::scope(|threads| {
        let writer = threads.spawn(|| write_in_order(rx, output, &pending, progress));
        rayon::in_place_scope(|jobs| {
            let mut seq = 0;
            let mut at_end = false;
            while !at_end {
                let Some(room) = pending.wait_for_room(window) else {
                    break;
                };
                // a group of consecutive lines already read in, one job: a line after a slow
                // one could not be written before it anyway
                let mut group: Vec<(u64, RawLine)> = Vec::new();
                let mut held = 0;
                while group.len() < GROUP_LINES.min(room) {
                    match reader.next_line() {
                        Ok(Some(line)) if line.is_blank() => {}
                        Ok(Some(line)) => {
                            held += line.held_bytes();
                            group.push((seq, line));
                            seq += 1;
                        }
                        Ok(None) => {
                            at_end = true;
                            break;
                        }
                        Err(e) => {
                            read_error = Some(e);
                            at_end = true;
                            break;
                        }
                    }
                    if !group.is_empty() && reader.drained() {
                        break;
                    }
                }
                if group.is_empty() {
                    continue;
                }
                pending.add(group.len(), held);
                let tx = tx.clone();
                jobs.spawn(move |_| {
                    for (n, line) in group {
                        let (text, ok) = answer_or_error(answer, &line);
                        // the writer only hangs up after every sender is gone
                        let _ = tx.send(Done {
                            seq: n,
                            text,
                            ok,
                            held: line.held_bytes(),
                            counted: false,
                        });
                    }
                });
            }
        });
        drop(tx);
        let written = writer
            .join()
            .unwrap_or_else(|_| (0, 0, Some(io::Error::other("the writer panicked"))));
        (written, ())
    });
    Streamed {
        lines: reader.lines_read(),
        answered,
        failed,
        read_error,
        write_error,
    }
}

/// `answer(line)`, or an error line if it panics (a bug): every line read gets its answer,
/// so the writer, which waits for each in turn, never waits for one that will not come.
fn answer_or_error<F: Fn(&RawLine) -> (String, bool)>(
    answer: &F,
    line: &RawLine,
) -> (String, bool) {
    std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| answer(line))).unwrap_or_else(|p| {
        let why = p
            .downcast_ref::<&str>()
            .map(|s| s.to_string())
            .or_else(|| p.downcast_ref::<String>().cloned())
            .unwrap_or_default();
        let message = serde_json::Value::from(format!("internal error: {why}"));
        (
            format!(
                "{{\"id\":null,\"error\":{{\"line\":{},\"message\":{message}}}}}",
                line.number
            ),
            false,
        )
    })
}

/// The writer: answers back in order, each written once its predecessors are, a flush
/// whenever nothing more is ready. After a write error it writes nothing more, tells the
/// reader to stop, and keeps releasing what arrives.
fn write_in_order<W: Write>(
    rx: Receiver<Done>,
    mut out: W,
    pending: &Pending,
    progress: &ProgressBar,
) -> (u64, u64, Option<io::Error>) {
    let mut waiting: BTreeMap<u64, Done> = BTreeMap::new();
    let (mut next, mut answered, mut failed) = (0u64, 0u64, 0u64);
    let mut error: Option<io::Error> = None;
    // Caught up, the writer naps (50 µs doubling to FLUSH_AFTER) rather than park on the
    // channel, so that a fast stream of answers does not wake it once per line; idle for
    // FLUSH_AFTER, it flushes and parks until the next answer.
    let first_nap = Duration::from_micros(50);
    let (mut idle, mut nap) = (Duration::ZERO, first_nap);
    loop {
        let done = match rx.try_recv() {
            Ok(d) => d,
            Err(TryRecvError::Disconnected) => break,
            Err(TryRecvError::Empty) if idle < FLUSH_AFTER => {
                std::thread::sleep(nap);
                idle += nap;
                nap = (nap * 2).min(FLUSH_AFTER);
                continue;
            }
            Err(TryRecvError::Empty) => {
                if error.is_none() {
                    if let Err(e) = out.flush() {
                        error = Some(e);
                        pending.stop();
                    }
                }
                match rx.recv() {
                    Ok(d) => d,
                    Err(_) => break,
                }
            }
        };
        (idle, nap) = (Duration::ZERO, first_nap);
        let mut done = done;
        if done.seq != next {
            // it waits for an earlier answer: its bytes count in the window until written
            pending.add(0, done.text.len());
            done.counted = true;
        }
        waiting.insert(done.seq, done);
        let (mut lines, mut bytes) = (0, 0);
        while let Some(d) = waiting.remove(&next) {
            next += 1;
            if error.is_none() {
                let written = out
                    .write_all(d.text.as_bytes())
                    .and_then(|()| out.write_all(b"\n"));
                match written {
                    Ok(()) => {
                        answered += 1;
                        failed += u64::from(!d.ok);
                        progress.set_position(answered);
                    }
                    Err(e) => {
                        error = Some(e);
                        pending.stop();
                    }
                }
            }
            lines += 1;
            bytes += d.held + if d.counted { d.text.len() } else { 0 };
        }
        if lines > 0 {
            pending.release(lines, bytes);
        }
    }
    if error.is_none() {
        if let Err(e) = out.flush() {
            error = Some(e);
        }
    }
    (answered, failed, error)
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::sync::atomic::{AtomicUsize, Ordering};
    use std::sync::mpsc::Sender;

    /// A `Write` whose bytes go to the test as they are written.
    struct Pipe(Sender<Vec<u8>>);

    impl Write for Pipe {
        fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
            let _ = self.0.send(buf.to_vec());
            Ok(buf.len())
        }
        fn flush(&mut self) -> io::Result<()> {
            Ok(())
        }
    }

    /// A source that gives one line a read, like a slow producer: each line is its own job.
    struct Trickle(std::io::Cursor<Vec<u8>>);

    impl Read for Trickle {
        fn read(&mut self, buf: &mut [u8]) -> io::Result<usize> {
            let rest = &self.0.get_ref()[self.0.position() as usize..];
            let n = rest
                .iter()
                .position(|&b| b == b'\n')
                .map_or(rest.len(), |k| k + 1);
            let n = n.min(buf.len());
            self.0.read(&mut buf[..n])
        }
    }

    /// A failure guard only: a correct stream answers long before it.
    const PATIENCE: Duration = Duration::from_secs(60);

    /// Runs `lines` lines `1`…`n` through [`stream`] in a thread, the answer of line `slow`
    /// held until the test releases it; gives the output as it comes, the release, the count
    /// of answers begun and the thread.
    #[allow(clippy::type_complexity)]
    fn held_stream(
        n: usize,
        slow: usize,
        window: Window,
        trickle: bool,
    ) -> (
        Receiver<Vec<u8>>,
        Sender<()>,
        std::sync::Arc<AtomicUsize>,
        std::thread::JoinHandle<Streamed>,
    ) {
        let input: String = (1..=n).map(|k| format!("{k}\n")).collect();
        let (out_tx, out_rx) = mpsc::channel();
        let (release_tx, release_rx) = mpsc::channel::<()>();
        let begun = std::sync::Arc::new(AtomicUsize::new(0));
        let counter = begun.clone();
        let handle = std::thread::spawn(move || {
            let release = Mutex::new(release_rx);
            let answer = |line: &RawLine| {
                counter.fetch_add(1, Ordering::SeqCst);
                let crate::reader::Content::Text(t) = &line.content else {
                    unreachable!()
                };
                let text = String::from_utf8(t.clone()).unwrap();
                if text == slow.to_string() {
                    let _ = release.lock().unwrap().recv_timeout(PATIENCE);
                }
                (format!("a{text}"), true)
            };
            let bytes = std::io::Cursor::new(input.into_bytes());
            let progress = ProgressBar::hidden();
            if trickle {
                let reader = LineReader::new(Trickle(bytes), 1 << 10);
                stream(reader, Pipe(out_tx), window, &progress, &answer)
            } else {
                let reader = LineReader::new(bytes, 1 << 10);
                stream(reader, Pipe(out_tx), window, &progress, &answer)
            }
        });
        (out_rx, release_tx, begun, handle)
    }

    fn wide() -> Window {
        Window {
            lines: 1 << 12,
            bytes: 1 << 20,
        }
    }

    /// Reads the output until it holds `want` complete lines.
    fn read_lines(rx: &Receiver<Vec<u8>>, got: &mut String, want: usize) {
        while got.matches('\n').count() < want {
            let bytes = rx
                .recv_timeout(PATIENCE)
                .expect("the answers before the slow line");
            got.push_str(std::str::from_utf8(&bytes).unwrap());
        }
    }

    #[test]
    fn answers_before_a_slow_line_are_written_before_it_ends() {
        let (out, release, _, handle) = held_stream(6, 3, wide(), false);
        let mut got = String::new();
        // lines 1 and 2 come out while line 3 is still held
        read_lines(&out, &mut got, 2);
        assert_eq!(got, "a1\na2\n");
        release.send(()).unwrap();
        let done = handle.join().unwrap();
        while let Ok(b) = out.try_recv() {
            got.push_str(std::str::from_utf8(&b).unwrap());
        }
        assert_eq!(got, "a1\na2\na3\na4\na5\na6\n");
        assert_eq!((done.lines, done.answered, done.failed), (6, 6, 0));
    }

    #[test]
    fn nothing_is_written_before_a_slow_first_line() {
        let (out, release, begun, handle) = held_stream(50, 1, wide(), true);
        // the lines after it are answered beside it, and nothing may be written yet
        let start = std::time::Instant::now();
        while begun.load(Ordering::SeqCst) < 50 && start.elapsed() < PATIENCE {
            std::thread::sleep(Duration::from_millis(1));
        }
        std::thread::sleep(Duration::from_millis(20));
        assert!(out.try_recv().is_err(), "an answer before line 1's");
        release.send(()).unwrap();
        handle.join().unwrap();
        let mut got = String::new();
        while let Ok(b) = out.try_recv() {
            got.push_str(std::str::from_utf8(&b).unwrap());
        }
        let want: String = (1..=50).map(|k| format!("a{k}\n")).collect();
        assert_eq!(got, want);
    }

    /// An answer that panics (a bug) is an error line in its place; the batch goes on.
    #[test]
    fn a_panicking_answer_is_an_error_line() {
        let input = "1\n2\n3\n";
        let (tx, rx) = mpsc::channel();
        let answer = |line: &RawLine| {
            if line.number == 2 {
                panic!("line two");
            }
            (format!("a{}", line.number), true)
        };
        let reader = LineReader::new(input.as_bytes(), 1 << 10);
        let done = stream(reader, Pipe(tx), wide(), &ProgressBar::hidden(), &answer);
        let got: String = rx
            .try_iter()
            .map(|b| String::from_utf8(b).unwrap())
            .collect();
        let lines: Vec<&str> = got.lines().collect();
        assert_eq!(lines.len(), 3, "{got}");
        assert_eq!((lines[0], lines[2]), ("a1", "a3"));
        let error: serde_json::Value = serde_json::from_str(lines[1]).unwrap();
        assert_eq!(error["error"]["line"], 2);
        assert!(error["error"]["message"]
            .as_str()
            .unwrap()
            .contains("line two"));
        assert_eq!((done.answered, done.failed), (3, 1));
    }

    /// With line 1 held and lines arriving one by one (each its own job), the reader stops
    /// taking lines once the window is full: exactly `window.lines` answers begin.
    #[test]
    fn the_reader_waits_while_the_window_is_full() {
        let window = Window {
            lines: 5,
            bytes: 1 << 20,
        };
        let (out, release, begun, handle) = held_stream(100, 1, window, true);
        let start = std::time::Instant::now();
        while begun.load(Ordering::SeqCst) < 5 && start.elapsed() < PATIENCE {
            std::thread::sleep(Duration::from_millis(1));
        }
        std::thread::sleep(Duration::from_millis(50));
        assert_eq!(begun.load(Ordering::SeqCst), 5);
        release.send(()).unwrap();
        let done = handle.join().unwrap();
        assert_eq!(done.answered, 100);
        let mut got = String::new();
        while let Ok(b) = out.try_recv() {
            got.push_str(std::str::from_utf8(&b).unwrap());
        }
        assert_eq!(got.lines().count(), 100);
        assert!(got.starts_with("a1\na2\n") && got.ends_with("a100\n"));
    }
}
