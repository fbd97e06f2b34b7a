//! `snooker validate` on the command line: bad input exits 2 with a message naming it; a
//! passing scene exits 0 and writes the JSON and Markdown reports.

use std::process::Command;

/// The validation set's scene every run here uses.
const HEAD_ON_STUN: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/validation/scenes/head-on-stun.toml"
);

fn snooker() -> Command {
    Command::new(env!("CARGO_BIN_EXE_snooker"))
}

#[test]
fn a_missing_scene_is_bad_input() {
    let out = snooker()
        .args(["validate", "--scene", "no/such/scene.toml"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("no/such/scene.toml"), "{err}");
}

#[test]
fn a_bad_time_step_is_bad_input() {
    for dt in ["-1", "0.02", "nan"] {
        let out = snooker().args(["validate", "--dt", dt]).output().unwrap();
        assert_eq!(out.status.code(), Some(2), "{dt}");
    }
    // Taken before, and the cross-check never finished.
    let out = snooker()
        .args(["validate", "--dt", "1e-300"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("--dt 1e-300: must be a time step in [1e-5, 0.01] s"),
        "{err}"
    );
}

#[test]
fn one_scene_passes_and_writes_its_reports() {
    let dir = std::env::temp_dir().join(format!("snooker-validate-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let (json, md) = (dir.join("r.json"), dir.join("r.md"));
    let scene = HEAD_ON_STUN;
    let out = snooker()
        .args(["validate", "--scene", scene, "--json"])
        .arg(&json)
        .arg("--markdown")
        .arg(&md)
        .output()
        .unwrap();
    let text = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(0), "{text}");
    assert!(
        text.contains("head-on-stun") && text.contains("PASS"),
        "{text}"
    );
    let doc: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap();
    assert_eq!(doc["runs"][0]["outcome"]["status"], "compared");
    assert!(
        std::fs::read_to_string(&md)
            .unwrap()
            .contains("| head-on-stun |")
    );
    std::fs::remove_dir_all(&dir).ok();
}

/// `--json -` is standard output, as for `simulate`, `referee`, `plan` and `discrepancy`:
/// before, a file named `-` was written.
#[test]
fn json_to_standard_output() {
    let dir = std::env::temp_dir().join(format!("snooker-validate-dash-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let scene = HEAD_ON_STUN;
    let out = snooker()
        .current_dir(&dir)
        .args(["validate", "--scene", scene, "--json", "-"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0));
    let doc: serde_json::Value = serde_json::from_slice(&out.stdout).expect("JSON on stdout");
    assert_eq!(doc["runs"][0]["outcome"]["status"], "compared");
    assert!(String::from_utf8_lossy(&out.stderr).contains("PASS"));
    assert!(!dir.join("-").exists(), "a file named - was written");
    std::fs::remove_dir_all(&dir).ok();
}

/// An output that cannot be written is refused before the cross-check runs (minutes over the
/// whole set), and nothing is written: before, the report was printed, `--json` written, and
/// only then did `--markdown DIR` (a directory) fail, leaving a half-done output and a
/// temporary file beside it.
#[test]
fn an_output_that_cannot_be_written_is_refused_before_the_run() {
    let dir = std::env::temp_dir().join(format!("snooker-validate-out-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    let blocked = dir.join("md");
    std::fs::create_dir_all(&blocked).unwrap();
    let json = dir.join("r.json");
    let scene = HEAD_ON_STUN;
    let out = snooker()
        .args(["validate", "--scene", scene, "--json"])
        .arg(&json)
        .arg("--markdown")
        .arg(&blocked)
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(
        err.contains("--markdown") && err.contains("is a directory"),
        "{err}"
    );
    assert!(
        out.stdout.is_empty(),
        "{}",
        String::from_utf8_lossy(&out.stdout)
    );
    let left: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    assert_eq!(left, ["md"], "nothing but the directory in the way");
    std::fs::remove_dir_all(&dir).ok();
}

/// The break-off's sections of the committed report (docs/validation.md, written by
/// `snooker validate --convergence --markdown docs/validation.md`) are what the command
/// writes today: its impacts and its outcome statistics. They had gone stale when the contact
/// detection changed (an extra red1-red3 impact; 35.059 ball-ball impacts on average where
/// the command gives 35.118).
#[test]
fn the_committed_report_has_the_break_off_the_command_writes() {
    let dir = std::env::temp_dir().join(format!("snooker-validate-doc-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let md = dir.join("break-off.md");
    let root = env!("CARGO_MANIFEST_DIR");
    let scene = format!("{root}/validation/scenes/break-off.toml");
    let out = snooker()
        .args(["validate", "--scene", &scene, "--markdown"])
        .arg(&md)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0));
    let written = std::fs::read_to_string(&md).unwrap();
    let committed = std::fs::read_to_string(format!("{root}/docs/validation.md")).unwrap();
    // The sections (from one heading to the next) about the break-off itself.
    let sections = written.split("\n#").filter(|s| {
        let heading = s.lines().next().unwrap_or_default();
        heading.contains("break-off")
    });
    let mut n = 0;
    for s in sections {
        assert!(committed.contains(s), "docs/validation.md lacks:\n#{s}");
        n += 1;
    }
    assert_eq!(n, 4, "two details and two outcome statistics");
    std::fs::remove_dir_all(&dir).ok();
}
