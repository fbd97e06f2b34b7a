//! Writing output files: checked before any work is done, written whole or not at all.

/// Why a path cannot become an output file.
#[derive(Debug, thiserror::Error)]
pub enum OutputError {
    /// The path is a directory.
    #[error("is a directory, not a file")]
    Directory,
    /// The path ends without a file name (`..`, `/`).
    #[error("has no file name")]
    NoFileName,
    /// The path ends with a separator (`out/x.rrd/`): it names a directory, so no file can be
    /// put there (and Rust's `Path` would drop the separator and take `x.rrd` for the name).
    #[error("ends with a path separator, which names a directory, not a file")]
    TrailingSeparator,
    /// An output directory's path is a file.
    #[error("is a file, not a directory")]
    FileNotDirectory,
    /// The path is a device, a pipe or a socket: an output replaces its file whole (a
    /// temporary file renamed onto it), which would put a regular file in its place.
    #[error(
        "is not a regular file (a device, a pipe or a socket); name a file, or `-` where the option takes it for standard output"
    )]
    NotRegularFile,
    /// `-`, where the option cannot write to standard output (it would make a file named `-`).
    #[error("`-` is standard output only for --json; this option writes a file: name one")]
    Dash,
    /// A file lies where a directory on the way should be.
    #[error("{} is not a directory", .0.display())]
    NotADirectory(std::path::PathBuf),
    /// The path, or a link it leads through, is under `/dev` or `/proc` (`/dev/stdout`,
    /// `/proc/self/fd/1`): an output replaces its file whole, and renaming a file onto a
    /// system path (as root, `/dev/stdout` itself) is never what was meant.
    #[error(
        "is not a regular file: it leads to {}, under /dev or /proc (a device or a process's descriptor), which an output written whole and renamed into place must not replace; name a file, or `-` where the option takes it for standard output",
        .0.display()
    )]
    SystemPath(std::path::PathBuf),
}

/// The paths an output path leads to through the links of its last component: the path
/// itself first, the file finally written last (a link is written through and stays a link).
/// At most 40 links are followed, as the kernel allows.
pub fn link_chain(path: &std::path::Path) -> Vec<std::path::PathBuf> {
    let mut chain = vec![path.to_path_buf()];
    for _ in 0..40 {
        let last = chain.last().expect("the chain starts with the path");
        let Ok(target) = std::fs::read_link(last) else {
            break;
        };
        let next = match last.parent() {
            Some(dir) if target.is_relative() => dir.join(target),
            _ => target,
        };
        chain.push(next);
    }
    chain
}

/// True for a path under `/dev` or `/proc` (made absolute first).
fn is_system_path(path: &std::path::Path) -> bool {
    std::path::absolute(path).is_ok_and(|p| p.starts_with("/dev") || p.starts_with("/proc"))
}

/// Checks, before any work, that `path` can become an output file: it is not `-` (a caller
/// whose option takes `-` for standard output handles it before), a directory (nor ends with
/// a separator), a device, a pipe or a socket, and nothing but directories lies on its way
/// (missing directories are created when it is written).
pub fn check_output(path: &std::path::Path) -> Result<(), OutputError> {
    if path.as_os_str() == "-" {
        return Err(OutputError::Dash);
    }
    if let Some(system) = link_chain(path).into_iter().find(|p| is_system_path(p)) {
        return Err(OutputError::SystemPath(system));
    }
    if path.is_dir() {
        return Err(OutputError::Directory);
    }
    if path.file_name().is_none() {
        return Err(OutputError::NoFileName);
    }
    let last = path.as_os_str().as_encoded_bytes().last();
    if last.is_some_and(|&b| std::path::is_separator(char::from(b))) {
        return Err(OutputError::TrailingSeparator);
    }
    // `metadata` follows links, so a link to a file is a file (and `/dev/stdout` a device).
    if path.exists() && !path.is_file() {
        return Err(OutputError::NotRegularFile);
    }
    let first_existing = path
        .ancestors()
        .skip(1)
        .filter(|a| !a.as_os_str().is_empty())
        .find(|a| a.exists());
    match first_existing {
        Some(a) if !a.is_dir() => Err(OutputError::NotADirectory(a.to_path_buf())),
        _ => Ok(()),
    }
}

/// Whether `a` and `b` name one file once written: the same path after the links of the last
/// component are followed, the longest existing part is resolved (links, `.` and `..`) and
/// the rest is taken lexically (`out/../out/a.json` and `out/a.json` are one file though
/// `out` does not exist yet; so are two spellings through a linked directory).
pub fn same_file(a: &std::path::Path, b: &std::path::Path) -> bool {
    match (resolved(a), resolved(b)) {
        (Some(a), Some(b)) => a == b,
        _ => false,
    }
}

/// The file `path` leads to, as [`same_file`] compares it (None: the working directory is
/// unknown, or no part of the path exists, not even its root).
fn resolved(path: &std::path::Path) -> Option<std::path::PathBuf> {
    use std::path::Component;
    let last = link_chain(path).pop()?;
    let absolute = std::path::absolute(last).ok()?;
    let parts: Vec<Component> = absolute.components().collect();
    (0..=parts.len()).rev().find_map(|k| {
        let head: std::path::PathBuf = parts[..k].iter().collect();
        let mut out = head.canonicalize().ok()?;
        // What does not exist holds no links: `..` there undoes the part before it.
        for part in &parts[k..] {
            match part {
                Component::ParentDir => {
                    out.pop();
                }
                Component::CurDir => {}
                other => out.push(other),
            }
        }
        Some(out)
    })
}

/// Checks a command's outputs before any work: each can become a file ([`check_output`]), no
/// two are one file (the last written would replace the other), and none is one of `inputs`
/// (a frame replaced by its own next frame). The message names the flag.
pub fn check_outputs(
    outputs: &[(&str, Option<std::path::PathBuf>)],
    inputs: &[&std::path::Path],
) -> Result<(), String> {
    let given: Vec<(&str, &std::path::Path)> = outputs
        .iter()
        .filter_map(|(flag, p)| p.as_deref().map(|p| (*flag, p)))
        .collect();
    for (k, &(flag, out)) in given.iter().enumerate() {
        check_output(out).map_err(|e| format!("{flag} {}: {e}", out.display()))?;
        if let Some(input) = inputs.iter().find(|i| same_file(out, i)) {
            return Err(format!(
                "{flag} {}: is an input of the command ({}): it would be replaced",
                out.display(),
                input.display()
            ));
        }
        if let Some((other, _)) = given[..k].iter().find(|(_, o)| same_file(out, o)) {
            return Err(format!(
                "{flag} {}: is also {other}'s file: each output needs its own",
                out.display()
            ));
        }
    }
    Ok(())
}

/// Checks, before any work, that `dir` can become an output directory holding `file`: it is
/// not a file, and `file` can be written in it ([`check_output`]).
pub fn check_output_dir(dir: &std::path::Path, file: &str) -> Result<(), OutputError> {
    if dir.exists() && !dir.is_dir() {
        return Err(OutputError::FileNotDirectory);
    }
    check_output(&dir.join(file))
}

/// Writes `text` to `path` atomically: a temporary file beside it, then a rename, so nothing
/// is left half-written. Missing directories on the way are created.
pub fn write_atomic(path: &std::path::Path, text: &[u8]) -> anyhow::Result<()> {
    let mut file = AtomicFile::create(path)?;
    file.write(text)?;
    file.commit()
}

/// Several outputs put in place together: each is written whole to its temporary file (and
/// flushed to disk) first, then all are renamed, so that one that cannot be written (its
/// directory replaced by a file during the run, a full disk) leaves none of the others
/// behind. Before, a command's outputs were written one after another, and a failing `--json`
/// left the `--log` written before it on disk under an exit of 2.
#[derive(Default)]
pub struct Outputs {
    files: Vec<(String, AtomicFile)>,
    /// The first file that could not be staged (the later ones are not tried).
    error: Option<String>,
}

impl Outputs {
    /// Writes `bytes` for `path` (the output of `flag`) to its temporary file; after a file
    /// that could not be, does nothing ([`Outputs::commit`] reports it).
    pub fn add(&mut self, flag: &str, path: &std::path::Path, bytes: &[u8]) {
        if self.error.is_some() {
            return;
        }
        let label = format!("{flag} {}", path.display());
        let staged = AtomicFile::create(path).and_then(|mut f| {
            f.write(bytes)?;
            f.flush()?;
            Ok(f)
        });
        match staged {
            Ok(file) => self.files.push((label, file)),
            Err(e) => self.error = Some(format!("{label}: {e:#}")),
        }
    }

    /// `--json`'s document with its final newline, unless it goes to standard output (`-`).
    pub fn add_json(&mut self, out: Option<&str>, text: Option<&String>) {
        if let (Some(out), Some(text)) = (out.filter(|o| *o != "-"), text) {
            self.add(
                "--json",
                std::path::Path::new(out),
                format!("{text}\n").as_bytes(),
            );
        }
    }

    /// Puts every file in place, in the order added, or none if one could not be staged.
    pub fn commit(self) -> Result<(), String> {
        if let Some(e) = self.error {
            return Err(e);
        }
        for (label, file) in self.files {
            file.commit().map_err(|e| format!("{label}: {e:#}"))?;
        }
        Ok(())
    }
}

/// A file written piece by piece and put in place whole: the pieces go to a temporary file
/// beside `path`, renamed onto it by [`AtomicFile::commit`]; dropped before that, the
/// temporary file is removed and nothing is left half-written.
pub struct AtomicFile {
    path: std::path::PathBuf,
    tmp: std::path::PathBuf,
    out: Option<std::io::BufWriter<std::fs::File>>,
}

impl AtomicFile {
    /// Starts writing `path` (missing directories on the way are created). A link is written
    /// through: the temporary file goes beside the file it leads to and is renamed onto that
    /// file, so the link stays a link ([`link_chain`]).
    pub fn create(path: &std::path::Path) -> anyhow::Result<AtomicFile> {
        use anyhow::Context;
        let path = &link_chain(path).pop().expect("the chain holds the path");
        let dir = path
            .parent()
            .filter(|d| !d.as_os_str().is_empty())
            .unwrap_or(std::path::Path::new("."));
        let name = path
            .file_name()
            .context("the output path has no file name")?;
        std::fs::create_dir_all(dir).with_context(|| format!("cannot create {}", dir.display()))?;
        let tmp = dir.join(format!(".{}.tmp", name.to_string_lossy()));
        let file = std::fs::File::create(&tmp)
            .with_context(|| format!("cannot write {}", tmp.display()))?;
        Ok(AtomicFile {
            path: path.into(),
            tmp,
            out: Some(std::io::BufWriter::new(file)),
        })
    }

    /// Appends `bytes`.
    pub fn write(&mut self, bytes: &[u8]) -> anyhow::Result<()> {
        use anyhow::Context;
        use std::io::Write;
        let out = self.out.as_mut().context("the file is closed")?;
        out.write_all(bytes)
            .with_context(|| format!("cannot write {}", self.tmp.display()))
    }

    /// Writes what is buffered to the temporary file and to the disk (errors a full disk gives
    /// appear here, before anything is put in place).
    pub fn flush(&mut self) -> anyhow::Result<()> {
        use anyhow::Context;
        use std::io::Write;
        let out = self.out.as_mut().context("the file is closed")?;
        out.flush()
            .and_then(|()| out.get_ref().sync_all())
            .with_context(|| format!("cannot write {}", self.tmp.display()))
    }

    /// Puts the file in place.
    pub fn commit(mut self) -> anyhow::Result<()> {
        use anyhow::Context;
        let out = self.out.take().context("the file is closed")?;
        let done = out
            .into_inner()
            .map_err(|e| e.into_error())
            .and_then(|f| f.sync_all())
            .with_context(|| format!("cannot write {}", self.tmp.display()))
            .and_then(|()| {
                std::fs::rename(&self.tmp, &self.path)
                    .with_context(|| format!("cannot write {}", self.path.display()))
            });
        if done.is_err() {
            // The temporary file is not left behind when it cannot be put in place.
            let _ = std::fs::remove_file(&self.tmp);
        }
        done
    }
}

impl Drop for AtomicFile {
    fn drop(&mut self) {
        if self.out.take().is_some() {
            let _ = std::fs::remove_file(&self.tmp);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A file that cannot be put in place (a directory took its name after the check) leaves
    /// nothing behind: before, the temporary file `.NAME.tmp` stayed beside it.
    #[test]
    fn a_failed_commit_leaves_no_temporary_file() {
        let dir = std::env::temp_dir().join(format!("snooker-atomic-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        let path = dir.join("out.json");
        std::fs::create_dir_all(&path).unwrap();
        let mut file = AtomicFile::create(&path).unwrap();
        file.write(b"{}").unwrap();
        assert!(file.commit().is_err());
        let left: Vec<_> = std::fs::read_dir(&dir)
            .unwrap()
            .map(|e| e.unwrap().file_name())
            .collect();
        assert_eq!(left, ["out.json"]);
        std::fs::remove_dir_all(&dir).ok();
    }

    /// Outputs staged together: one that cannot be written leaves none of the others (before,
    /// a command's `--log` was in place when its `--json` failed, under an exit of 2).
    #[test]
    fn staged_outputs_are_put_in_place_all_or_none() {
        let dir = std::env::temp_dir().join(format!("snooker-staged-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        std::fs::write(dir.join("d"), "a file where a directory is needed").unwrap();
        let mut files = Outputs::default();
        files.add("--log", &dir.join("log.jsonl"), b"{}\n");
        files.add("--json", &dir.join("d/sum.json"), b"{}");
        files.add("--record", &dir.join("r.rrd"), b"rrd");
        let e = files.commit().unwrap_err();
        assert!(e.starts_with("--json "), "{e}");
        let mut left: Vec<_> = std::fs::read_dir(&dir)
            .unwrap()
            .map(|e| e.unwrap().file_name())
            .collect();
        left.sort();
        assert_eq!(left, ["d"]);
        let mut files = Outputs::default();
        files.add("--log", &dir.join("log.jsonl"), b"{}\n");
        files.add("--json", &dir.join("e/sum.json"), b"{}");
        files.commit().unwrap();
        assert_eq!(std::fs::read(dir.join("e/sum.json")).unwrap(), b"{}");
        assert_eq!(std::fs::read(dir.join("log.jsonl")).unwrap(), b"{}\n");
        std::fs::remove_dir_all(&dir).ok();
    }

    /// Two spellings of one output file are one file, whether it exists or not: through `..`
    /// and through a linked directory (before, only an existing file was resolved, and
    /// `--json o/a.json --record o/../o/a.json` staged both into one temporary file, exited 2
    /// and left the recording under the JSON's name).
    #[cfg(unix)]
    #[test]
    fn two_spellings_of_one_output_are_one_file() {
        let dir = std::env::temp_dir().join(format!("snooker-same-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(dir.join("real")).unwrap();
        std::os::unix::fs::symlink("real", dir.join("link")).unwrap();
        let pairs = [
            ("o/a.json", "o/../o/a.json"),
            ("o/a.json", "o/./a.json"),
            ("real/a.json", "link/a.json"),
            ("real/new/a.json", "link/new/x/../a.json"),
        ];
        for (a, b) in pairs {
            assert!(same_file(&dir.join(a), &dir.join(b)), "{a} {b}");
        }
        assert!(!same_file(&dir.join("o/a.json"), &dir.join("o/b.json")));
        assert!(!same_file(&dir.join("o/a.json"), &dir.join("a.json")));
        std::fs::write(dir.join("real/in.toml"), "x").unwrap();
        let e = check_outputs(
            &[("--json", Some(dir.join("link/x/../in.toml")))],
            &[&dir.join("real/in.toml")],
        )
        .unwrap_err();
        assert!(e.contains("is an input"), "{e}");
        let e = check_outputs(
            &[
                ("--json", Some(dir.join("o/a.json"))),
                ("--record", Some(dir.join("o/../o/a.json"))),
            ],
            &[],
        )
        .unwrap_err();
        assert!(e.contains("is also --json's file"), "{e}");
        std::fs::remove_dir_all(&dir).ok();
    }

    /// An output through a link writes the file it leads to: before, the temporary file was
    /// renamed onto the link itself, which became a file and left its target as it was (as
    /// root, `--log /dev/stdout` replaced the machine's `/dev/stdout`).
    #[cfg(unix)]
    #[test]
    fn a_link_is_written_through_and_a_system_path_refused() {
        let dir = std::env::temp_dir().join(format!("snooker-link-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(dir.join("sub")).unwrap();
        std::fs::write(dir.join("sub/real.json"), "old").unwrap();
        let link = dir.join("link.json");
        std::os::unix::fs::symlink("sub/real.json", &link).unwrap();
        let hop = dir.join("hop.json");
        std::os::unix::fs::symlink("link.json", &hop).unwrap();
        check_output(&hop).unwrap();
        write_atomic(&hop, b"new").unwrap();
        assert!(std::fs::symlink_metadata(&hop).unwrap().is_symlink());
        assert!(std::fs::symlink_metadata(&link).unwrap().is_symlink());
        assert_eq!(
            std::fs::read_to_string(dir.join("sub/real.json")).unwrap(),
            "new"
        );
        let left: Vec<_> = std::fs::read_dir(dir.join("sub"))
            .unwrap()
            .map(|e| e.unwrap().file_name())
            .collect();
        assert_eq!(left, ["real.json"]);
        // A link to standard output, and the system's own paths, are refused before any work.
        let out = dir.join("out.jsonl");
        std::os::unix::fs::symlink("/dev/stdout", &out).unwrap();
        for p in [
            out.as_path(),
            "/dev/stdout".as_ref(),
            "/proc/self/fd/1".as_ref(),
        ] {
            let e = check_output(p).unwrap_err();
            assert!(
                matches!(e, OutputError::SystemPath(_)),
                "{}: {e}",
                p.display()
            );
        }
        std::fs::remove_dir_all(&dir).ok();
    }
}
