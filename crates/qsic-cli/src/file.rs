//! Writing an output file whole or not at all (`qsic plot -o FILE`, `qsic motion --plot FILE`).
//!
//! The bytes go to a new temporary file in the target's directory (so that the rename stays
//! on one file system), are flushed and synced, and the temporary is renamed over the target
//! only then: a reader sees the old file or the new one, never a truncated one, and an error
//! (a full disk, a file size limit, a rename refused) removes the temporary and leaves the
//! target as it was. A target that exists and is not a regular file (`/dev/stdout`, a
//! FIFO) is written in place: it holds no file to leave half written, and replacing it would
//! be wrong. A symbolic link is followed to the file it names.

use std::fs::{self, File, OpenOptions};
use std::io::{self, Write};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering};

/// Writes `bytes` to `path` whole or not at all (module docs).
///
/// # Errors
/// The first I/O error: creating the temporary, writing, syncing, or renaming it (the
/// temporary is removed; `path` is unchanged), or writing a non-regular target in place.
pub fn write_atomically(path: &Path, bytes: &[u8]) -> io::Result<()> {
    write_atomically_with(path, |file| file.write_all(bytes))
}

/// [`write_atomically`] with the contents written by `fill` into the temporary (or into a
/// non-regular target) — the seam through which the tests make a write fail.
///
/// # Errors
/// As [`write_atomically`], and the error of `fill`.
pub fn write_atomically_with<F>(path: &Path, fill: F) -> io::Result<()>
where
    F: FnOnce(&mut dyn Write) -> io::Result<()>,
{
    let target = resolved(path);
    if let Ok(meta) = fs::metadata(&target) {
        if !meta.is_file() && !meta.is_dir() {
            let mut file = OpenOptions::new().write(true).open(&target)?;
            fill(&mut file)?;
            return file.flush();
        }
    }
    let (mut file, temp) = create_temporary(&target)?;
    let written = (|| {
        fill(&mut file)?;
        file.flush()?;
        if let Ok(meta) = fs::metadata(&target) {
            // the replaced file's permissions, not the temporary's
            file.set_permissions(meta.permissions())?;
        }
        file.sync_all()?;
        drop(file);
        fs::rename(&temp, &target)
    })();
    if written.is_err() {
        let _ = fs::remove_file(&temp);
    }
    written
}

/// `path`, or the file a symbolic link at `path` names (when it resolves).
fn resolved(path: &Path) -> PathBuf {
    match fs::symlink_metadata(path) {
        Ok(m) if m.file_type().is_symlink() => {
            fs::canonicalize(path).unwrap_or_else(|_| path.to_path_buf())
        }
        _ => path.to_path_buf(),
    }
}

/// A new file `.NAME.PID-K.tmp` beside `target`, created exclusively.
fn create_temporary(target: &Path) -> io::Result<(File, PathBuf)> {
    static NEXT: AtomicUsize = AtomicUsize::new(0);
    let dir = match target.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => Path::new("."),
    };
    let name = target
        .file_name()
        .ok_or_else(|| io::Error::new(io::ErrorKind::InvalidInput, "not a file name"))?
        .to_string_lossy();
    loop {
        let k = NEXT.fetch_add(1, Ordering::Relaxed);
        let temp = dir.join(format!(".{name}.{}-{k}.tmp", std::process::id()));
        match OpenOptions::new().write(true).create_new(true).open(&temp) {
            Ok(file) => return Ok((file, temp)),
            Err(e) if e.kind() == io::ErrorKind::AlreadyExists && k < 1000 => continue,
            Err(e) => return Err(e),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A fresh directory for one test.
    fn scratch(name: &str) -> PathBuf {
        let dir = std::env::temp_dir().join(format!("qsic-file-{name}-{}", std::process::id()));
        let _ = fs::remove_dir_all(&dir);
        fs::create_dir_all(&dir).unwrap();
        dir
    }

    fn entries(dir: &Path) -> Vec<String> {
        let mut names: Vec<String> = fs::read_dir(dir)
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .collect();
        names.sort();
        names
    }

    /// A write that fails half way (a full disk) leaves the old file and no temporary; one
    /// that succeeds replaces it.
    #[test]
    fn a_failed_write_leaves_the_target_as_it_was() {
        let dir = scratch("fail");
        let path = dir.join("out.svg");
        fs::write(&path, "old").unwrap();
        let full = |w: &mut dyn Write| {
            w.write_all(b"<svg>half")?;
            Err(io::Error::new(io::ErrorKind::StorageFull, "no space left"))
        };
        let e = write_atomically_with(&path, full).unwrap_err();
        assert_eq!(e.kind(), io::ErrorKind::StorageFull);
        assert_eq!(fs::read_to_string(&path).unwrap(), "old");
        assert_eq!(entries(&dir), ["out.svg"]);
        // no target before: none after
        let fresh = dir.join("new.svg");
        assert!(write_atomically_with(&fresh, full).is_err());
        assert_eq!(entries(&dir), ["out.svg"]);
        write_atomically(&path, b"<svg/>").unwrap();
        assert_eq!(fs::read_to_string(&path).unwrap(), "<svg/>");
        assert_eq!(entries(&dir), ["out.svg"]);
        fs::remove_dir_all(&dir).unwrap();
    }

    /// A rename that fails (the target is a directory) removes the temporary.
    #[test]
    fn a_failed_rename_removes_the_temporary() {
        let dir = scratch("rename");
        fs::create_dir(dir.join("out.svg")).unwrap();
        fs::write(dir.join("out.svg").join("keep"), "x").unwrap();
        assert!(write_atomically(&dir.join("out.svg"), b"<svg/>").is_err());
        assert_eq!(entries(&dir), ["out.svg"]);
        assert_eq!(entries(&dir.join("out.svg")), ["keep"]);
        fs::remove_dir_all(&dir).unwrap();
    }

    /// A symbolic link is written through: the link stays, its file changes.
    #[cfg(unix)]
    #[test]
    fn a_link_is_followed() {
        let dir = scratch("link");
        let real = dir.join("real.svg");
        fs::write(&real, "old").unwrap();
        let link = dir.join("link.svg");
        std::os::unix::fs::symlink(&real, &link).unwrap();
        write_atomically(&link, b"new").unwrap();
        assert!(fs::symlink_metadata(&link)
            .unwrap()
            .file_type()
            .is_symlink());
        assert_eq!(fs::read_to_string(&real).unwrap(), "new");
        fs::remove_dir_all(&dir).unwrap();
    }
}
