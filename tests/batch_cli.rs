//! `snooker batch`: every scene of `scenes/` gives, line for line, the result `snooker simulate
//! --json` gives (to the bit), whatever the thread count; a failing scene keeps its place with
//! its error and the batch goes on (exit 1); the Parquet table; bad input (exit 2, one
//! message, nothing written).

mod common;

use common::{snooker, temp_dir};
use serde_json::Value;
use std::path::Path;

fn lines(path: &Path) -> Vec<Value> {
    std::fs::read_to_string(path)
        .unwrap()
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect()
}

#[test]
fn a_directory_gives_simulate_results_line_for_line_on_any_thread_count() {
    let dir = temp_dir("batch-dir");
    let (one, two) = (dir.join("one.jsonl"), dir.join("two.jsonl"));
    for (out, threads) in [(&one, "1"), (&two, "2")] {
        let o = snooker(&[
            "batch",
            "scenes",
            "--out",
            out.to_str().unwrap(),
            "--threads",
            threads,
        ]);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    }
    assert_eq!(std::fs::read(&one).unwrap(), std::fs::read(&two).unwrap());
    let mut files: Vec<_> = std::fs::read_dir("scenes")
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "toml"))
        .collect();
    files.sort();
    let got = lines(&one);
    assert_eq!(got.len(), files.len());
    for (file, mut line) in files.iter().zip(got) {
        let o = snooker(&["simulate", file.to_str().unwrap(), "--quiet", "--json", "-"]);
        assert!(o.status.success());
        let want: Value = serde_json::from_slice(&o.stdout).unwrap();
        let source = line.as_object_mut().unwrap().remove("source").unwrap();
        assert_eq!(source, file.to_str().unwrap());
        assert_eq!(line, want, "{}", file.display());
    }
}

#[test]
fn a_failing_scene_keeps_its_place_and_the_batch_goes_on() {
    let dir = temp_dir("batch-fail");
    let input = dir.join("shots.jsonl");
    let good = r#"{"balls": [{"id": "cue", "pos": [1.0, 0.8]}, {"id": "red", "pos": [2.0, 0.9]}], "cue": {"ball": "cue", "speed": 2.0, "aim": 0.1}}"#;
    let bad = r#"{"balls": [{"id": "cue", "pos": [1.0, 0.8, 3.0]}]}"#;
    std::fs::write(&input, format!("{good}\n\n{bad}\n{good}\n")).unwrap();
    for out in ["r.jsonl", "r.parquet"] {
        let out = dir.join(out);
        let o = snooker(&[
            "batch",
            input.to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
        ]);
        assert_eq!(o.status.code(), Some(1));
        let err = String::from_utf8_lossy(&o.stderr);
        assert!(
            err.contains("shots.jsonl:3") && err.contains("balls[0].pos"),
            "{err}"
        );
        // The scene's source once, not twice.
        assert_eq!(err.matches("shots.jsonl:3").count(), 1, "{err}");
        assert!(out.exists());
    }
    let got = lines(&dir.join("r.jsonl"));
    assert_eq!(got.len(), 3);
    assert!(
        got[0]["source"]
            .as_str()
            .unwrap()
            .ends_with("shots.jsonl:1")
    );
    assert!(got[1]["error"].as_str().unwrap().contains("balls[0].pos"));
    assert!(got[1].get("events").is_none());
    assert_eq!(got[0]["final"], got[2]["final"]);
    // A Parquet file (its magic number at both ends; its columns are read back in
    // batch/tests/table.rs and by pyarrow in python/tests).
    let table = std::fs::read(dir.join("r.parquet")).unwrap();
    assert!(table.starts_with(b"PAR1") && table.ends_with(b"PAR1"));
}

#[test]
fn bad_input_is_one_message_and_nothing_written() {
    let dir = temp_dir("batch-bad");
    let out = dir.join("r.jsonl");
    let txt = dir.join("scenes.txt");
    std::fs::write(&txt, "x").unwrap();
    let empty = dir.join("empty");
    std::fs::create_dir_all(&empty).unwrap();
    for (args, says) in [
        (vec!["batch", "no/such/dir", "--out"], "no/such/dir"),
        (vec!["batch", txt.to_str().unwrap(), "--out"], "JSON-lines"),
        (vec!["batch", empty.to_str().unwrap(), "--out"], "no scenes"),
        (
            vec!["batch", "scenes", "--threads", "0", "--out"],
            "--threads",
        ),
        (vec!["batch", "scenes", "--out"], "is a directory"),
        // A CSV name got JSON lines under it; `-` made a file named `-`.
        (vec!["batch", "scenes", "--out"], "not .csv"),
        (
            vec!["batch", "scenes", "--out"],
            "standard output only for --json",
        ),
    ] {
        let mut args = args.clone();
        let csv = dir.join("r.csv");
        let target = match says {
            "is a directory" => dir.to_str().unwrap(),
            "not .csv" => csv.to_str().unwrap(),
            "standard output only for --json" => "-",
            _ => out.to_str().unwrap(),
        };
        args.push(target);
        let o = snooker(&args);
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(err.lines().count(), 1, "{err}");
        assert!(err.contains(says), "{args:?}: {err}");
        assert!(!out.exists(), "{args:?}");
    }
}

/// A thread count far beyond any machine's cores is refused at once (exit 2, naming
/// `--threads`): before, `--threads 100000` (or 2^64 - 1) started that many threads for
/// every chunk and had not finished a 15-scene batch after a minute.
#[test]
fn a_huge_thread_count_is_refused_at_once() {
    let dir = temp_dir("batch-threads");
    let out = dir.join("r.jsonl");
    for n in ["100000", "18446744073709551615"] {
        let mut child = std::process::Command::new(env!("CARGO_BIN_EXE_snooker"))
            .args(["batch", "scenes", "--threads", n, "--out"])
            .arg(&out)
            .stderr(std::process::Stdio::piped())
            .spawn()
            .unwrap();
        let start = std::time::Instant::now();
        let status = loop {
            if let Some(s) = child.try_wait().unwrap() {
                break s;
            }
            if start.elapsed().as_secs() > 20 {
                child.kill().unwrap();
                child.wait().unwrap();
                panic!("--threads {n}: still running after 20 s");
            }
            std::thread::sleep(std::time::Duration::from_millis(50));
        };
        let mut err = String::new();
        std::io::Read::read_to_string(&mut child.stderr.take().unwrap(), &mut err).unwrap();
        assert_eq!(status.code(), Some(2), "{err}");
        assert!(
            err.contains("--threads") && err.contains("at most"),
            "{err}"
        );
        assert!(!out.exists());
    }
    std::fs::remove_dir_all(&dir).ok();
}

/// The results never replace the batch's own input: before, `batch shots.jsonl --out
/// shots.jsonl` read the scenes, then wrote the results over them (exit 0, the scenes gone).
#[test]
fn the_results_do_not_replace_the_input() {
    let dir = temp_dir("batch-same");
    let input = dir.join("shots.jsonl");
    let text = "{\"balls\": [{\"id\": \"cue\", \"pos\": [1.0, 0.8]}], \"cue\": {\"ball\": \"cue\", \"speed\": 1.0, \"aim\": 0.0}}\n";
    std::fs::write(&input, text).unwrap();
    let o = snooker(&[
        "batch",
        input.to_str().unwrap(),
        "--out",
        input.to_str().unwrap(),
    ]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.contains("--out") && err.contains("input"), "{err}");
    assert_eq!(std::fs::read_to_string(&input).unwrap(), text);
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn a_scene_entry_that_cannot_be_read_fails_in_its_place() {
    // A dangling link and an upper-case extension were skipped without a word: "1 scenes,
    // 0 failed", exit 0, a scene lost from a run that said it succeeded.
    let dir = temp_dir("batch-entries");
    let scenes = dir.join("scenes");
    std::fs::create_dir_all(&scenes).unwrap();
    let good = "balls = [{id = \"cue\", pos = [1.0, 0.8]}]\n[cue]\nball = \"cue\"\nspeed = 1.0\naim = 0.2\n";
    std::fs::write(scenes.join("a.toml"), good).unwrap();
    std::fs::write(scenes.join("c.TOML"), good).unwrap();
    std::os::unix::fs::symlink(dir.join("missing.toml"), scenes.join("b.toml")).unwrap();
    let out = dir.join("r.jsonl");
    let o = snooker(&[
        "batch",
        scenes.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(1), "{err}");
    assert!(err.contains("b.toml"), "{err}");
    let got = lines(&out);
    assert_eq!(got.len(), 3);
    assert!(got[0].get("error").is_none() && got[2].get("error").is_none());
    assert!(got[1]["error"].as_str().unwrap().contains("b.toml"));
    assert!(got[2]["source"].as_str().unwrap().ends_with("c.TOML"));
    // An upper-case .PARQUET is a table too (it was JSON lines under that name).
    let table = dir.join("r.PARQUET");
    snooker(&[
        "batch",
        scenes.to_str().unwrap(),
        "--out",
        table.to_str().unwrap(),
        "-q",
    ]);
    assert!(std::fs::read(&table).unwrap().starts_with(b"PAR1"));
}
