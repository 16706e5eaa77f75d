//! Reading input files with a size cap: an endless or huge file (`/dev/zero`, a log file
//! given by mistake) is refused after [`MAX_FILE_BYTES`] bytes instead of filling memory.
//!
//! A file that is not a regular file (a pipe: `/dev/stdin`, `<(...)`, a FIFO; `-` means
//! stdin) can be read only once, but a command may look at its file more than once (its
//! keys, then the system). Such a file is read once, streamed with the same cap, and its text
//! is kept for the rest of the process: every later read of the same path gets the same text.

use super::InputError;
use std::io::Read;
use std::path::Path;

/// Largest input file read (64 MiB). A 200x200 system file with 20-digit entries is about
/// 1 MiB; every expression entry is itself bounded (see [`super::expr`]).
pub const MAX_FILE_BYTES: u64 = 64 << 20;

/// The text format of a system file.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SystemFormat {
    Json,
    Toml,
}

impl SystemFormat {
    /// The format of the file `path` with contents `text`: by the extension (`.toml`,
    /// `.json`, any case), else by the first character (`{` means JSON).
    pub fn of(path: &Path, text: &str) -> SystemFormat {
        let ext = path
            .extension()
            .and_then(|e| e.to_str())
            .map(str::to_ascii_lowercase);
        match ext.as_deref() {
            Some("toml") => SystemFormat::Toml,
            Some("json") => SystemFormat::Json,
            _ if text.trim_start().starts_with('{') => SystemFormat::Json,
            _ => SystemFormat::Toml,
        }
    }
}

/// The text of `path`, at most [`MAX_FILE_BYTES`] bytes.
///
/// # Errors
/// An unreadable file, a file that is not UTF-8, and a file larger than the cap (read no
/// further than the cap: `/dev/zero` fails at once). The message names the file.
pub fn read_text(path: &Path) -> Result<String, InputError> {
    read_text_capped(path, MAX_FILE_BYTES)
}

/// [`read_text`] with an explicit cap (bytes).
///
/// # Errors
/// As [`read_text`].
pub fn read_text_capped(path: &Path, cap: u64) -> Result<String, InputError> {
    let stdin = path.as_os_str() == "-";
    let regular = !stdin && std::fs::metadata(path).is_ok_and(|m| m.is_file());
    if regular {
        return read_once(path, cap);
    }
    let key = path.to_path_buf();
    let mut kept = KEPT
        .lock()
        .unwrap_or_else(std::sync::PoisonError::into_inner);
    if let Some(t) = kept.iter().find(|(p, _)| *p == key) {
        return t.1.clone();
    }
    let text = read_once(path, cap);
    kept.push((key, text.clone()));
    text
}

type Kept = Vec<(std::path::PathBuf, Result<String, InputError>)>;

/// The texts of the non-regular files read so far (see the module docs).
static KEPT: std::sync::Mutex<Kept> = std::sync::Mutex::new(Vec::new());

/// Reads `path` (`-`: stdin) once, at most `cap` bytes.
fn read_once(path: &Path, cap: u64) -> Result<String, InputError> {
    let shown = path.display().to_string();
    let fail = |m: String| InputError::file(&shown, m).with_kind(super::InputErrorKind::Read);
    let f: Box<dyn Read> = if path.as_os_str() == "-" {
        Box::new(std::io::stdin())
    } else {
        Box::new(std::fs::File::open(path).map_err(|e| fail(format!("cannot read the file: {e}")))?)
    };
    let mut bytes = Vec::new();
    f.take(cap + 1)
        .read_to_end(&mut bytes)
        .map_err(|e| fail(format!("cannot read the file: {e}")))?;
    if bytes.len() as u64 > cap {
        return Err(InputError::file(
            &shown,
            format!(
                "the file is larger than {} MiB: not a system file",
                cap >> 20
            ),
        )
        .with_kind(super::InputErrorKind::TooLarge));
    }
    String::from_utf8(bytes).map_err(|e| {
        fail(format!(
            "the file is not UTF-8 text (invalid byte at offset {})",
            e.utf8_error().valid_up_to()
        ))
    })
}
