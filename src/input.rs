//! Hostile-input guards shared by every reader: input files are read up to a documented size
//! limit, and text quoted in error messages is bounded (tokens clipped, lists summarised), so a
//! malformed or enormous input can neither exhaust memory nor produce an enormous message.

use std::fmt::Display;
use std::io::Read;
use std::path::Path;

/// Largest input file any reader of this crate (OBJ, and the command line's field CSV, session,
/// strokes, guides, config and strips files) accepts: 512 MiB. A mesh of a few million vertices
/// fits; `/dev/zero` or a runaway file is refused after reading at most this much.
pub const MAX_INPUT_BYTES: u64 = 512 * 1024 * 1024;

/// Longest token (a word from an input file) quoted whole in an error message, in characters.
pub const MAX_QUOTED_CHARS: usize = 80;

/// Most items of a list (e.g. mesh problems) written out in one error message; the rest are
/// counted ("… and 399,990 more").
pub const MAX_LISTED_ITEMS: usize = 10;

/// The bytes of the file at `path`, read up to [`MAX_INPUT_BYTES`].
///
/// Errors (as `std::io::Error`, whose message is meant for a person): the file cannot be opened
/// or read, is a directory, or holds more than [`MAX_INPUT_BYTES`] bytes (kind `InvalidData`,
/// the message gives the limit). A regular file that is too large is refused before reading;
/// a device or pipe is read up to one byte past the limit.
pub fn read_limited(path: &Path) -> std::io::Result<Vec<u8>> {
    let file = std::fs::File::open(path)?;
    let metadata = file.metadata()?;
    if metadata.is_dir() {
        return Err(std::io::Error::new(std::io::ErrorKind::InvalidInput, "is a directory, not a file"));
    }
    if metadata.is_file() && metadata.len() > MAX_INPUT_BYTES {
        return Err(too_large());
    }
    let mut bytes = Vec::new();
    file.take(MAX_INPUT_BYTES + 1).read_to_end(&mut bytes)?;
    if bytes.len() as u64 > MAX_INPUT_BYTES {
        return Err(too_large());
    }
    Ok(bytes)
}

fn too_large() -> std::io::Error {
    std::io::Error::new(
        std::io::ErrorKind::InvalidData,
        format!("larger than the input limit of {} MiB", MAX_INPUT_BYTES / (1024 * 1024)),
    )
}

/// `token` for an error message: unchanged up to [`MAX_QUOTED_CHARS`] characters, otherwise its
/// first [`MAX_QUOTED_CHARS`] characters followed by "…"; control characters (line breaks, NUL)
/// are shown as `\u{..}` escapes so that a message stays on one line.
pub fn clip(token: &str) -> String {
    let mut clipped = String::new();
    for (i, c) in token.chars().enumerate() {
        if i == MAX_QUOTED_CHARS {
            clipped.push('…');
            break;
        }
        if c.is_control() {
            clipped.extend(c.escape_unicode());
        } else {
            clipped.push(c);
        }
    }
    clipped
}

/// `text` (e.g. a parser's message that quotes the input) with every whitespace-separated word
/// longer than [`MAX_QUOTED_CHARS`] characters clipped as [`clip`] does; runs of whitespace
/// become one space.
pub fn clip_words(text: &str) -> String {
    text.split_whitespace().map(clip).collect::<Vec<_>>().join(" ")
}

/// The first `shown` items joined by `separator`, followed by `separator` and "and N more" when
/// there are more (N with thousands separators, e.g. "and 399,990 more").
pub fn summarise_list<T: Display>(items: &[T], shown: usize, separator: &str) -> String {
    let mut text = items.iter().take(shown).map(ToString::to_string).collect::<Vec<_>>().join(separator);
    if items.len() > shown {
        text.push_str(separator);
        text.push_str(&format!("and {} more", thousands(items.len() - shown)));
    }
    text
}

/// `n` with a comma every three digits: 399990 → "399,990".
pub fn thousands(n: usize) -> String {
    let digits = n.to_string();
    let mut text = String::new();
    for (i, c) in digits.chars().enumerate() {
        if i > 0 && (digits.len() - i) % 3 == 0 {
            text.push(',');
        }
        text.push(c);
    }
    text
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn long_tokens_are_clipped_and_control_characters_escaped() {
        assert_eq!(clip("1.5e3x"), "1.5e3x");
        let long = "x".repeat(1_000_000);
        let clipped = clip(&long);
        assert_eq!(clipped.chars().count(), MAX_QUOTED_CHARS + 1);
        assert!(clipped.ends_with('…'));
        assert_eq!(clip("a\nb\0"), "a\\u{a}b\\u{0}");
        let message = format!("unknown field `{long}`, expected `strokes`");
        assert_eq!(clip_words(&message).chars().count(), "unknown field ".len() + MAX_QUOTED_CHARS + 1 + " expected `strokes`".len());
    }

    #[test]
    fn lists_are_cut_with_a_count_of_the_rest() {
        let items: Vec<usize> = (0..400_000).collect();
        assert_eq!(summarise_list(&items, 3, "; "), "0; 1; 2; and 399,997 more");
        assert_eq!(summarise_list(&items[..2], 3, ", "), "0, 1");
        assert_eq!(thousands(0), "0");
        assert_eq!(thousands(999), "999");
        assert_eq!(thousands(1000), "1,000");
        assert_eq!(thousands(1_234_567), "1,234,567");
    }

    #[test]
    fn devices_and_directories_are_bounded_or_refused() {
        let zero = Path::new("/dev/zero");
        if zero.exists() {
            let error = read_limited(zero).expect_err("endless device");
            assert_eq!(error.kind(), std::io::ErrorKind::InvalidData);
            assert!(error.to_string().contains("512 MiB"), "{error}");
        }
        let error = read_limited(Path::new(env!("CARGO_MANIFEST_DIR"))).expect_err("a directory");
        assert!(error.to_string().contains("directory"), "{error}");
    }
}
