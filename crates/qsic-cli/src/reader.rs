//! The lines of a batch input, bounded: [`LineReader`] gives each line's bytes without its
//! terminator (`\n` or `\r\n`), or only the length of a line longer than its limit, which
//! it reads through without storing; a UTF-8 byte-order mark at the very start of the input
//! is skipped. Memory use is the read buffer plus one line, whatever the input.

use std::io::{self, BufRead, BufReader, Read};

/// Size of the input buffer.
/// Longest input line, in bytes, not counting its line terminator (1 MiB). A 4×4
/// matrix of numbers at the library's digit limit, or two polynomial strings at its
/// length limit, fit well within it.
pub const MAX_LINE_BYTES: usize = 1 << 20;

const READ_BUFFER_BYTES: usize = 256 << 10;

/// The UTF-8 byte-order mark, skipped at the very start of the input (editors on Windows
/// write it).
const BYTE_ORDER_MARK: [u8; 3] = [0xEF, 0xBB, 0xBF];

/// The content of one input line.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Content {
    /// The bytes of the line without its terminator (`\n` or `\r\n`).
    Text(Vec<u8>),
    /// A line longer than the limit; only its length is kept.
    TooLong {
        /// Bytes of the line, its terminator (and a byte-order mark before line 1) not
        /// counted.
        bytes: u64,
    },
}

/// One input line with its 1-based number.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct RawLine {
    /// 1-based line number, blank lines included.
    pub number: u64,
    /// What the line holds.
    pub content: Content,
}

impl RawLine {
    /// Whether the line holds only ASCII whitespace (an empty line included).
    pub(crate) fn is_blank(&self) -> bool {
        matches!(&self.content, Content::Text(t) if t.iter().all(u8::is_ascii_whitespace))
    }

    /// Bytes held in memory.
    pub(crate) fn held_bytes(&self) -> usize {
        match &self.content {
            Content::Text(t) => t.len(),
            Content::TooLong { .. } => 0,
        }
    }
}

/// Reads lines of at most `max_line_bytes` bytes (terminator excluded); longer lines are
/// consumed up to their end without being stored. Memory use is the buffer plus one line.
pub struct LineReader<R> {
    inner: BufReader<R>,
    max_line_bytes: usize,
    lines_read: u64,
}

impl<R: Read> LineReader<R> {
    /// A reader of lines of at most `max_line_bytes` bytes.
    pub fn new(inner: R, max_line_bytes: usize) -> Self {
        LineReader {
            inner: BufReader::with_capacity(READ_BUFFER_BYTES, inner),
            max_line_bytes,
            lines_read: 0,
        }
    }

    /// Lines read so far, blank ones included.
    pub fn lines_read(&self) -> u64 {
        self.lines_read
    }

    /// Whether everything read from the source so far has been consumed, so that the
    /// next line may have to wait for the source (an interactive producer).
    pub fn drained(&self) -> bool {
        self.inner.buffer().is_empty()
    }

    /// The next line, `None` at the end of the input. A last line without a newline is
    /// a line. A UTF-8 byte-order mark at the very start of the input is skipped; the
    /// limit, and the length a [`Content::TooLong`] reports, count neither it nor the
    /// terminator.
    ///
    /// # Errors
    /// Any read error of the source other than [`io::ErrorKind::Interrupted`].
    pub fn next_line(&mut self) -> io::Result<Option<RawLine>> {
        let first = self.lines_read == 0;
        let mut text = Vec::new();
        // the line's first bytes, for the mark
        let mut head = [0u8; BYTE_ORDER_MARK.len()];
        let mut head_len = 0;
        let mut length: u64 = 0; // bytes before the '\n'
        let mut last = None; // the last of them
        let mut read_any = false;
        let mut too_long = false;
        loop {
            let available = match self.inner.fill_buf() {
                Ok(bytes) => bytes,
                Err(e) if e.kind() == io::ErrorKind::Interrupted => continue,
                Err(e) => return Err(e),
            };
            if available.is_empty() {
                if !read_any {
                    return Ok(None);
                }
                break;
            }
            read_any = true;
            let (take, ends) = match find_newline(available) {
                Some(i) => (i + 1, true),
                None => (available.len(), false),
            };
            let piece = &available[..take - usize::from(ends)];
            if first {
                for &c in piece.iter().take(head.len() - head_len) {
                    head[head_len] = c;
                    head_len += 1;
                }
            }
            length += piece.len() as u64;
            last = piece.last().copied().or(last);
            if !too_long {
                // room for the '\r' of a "\r\n" terminator and for a mark
                if text.len() + piece.len() > self.max_line_bytes + 1 + BYTE_ORDER_MARK.len() {
                    too_long = true;
                    text = Vec::new();
                } else if text.is_empty() {
                    // The usual case, a whole line in the buffer: one exact allocation.
                    text = piece.to_vec();
                } else {
                    text.extend_from_slice(piece);
                }
            }
            self.inner.consume(take);
            if ends {
                break;
            }
        }
        self.lines_read += 1;
        let mark = if first && head[..head_len] == BYTE_ORDER_MARK {
            BYTE_ORDER_MARK.len()
        } else {
            0
        };
        // a '\r' ending the line is part of its terminator (the mark's bytes are not '\r')
        let cr = usize::from(last == Some(b'\r'));
        let len = length - (mark + cr) as u64;
        let content = if too_long || len > self.max_line_bytes as u64 {
            Content::TooLong { bytes: len }
        } else {
            text.truncate(text.len() - cr);
            text.drain(..mark);
            Content::Text(text)
        };
        Ok(Some(RawLine {
            number: self.lines_read,
            content,
        }))
    }
}

/// The index of the first `\n` in `b`, eight bytes at a time (a word has a zero byte iff
/// `(x − 0x01…01) & !x & 0x80…80` is nonzero; the lowest such bit marks the first one).
fn find_newline(b: &[u8]) -> Option<usize> {
    const ONES: u64 = 0x0101_0101_0101_0101;
    const HIGH: u64 = 0x8080_8080_8080_8080;
    let mut chunks = b.chunks_exact(8);
    let mut offset = 0;
    for chunk in &mut chunks {
        let mut word = [0u8; 8];
        word.copy_from_slice(chunk);
        let x = u64::from_le_bytes(word) ^ (ONES * u64::from(b'\n'));
        let found = x.wrapping_sub(ONES) & !x & HIGH;
        if found != 0 {
            return Some(offset + (found.trailing_zeros() / 8) as usize);
        }
        offset += 8;
    }
    chunks
        .remainder()
        .iter()
        .position(|&c| c == b'\n')
        .map(|i| offset + i)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn lines_of(input: &[u8], limit: usize) -> Vec<RawLine> {
        let mut reader = LineReader::new(input, limit);
        let mut lines = Vec::new();
        while let Some(line) = reader.next_line().expect("in-memory reads succeed") {
            lines.push(line);
        }
        lines
    }

    fn text(number: u64, s: &str) -> RawLine {
        RawLine {
            number,
            content: Content::Text(s.as_bytes().to_vec()),
        }
    }

    #[test]
    fn line_reader_bounds_lines_and_strips_terminators() {
        let input = b"ab\r\n\n0123456789\nabcde\nlast";
        assert_eq!(
            lines_of(input, 5),
            vec![
                text(1, "ab"),
                text(2, ""),
                RawLine {
                    number: 3,
                    content: Content::TooLong { bytes: 10 }
                },
                text(4, "abcde"),
                text(5, "last"),
            ]
        );
        assert!(lines_of(b"", 5).is_empty());
        assert_eq!(lines_of(b"\n", 5), vec![text(1, "")]);
    }

    fn too_long(number: u64, bytes: u64) -> RawLine {
        RawLine {
            number,
            content: Content::TooLong { bytes },
        }
    }

    /// A source that gives one byte a read, so a line and a byte-order mark arrive in
    /// pieces.
    struct ByteByByte<'a>(&'a [u8]);

    impl Read for ByteByByte<'_> {
        fn read(&mut self, buf: &mut [u8]) -> io::Result<usize> {
            match (self.0.split_first(), buf.first_mut()) {
                (Some((&b, rest)), Some(slot)) => {
                    *slot = b;
                    self.0 = rest;
                    Ok(1)
                }
                _ => Ok(0),
            }
        }
    }

    fn lines_byte_by_byte(input: &[u8], limit: usize) -> Vec<RawLine> {
        let mut reader = LineReader::new(ByteByByte(input), limit);
        let mut lines = Vec::new();
        while let Some(line) = reader.next_line().expect("in-memory reads succeed") {
            lines.push(line);
        }
        lines
    }

    #[test]
    fn the_limit_and_the_reported_length_exclude_the_terminator() {
        // limit 5: a line of exactly 5 bytes is read, one of 6 refused, whatever ends it
        let cases: [(&[u8], RawLine); 8] = [
            (b"abcde\n", text(1, "abcde")),
            (b"abcde\r\n", text(1, "abcde")),
            (b"abcde", text(1, "abcde")),
            (b"abcdef\n", too_long(1, 6)),
            (b"abcdef\r\n", too_long(1, 6)),
            (b"abcdef", too_long(1, 6)),
            (b"abcdefg\r", too_long(1, 7)),
            (b"abcd\r\r\n", text(1, "abcd\r")),
        ];
        for (input, want) in cases {
            assert_eq!(lines_of(input, 5), vec![want.clone()], "{input:?}");
            assert_eq!(lines_byte_by_byte(input, 5), vec![want], "{input:?}");
        }
        let mut long = vec![b'x'; 3 * READ_BUFFER_BYTES];
        long.extend_from_slice(b"\r\n");
        assert_eq!(
            lines_of(&long, 1000),
            vec![too_long(1, 3 * READ_BUFFER_BYTES as u64)]
        );
    }

    #[test]
    fn a_byte_order_mark_is_skipped_only_at_the_start() {
        const BOM: &[u8] = b"\xEF\xBB\xBF";
        let with_bom = |rest: &[u8]| [BOM, rest].concat();
        let cases: Vec<(Vec<u8>, Vec<RawLine>)> = vec![
            (with_bom(b"{}\n{}"), vec![text(1, "{}"), text(2, "{}")]),
            // the mark counts in no line's length
            (with_bom(b"abcde\r\n"), vec![text(1, "abcde")]),
            (with_bom(b"abcdef\n"), vec![too_long(1, 6)]),
            // a file of the mark alone is one blank line
            (BOM.to_vec(), vec![text(1, "")]),
            (with_bom(b"\n"), vec![text(1, "")]),
            // elsewhere the mark is the line's text (invalid JSON)
            (
                [b"{}\n", BOM, b"{}"].concat(),
                vec![
                    text(1, "{}"),
                    RawLine {
                        number: 2,
                        content: Content::Text(with_bom(b"{}")),
                    },
                ],
            ),
            (
                [b" ", BOM].concat(),
                vec![RawLine {
                    number: 1,
                    content: Content::Text([b" ", BOM].concat()),
                }],
            ),
            // a part of a mark is no mark
            (
                b"\xEF\xBB{}".to_vec(),
                vec![RawLine {
                    number: 1,
                    content: Content::Text(b"\xEF\xBB{}".to_vec()),
                }],
            ),
        ];
        for (input, want) in cases {
            assert_eq!(lines_of(&input, 5), want, "{input:?}");
            assert_eq!(lines_byte_by_byte(&input, 5), want, "{input:?}");
        }
    }

    #[test]
    fn find_newline_finds_the_first() {
        for len in 0..20 {
            for at in 0..=len {
                let mut b = vec![b'a'; len];
                b.extend_from_slice(&[0x8a, 0x0b, 0x09, 0x00, 0xff]);
                if at < len {
                    b[at] = b'\n';
                    b.push(b'\n');
                }
                let want = b.iter().position(|&c| c == b'\n');
                assert_eq!(find_newline(&b), want, "{b:?}");
            }
        }
    }

    #[test]
    fn over_long_line_longer_than_the_buffer_is_skipped() {
        let mut input = vec![b'x'; 3 * READ_BUFFER_BYTES];
        input.extend_from_slice(b"\n{}\n");
        let lines = lines_of(&input, 1000);
        assert_eq!(lines.len(), 2);
        assert!(matches!(lines[0].content, Content::TooLong { .. }));
        assert_eq!(lines[1], text(2, "{}"));
    }
}
