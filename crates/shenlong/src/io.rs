//! Writing files safely: all or nothing.

use std::io::Write;
use std::path::{Path, PathBuf};

/// The most bytes a file is read to: scene files, houses, asset databases, suites, run
/// folders' files (1 GiB; the limit of every file a scene points to too).
pub const MAX_READ_BYTES: u64 = 1 << 30;

/// Opens a regular file of at most `max` bytes, and gives its length. Anything else is
/// refused before a byte is read: a FIFO (which would block: it is opened without
/// waiting, then checked by its handle, so nothing swapped in between is read), a device
/// or a link to one (`/dev/zero`, which never ends), a folder.
///
/// # Errors
/// The file cannot be opened, is no regular file, or is larger than `max`.
pub fn open_limited(path: &Path, max: u64) -> std::io::Result<(std::fs::File, u64)> {
    let mut options = std::fs::OpenOptions::new();
    options.read(true);
    #[cfg(unix)]
    {
        use std::os::unix::fs::OpenOptionsExt;
        options.custom_flags(libc::O_NONBLOCK);
    }
    let file = options.open(path)?;
    let meta = file.metadata()?;
    if !meta.is_file() {
        return Err(std::io::Error::new(
            std::io::ErrorKind::InvalidInput,
            "not a regular file (a pipe, a device or a folder); only files are read",
        ));
    }
    if meta.len() > max {
        return Err(too_large(max));
    }
    Ok((file, meta.len()))
}

fn too_large(max: u64) -> std::io::Error {
    std::io::Error::new(
        std::io::ErrorKind::InvalidInput,
        format!("larger than {} MiB", max >> 20),
    )
}

/// Reads a regular file of at most `max` bytes ([`open_limited`]); a file that grows past
/// `max` while it is read is refused too.
///
/// # Errors
/// As [`open_limited`], and the read.
pub fn read_limited(path: &Path, max: u64) -> std::io::Result<Vec<u8>> {
    use std::io::Read;
    let (file, len) = open_limited(path, max)?;
    let mut out = Vec::with_capacity(usize::try_from(len).unwrap_or(0));
    file.take(max.saturating_add(1)).read_to_end(&mut out)?;
    if out.len() as u64 > max {
        return Err(too_large(max));
    }
    Ok(out)
}

/// [`read_limited`] as UTF-8 text.
///
/// # Errors
/// As [`read_limited`], and text that is not UTF-8.
pub fn read_text_limited(path: &Path, max: u64) -> std::io::Result<String> {
    String::from_utf8(read_limited(path, max)?).map_err(|_| {
        std::io::Error::new(
            std::io::ErrorKind::InvalidData,
            "stream did not contain valid UTF-8",
        )
    })
}

/// Writes `bytes` to `path` atomically: into a temporary file beside it, flushed to disk,
/// then renamed over the target. On any error the target is left as it was and the
/// temporary file is removed. A replaced file keeps its permissions; a new one is
/// readable by all (0644 on Unix), as an ordinary write would make it.
///
/// Where the output is not a regular file it is written in place, never replaced: a FIFO,
/// a character device or a socket (`-o /dev/stdout`, a named pipe a user reads from), or a
/// link to one (`--json out.json` linked to `/proc/self/fd/1`). A link to a regular file
/// keeps the link: the file it names is replaced, atomically.
pub fn write_atomic(path: &Path, bytes: &[u8]) -> std::io::Result<()> {
    prepare(path, bytes)?.commit()
}

/// A write made ready but not yet done: staged in full beside a regular file (or its
/// link's file), or to be written in place to a stream. [`Prepared::commit`] does it;
/// dropped, nothing is written. Preparing one output first and writing another before
/// committing it writes neither when the first cannot be written.
#[derive(Debug)]
pub enum Prepared {
    /// Written beside the file, to be renamed over it.
    Staged(Staged),
    /// A stream (FIFO, character device, socket), written in place.
    InPlace {
        /// Where.
        path: PathBuf,
        /// What.
        bytes: Vec<u8>,
    },
}

impl Prepared {
    /// Does the write.
    ///
    /// # Errors
    /// The rename or the stream's write failed.
    pub fn commit(self) -> std::io::Result<()> {
        match self {
            Self::Staged(staged) => staged.commit(),
            Self::InPlace { path, bytes } => {
                let mut out = std::fs::OpenOptions::new().write(true).open(&path)?;
                out.write_all(&bytes)?;
                out.flush()
            }
        }
    }
}

/// Whether a file type is a stream written in place rather than replaced.
fn is_stream(kind: std::fs::FileType) -> bool {
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileTypeExt;
        kind.is_fifo() || kind.is_char_device() || kind.is_socket()
    }
    #[cfg(not(unix))]
    {
        !kind.is_file() && !kind.is_dir()
    }
}

/// Makes a write of `bytes` to `path` ready ([`Prepared`]).
///
/// # Errors
/// The temporary file cannot be written, or `path` is a folder or a block device.
pub fn prepare(path: &Path, bytes: &[u8]) -> std::io::Result<Prepared> {
    match std::fs::metadata(path) {
        // Following links: what the output really is.
        Ok(m) if is_stream(m.file_type()) => Ok(Prepared::InPlace {
            path: path.to_path_buf(),
            bytes: bytes.to_vec(),
        }),
        Ok(m) if m.is_dir() => Err(std::io::Error::other("it is a folder")),
        Ok(m) if !m.is_file() => Err(std::io::Error::other(
            "it is neither a regular file nor a stream",
        )),
        Ok(_) => {
            let is_link = std::fs::symlink_metadata(path).is_ok_and(|l| l.file_type().is_symlink());
            let target = if is_link {
                std::fs::canonicalize(path)?
            } else {
                path.to_path_buf()
            };
            Ok(Prepared::Staged(stage(&target, |file| {
                file.write_all(bytes)
            })?))
        }
        Err(_) => Ok(Prepared::Staged(stage(path, |file| file.write_all(bytes))?)),
    }
}

/// A file written in full beside its target but not yet in place: [`Staged::commit`]
/// renames it over the target; dropped uncommitted, it is removed. Several files staged
/// first and committed after are written all or nothing, but for a failed rename.
#[derive(Debug)]
pub struct Staged {
    file: tempfile::NamedTempFile,
    target: PathBuf,
}

impl Staged {
    /// Where the file goes.
    pub fn target(&self) -> &Path {
        &self.target
    }

    /// Renames the file over its target. A rename replaces a link at the target by the
    /// file; it never writes through the link.
    pub fn commit(self) -> std::io::Result<()> {
        self.file.persist(&self.target).map_err(|e| e.error)?;
        Ok(())
    }
}

/// Writes a temporary file in `path`'s folder with `fill`, flushed to disk, with the
/// permissions `path` has (a new file's: 0644 on Unix), for [`Staged::commit`] to rename
/// over `path`. On any error the temporary file is removed.
pub fn stage(
    path: &Path,
    fill: impl FnOnce(&mut std::fs::File) -> std::io::Result<()>,
) -> std::io::Result<Staged> {
    let dir = match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => Path::new("."),
    };
    remove_stale_temporaries(dir);
    let mut file = tempfile::Builder::new()
        .prefix(".shenlong-")
        .suffix(".tmp")
        .tempfile_in(dir)?;
    fill(file.as_file_mut())?;
    let permissions = match std::fs::metadata(path) {
        Ok(existing) => existing.permissions(),
        Err(_) => default_permissions(),
    };
    file.as_file().set_permissions(permissions)?;
    file.as_file().sync_all()?;
    Ok(Staged {
        file,
        target: path.to_path_buf(),
    })
}

/// Temporary files older than this are left by a process that was killed mid-write.
pub const STALE_AFTER: std::time::Duration = std::time::Duration::from_secs(600);

/// Removes `.shenlong-*.tmp` files older than [`STALE_AFTER`] from `dir`: what a write
/// killed before its rename (kill -9, power loss) left behind. Younger ones may belong to a
/// write in progress and are kept.
fn remove_stale_temporaries(dir: &Path) {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return;
    };
    for entry in entries.flatten() {
        let name = entry.file_name();
        let name = name.to_string_lossy();
        if !(name.starts_with(".shenlong-") && name.ends_with(".tmp")) {
            continue;
        }
        let old = entry
            .metadata()
            .and_then(|m| m.modified())
            .ok()
            .and_then(|t| t.elapsed().ok())
            .is_some_and(|age| age > STALE_AFTER);
        if old && entry.file_type().is_ok_and(|t| t.is_file()) {
            let _ = std::fs::remove_file(entry.path());
        }
    }
}

#[cfg(unix)]
fn default_permissions() -> std::fs::Permissions {
    use std::os::unix::fs::PermissionsExt;
    std::fs::Permissions::from_mode(0o644)
}

#[cfg(not(unix))]
fn default_permissions() -> std::fs::Permissions {
    // Elsewhere a new temporary file already has ordinary permissions.
    let probe = tempfile::tempfile().and_then(|f| f.metadata());
    probe
        .map(|m| m.permissions())
        .expect("a temporary file can be created")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn stale_temporaries_of_killed_writes_are_removed() {
        let dir = tempfile::tempdir().unwrap();
        let stale = dir.path().join(".shenlong-abc123.tmp");
        let fresh = dir.path().join(".shenlong-def456.tmp");
        std::fs::write(&stale, b"half").unwrap();
        std::fs::write(&fresh, b"in progress").unwrap();
        let hour_ago = std::time::SystemTime::now() - std::time::Duration::from_secs(3600);
        std::fs::File::options()
            .write(true)
            .open(&stale)
            .unwrap()
            .set_modified(hour_ago)
            .unwrap();
        write_atomic(&dir.path().join("scene.json"), b"x").unwrap();
        assert!(!stale.exists(), "the stale one is gone");
        assert!(
            fresh.exists(),
            "a recent one may be another write in progress"
        );
    }

    #[cfg(unix)]
    #[test]
    fn special_outputs_are_written_in_place_never_replaced() {
        use std::os::unix::fs::FileTypeExt;
        let dir = tempfile::tempdir().unwrap();
        // A FIFO with a reader: written through, still a FIFO.
        let fifo = dir.path().join("out.fifo");
        let made = std::process::Command::new("mkfifo").arg(&fifo).status();
        if made.is_ok_and(|s| s.success()) {
            let reader = {
                let fifo = fifo.clone();
                std::thread::spawn(move || std::fs::read(&fifo).unwrap())
            };
            write_atomic(&fifo, b"through the pipe").unwrap();
            assert_eq!(reader.join().unwrap(), b"through the pipe");
            assert!(std::fs::symlink_metadata(&fifo)
                .unwrap()
                .file_type()
                .is_fifo());
        }
        // A link to a character device: the link stays.
        let null = dir.path().join("null.json");
        std::os::unix::fs::symlink("/dev/null", &null).unwrap();
        write_atomic(&null, b"{}").unwrap();
        assert!(std::fs::symlink_metadata(&null)
            .unwrap()
            .file_type()
            .is_symlink());
        // A link to a regular file: the file is replaced, the link kept.
        let real = dir.path().join("real.json");
        std::fs::write(&real, b"old").unwrap();
        let link = dir.path().join("link.json");
        std::os::unix::fs::symlink(&real, &link).unwrap();
        write_atomic(&link, b"new").unwrap();
        assert!(std::fs::symlink_metadata(&link)
            .unwrap()
            .file_type()
            .is_symlink());
        assert_eq!(std::fs::read(&real).unwrap(), b"new");
        // Nothing prepared is written until committed.
        let later = dir.path().join("later.json");
        let prepared = prepare(&later, b"x").unwrap();
        assert!(!later.exists());
        drop(prepared);
        assert!(!later.exists());
    }

    #[test]
    fn writes_and_replaces() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("scene.json");
        write_atomic(&path, b"one").unwrap();
        write_atomic(&path, b"two").unwrap();
        assert_eq!(std::fs::read(&path).unwrap(), b"two");
        assert_eq!(
            std::fs::read_dir(dir.path()).unwrap().count(),
            1,
            "no temporary file left"
        );
    }

    #[test]
    fn a_failed_write_changes_nothing() {
        let dir = tempfile::tempdir().unwrap();
        let missing = dir.path().join("no such dir").join("scene.json");
        assert!(write_atomic(&missing, b"x").is_err());
        assert!(!missing.exists());
    }
}
