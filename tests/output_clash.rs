//! Outputs that would replace an input or each other are refused before any work, whatever
//! the spelling (`..`, `.`, a linked directory), by every command that writes files: exit 2,
//! one message naming the flag, and nothing written or changed. (An independent hunt found
//! `validate` and `discrepancy` writing their report over their own input, `validate` writing
//! its Markdown over its JSON, and `simulate` staging two outputs spelled apart into one
//! temporary file.)

mod common;

use common::{snooker, temp_dir};
use std::path::Path;

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

/// Runs `args`; asserts exit 2, one line naming `says`, and that `dir` holds exactly `kept`
/// afterwards, each file as it was.
#[track_caller]
fn refused(args: &[&str], says: &str, dir: &Path, kept: &[(&str, &str)]) {
    let o = snooker(args);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{args:?}: {err}");
    assert_eq!(err.trim_end().lines().count(), 1, "{args:?}: {err}");
    assert!(err.contains(says), "{args:?}: {err}");
    let mut left: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    left.sort();
    let mut want: Vec<String> = kept.iter().map(|(f, _)| f.to_string()).collect();
    want.sort();
    assert_eq!(left, want, "{args:?}");
    for (f, text) in kept {
        assert_eq!(std::fs::read_to_string(dir.join(f)).unwrap(), *text, "{f}");
    }
}

#[test]
fn two_spellings_of_one_output_are_refused() {
    let dir = temp_dir("clash-simulate");
    let scene = std::fs::read_to_string("scenes/cut-30.toml").unwrap();
    std::fs::write(dir.join("s.toml"), &scene).unwrap();
    let kept = [("s.toml", scene.as_str())];
    let input = dir.join("s.toml");
    let simulate = |json: &Path, rrd: &Path| {
        ["simulate", s(&input), "--json", s(json), "--record", s(rrd)].map(String::from)
    };
    let args = simulate(&dir.join("o/a.json"), &dir.join("o/../o/a.json"));
    let args: Vec<&str> = args.iter().map(String::as_str).collect();
    refused(&args, "is also --json's file", &dir, &kept);
    let (json, frame_out) = (dir.join("r.json"), dir.join("./x/../r.json"));
    let frame = "scenes/frames/break-off.toml";
    let args = [
        "referee",
        frame,
        "--json",
        s(&json),
        "--frame-out",
        s(&frame_out),
    ];
    refused(&args, "is also --json's file", &dir, &kept);
    #[cfg(unix)]
    {
        std::os::unix::fs::symlink("o", dir.join("link")).unwrap();
        std::fs::create_dir(dir.join("o")).unwrap();
        let args = simulate(&dir.join("o/a.json"), &dir.join("link/a.json"));
        let o = snooker(&args.iter().map(String::as_str).collect::<Vec<_>>());
        assert_eq!(o.status.code(), Some(2));
        assert!(String::from_utf8_lossy(&o.stderr).contains("is also --json's file"));
        assert_eq!(std::fs::read_dir(dir.join("o")).unwrap().count(), 0);
    }
}

#[test]
fn validate_refuses_its_input_and_one_file_for_both_reports() {
    let dir = temp_dir("clash-validate");
    let scene = std::fs::read_to_string("scenes/cut-30.toml").unwrap();
    std::fs::write(dir.join("s.toml"), &scene).unwrap();
    let kept = [("s.toml", scene.as_str())];
    let input = dir.join("s.toml");
    let args = ["validate", "--scene", s(&input), "--json", s(&input)];
    refused(&args, "is an input of the command", &dir, &kept);
    let (json, md) = (dir.join("v.json"), dir.join("v/../v.json"));
    let args = [
        "validate",
        "--scene",
        s(&input),
        "--json",
        s(&json),
        "--markdown",
        s(&md),
    ];
    refused(&args, "is also --json's file", &dir, &kept);
}

#[test]
fn discrepancy_refuses_the_files_it_reads() {
    let dir = temp_dir("clash-discrepancy");
    let scene = std::fs::read_to_string("scenes/table-i-1.toml").unwrap();
    let csv = std::fs::read_to_string("data/discrepancy/table-i.csv").unwrap();
    let csv: String = csv
        .lines()
        .filter(|l| !l.starts_with("table-i-") || l.starts_with("table-i-1,"))
        .map(|l| format!("{l}\n"))
        .collect();
    let data = "scene = \"s.toml\"\nobservables = \"t.csv\"\n";
    std::fs::write(dir.join("s.toml"), &scene).unwrap();
    std::fs::write(dir.join("t.csv"), &csv).unwrap();
    std::fs::write(dir.join("d.toml"), data).unwrap();
    let kept = [
        ("s.toml", scene.as_str()),
        ("t.csv", csv.as_str()),
        ("d.toml", data),
    ];
    let d = dir.join("d.toml");
    for target in ["d.toml", "t.csv", "x/../s.toml"] {
        let out = dir.join(target);
        let args = ["discrepancy", s(&d), "--json", s(&out)];
        refused(&args, "is an input of the command", &dir, &kept);
    }
    // The report directory's own report.json is the JSON report's file.
    let (json, report) = (dir.join("r/report.json"), dir.join("r"));
    let args = [
        "discrepancy",
        s(&d),
        "--json",
        s(&json),
        "--report",
        s(&report),
    ];
    refused(&args, "is also --json's file", &dir, &kept);
}
