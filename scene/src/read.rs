//! Reading an input file whole, as UTF-8 text, up to a size no input of this program comes
//! near, so that a wrong path (a video, `/dev/zero`) is refused instead of filling memory or
//! reading for ever.

use std::io::Read;
use std::path::Path;

/// The largest input file read, bytes (256 MiB: a scene is a few kB, a day of tracks at
/// 1 kHz about 100 MB).
pub const MAX_INPUT_BYTES: u64 = 256 << 20;

/// Reads `path` as UTF-8 text; a file longer than [`MAX_INPUT_BYTES`] is an error of kind
/// `FileTooLarge`, read no further.
pub fn read_text(path: &Path) -> std::io::Result<String> {
    let mut text = String::new();
    std::fs::File::open(path)?
        .take(MAX_INPUT_BYTES + 1)
        .read_to_string(&mut text)?;
    if text.len() as u64 > MAX_INPUT_BYTES {
        return Err(std::io::Error::new(
            std::io::ErrorKind::FileTooLarge,
            format!(
                "longer than {} MiB, more than any input of this program",
                MAX_INPUT_BYTES >> 20
            ),
        ));
    }
    Ok(text)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_endless_input_is_refused_after_the_limit() {
        let e = read_text(Path::new("/dev/zero")).unwrap_err();
        assert_eq!(e.kind(), std::io::ErrorKind::FileTooLarge);
        assert!(e.to_string().contains("256 MiB"), "{e}");
    }

    #[test]
    fn a_file_is_read_whole() {
        let path = std::env::temp_dir().join(format!("read-text-{}.txt", std::process::id()));
        std::fs::write(&path, "name = \"x\"\n").unwrap();
        assert_eq!(read_text(&path).unwrap(), "name = \"x\"\n");
        std::fs::remove_file(&path).unwrap();
    }
}
