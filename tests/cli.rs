//! The command line: the default run, the JSON contract, and bad input (one message naming the
//! file, the key and the reason; exit code 2; nothing written).

mod common;

use common::{snooker, temp_dir};
use serde_json::Value;
use std::path::Path;

#[test]
fn default_run_prints_a_summary_and_writes_the_contract() {
    // The README's main command, in a fresh directory: `out/` does not exist yet.
    let dir = temp_dir("default");
    let o = std::process::Command::new(env!("CARGO_BIN_EXE_snooker"))
        .current_dir(&dir)
        .args([
            "simulate",
            "--json",
            "out/break-off.json",
            "--record",
            "out/break-off.rrd",
        ])
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let out = dir.join("out/break-off.json");
    assert!(
        std::fs::metadata(dir.join("out/break-off.rrd"))
            .unwrap()
            .len()
            > 1_000_000
    );
    let text = String::from_utf8(o.stdout).unwrap();
    for needle in [
        "scene: break-off",
        "events by kind:",
        "pots:",
        "final positions",
        "simulated",
    ] {
        assert!(text.contains(needle), "summary lacks {needle:?}:\n{text}");
    }
    let doc: Value = serde_json::from_str(&std::fs::read_to_string(&out).unwrap()).unwrap();
    assert_eq!(doc["scene"], "break-off");
    let events = doc["events"].as_array().unwrap();
    let kinds = [
        "ball_ball",
        "ball_cushion",
        "ball_pocket",
        "slide_to_roll",
        "slide_to_spin",
        "slide_to_stop",
        "roll_to_spin",
        "roll_to_stop",
        "spin_to_stop",
        "lift_off",
        "landing",
    ];
    let motions = [
        "sliding",
        "rolling",
        "spinning",
        "stationary",
        "airborne",
        "pocketed",
    ];
    let mut last = 0.0;
    for e in events {
        let t = e["t"].as_f64().unwrap();
        assert!(t >= last);
        last = t;
        assert!(kinds.contains(&e["kind"].as_str().unwrap()), "{e}");
        let balls = e["balls"].as_array().unwrap();
        for b in balls {
            let s = &e["after"][b.as_str().unwrap()];
            assert_eq!(s["pos"].as_array().unwrap().len(), 3);
            assert_eq!(s["vel"].as_array().unwrap().len(), 3);
            assert_eq!(s["spin"].as_array().unwrap().len(), 3);
            assert!(motions.contains(&s["motion"].as_str().unwrap()));
        }
    }
    let fin = doc["final"].as_object().unwrap();
    assert_eq!(fin.len(), 22);
    for s in fin.values() {
        assert!(["stationary", "pocketed"].contains(&s["motion"].as_str().unwrap()));
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn json_to_stdout() {
    let o = snooker(&["simulate", "-q", "--json", "-"]);
    assert!(o.status.success());
    let doc: Value = serde_json::from_slice(&o.stdout).unwrap();
    assert!(doc["events"].is_array());
}

/// Runs a bad scene; checks exit code 2, a single error line naming the file and key, and that
/// the requested output was not written.
fn rejects(tag: &str, scene: &str, key: &str, reason: &str) {
    let dir = temp_dir(tag);
    let path = dir.join(format!("{tag}.toml"));
    std::fs::write(&path, scene).unwrap();
    let out = dir.join("r.json");
    let o = snooker(&[
        "simulate",
        path.to_str().unwrap(),
        "--json",
        out.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(2), "{tag}");
    let err = String::from_utf8(o.stderr).unwrap();
    assert_eq!(err.lines().count(), 1, "{tag}: {err}");
    assert!(
        err.contains(path.to_str().unwrap()),
        "{tag}: no file in {err}"
    );
    assert!(
        err.contains(&format!("`{key}`")),
        "{tag}: no key {key} in {err}"
    );
    assert!(err.contains(reason), "{tag}: no reason {reason:?} in {err}");
    assert!(!Path::new(&out).exists(), "{tag}: output written");
    assert!(o.stdout.is_empty());
    std::fs::remove_dir_all(&dir).unwrap();
}

const BALL: &str = "[[balls]]\nid = \"cue\"\npos = [0.5, 0.5]\n";

#[test]
fn bad_scenes_are_rejected_with_file_key_and_reason() {
    rejects(
        "unknown",
        "[params]\nmu_slid = 0.2\n",
        "params.mu_slid",
        "unknown field",
    );
    rejects(
        "overlap",
        &format!("{BALL}[[balls]]\nid = \"red\"\npos = [0.52, 0.5]\n"),
        "balls[1].pos",
        "overlaps",
    );
    rejects(
        "off",
        "[[balls]]\nid = \"cue\"\npos = [3.6, 0.5]\n",
        "balls[0].pos",
        "off the cloth",
    );
    rejects(
        "miscue",
        &format!("{BALL}[cue]\nball = \"cue\"\nspeed = 2.0\naim = 0.0\noffset = [0.0, 0.025]\n"),
        "cue.offset",
        "miscue",
    );
    rejects(
        "nan",
        "[[balls]]\nid = \"cue\"\npos = [0.5, nan]\n",
        "balls[0].pos",
        "finite",
    );
    rejects(
        "inf",
        &format!("{BALL}[cue]\nball = \"cue\"\nspeed = inf\naim = 0.0\n"),
        "cue.speed",
        "finite",
    );
    rejects(
        "param",
        &format!("{BALL}[params]\ne_ball = 1.5\n"),
        "params.e_ball",
        "[0, 1]",
    );
    rejects(
        "model",
        &format!("{BALL}[models]\ncushion = \"rubber\"\n"),
        "models.cushion",
        "unknown variant",
    );
    rejects(
        "noball",
        &format!("{BALL}[cue]\nball = \"white\"\nspeed = 1.0\naim = 0.0\n"),
        "cue.ball",
        "no ball",
    );
    rejects(
        "layout",
        "layout = \"nine-ball\"\n",
        "layout",
        "unknown layout",
    );
    rejects("dup", &format!("{BALL}{BALL}"), "balls[1].id", "used twice");
    // A table written as an array: serde's derive read it by position (this strike was played
    // at 2 m/s, aim 0.1), so a reordering of the struct's fields changed what it meant.
    rejects(
        "cue-array",
        &format!("cue = [\"cue\", 2.0, 0.1]\n{BALL}"),
        "cue",
        "invalid type: sequence, expected struct",
    );
    rejects(
        "ball-array",
        "balls = [[\"cue\", [0.5, 0.5]]]\n",
        "balls[0]",
        "invalid type: sequence, expected struct",
    );
    // A huge value is read back short: `{}` wrote 1e300 as 301 digits.
    for (tag, scene, key, shown) in [
        (
            "huge-speed",
            format!("{BALL}[cue]\nball = \"cue\"\nspeed = 1e300\naim = 0.0\n"),
            "cue.speed",
            "got 1e300",
        ),
        (
            "far",
            "[[balls]]\nid = \"cue\"\npos = [1e300, 0.5]\n".to_string(),
            "balls[0].pos",
            "centre (1.0000e300, 0.5000) m",
        ),
        (
            "huge-param",
            format!("{BALL}[params]\nmu_slide = -1e300\n"),
            "params.mu_slide",
            "got -1e300",
        ),
    ] {
        rejects(tag, &scene, key, shown);
    }
}

#[test]
fn a_missing_file_is_reported() {
    let o = snooker(&["simulate", "/nonexistent/scene.toml"]);
    assert_eq!(o.status.code(), Some(2));
    let err = String::from_utf8(o.stderr).unwrap();
    assert!(err.contains("/nonexistent/scene.toml") && err.contains("cannot read"));
}

#[test]
fn bad_arguments_exit_with_2_and_one_line() {
    // Issue 11: an unknown flag printed clap's seven-line usage.
    for args in [
        &["simulate", "--bogus"][..],
        &["frobnicate"],
        &["impact", "--speed"],
    ] {
        let o = snooker(args);
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        let err = String::from_utf8(o.stderr).unwrap();
        assert_eq!(err.trim_end().lines().count(), 1, "{args:?}: {err}");
        assert!(err.starts_with("error: "), "{args:?}: {err}");
    }
}

#[test]
fn an_output_that_is_a_device_is_refused_before_any_work() {
    // An output is written to a temporary file renamed onto its path: on /dev/null that
    // replaced the device with a regular file when run as root, and failed after the
    // simulation otherwise. It is refused up front, naming the option.
    for (args, option) in [
        (
            &["simulate", "scenes/cut-30.toml", "--json", "/dev/null"][..],
            "--json",
        ),
        (
            &["simulate", "scenes/cut-30.toml", "--record", "/dev/null"],
            "--record",
        ),
    ] {
        refused(args, &[option, "not a regular file"]);
    }
    assert!(std::path::Path::new("/dev/null").exists());
}

/// `args` exit 2 with one line naming each of `needles`.
fn refused(args: &[&str], needles: &[&str]) {
    let o = snooker(args);
    assert_eq!(o.status.code(), Some(2), "{args:?}");
    let err = String::from_utf8(o.stderr).unwrap();
    assert_eq!(err.trim_end().lines().count(), 1, "{err}");
    for n in needles {
        assert!(err.contains(n), "{args:?}: {n:?} not in {err}");
    }
}

#[test]
fn an_endless_input_is_refused_not_read_for_ever() {
    // `/dev/zero` as the scene: every command read it until memory ran out.
    for args in [
        &["simulate", "/dev/zero"][..],
        &["referee", "/dev/zero"],
        &[
            "plan",
            "/dev/zero",
            "--pot",
            "red",
            "--pocket",
            "top-left",
            "--cue-to",
            "1,0",
        ],
    ] {
        refused(args, &["/dev/zero", "256 MiB"]);
    }
}

#[test]
fn the_result_says_why_the_shot_ended() {
    // A shot stopped at its horizon showed moving balls in `final`, which the contract says
    // are at rest: `ending` (an extension) tells the two apart, read as a script reads it.
    let dir = temp_dir("ending");
    let scene = dir.join("s.toml");
    for (sim, ending, motion) in [
        ("", "at_rest", "stationary"),
        ("[sim]\nhorizon = 0.5\n", "horizon", "rolling"),
    ] {
        std::fs::write(
            &scene,
            format!(
                "balls = [{{id = \"cue\", pos = [1.0, 0.8], vel = [1.0, 0.0, 0.0], spin = [0.0, 38.17, 0.0]}}]\n{sim}"
            ),
        )
        .unwrap();
        let o = snooker(&["simulate", scene.to_str().unwrap(), "-q", "--json", "-"]);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        let doc: Value = serde_json::from_slice(&o.stdout).unwrap();
        assert_eq!(doc["ending"], ending, "{sim}");
        assert_eq!(doc["final"]["cue"]["motion"], motion, "{sim}");
        // After `duration`, as the extension is documented.
        let keys: Vec<&str> = doc
            .as_object()
            .unwrap()
            .keys()
            .map(String::as_str)
            .collect();
        let at = |k: &str| keys.iter().position(|x| *x == k).unwrap();
        assert_eq!(at("ending"), at("duration") + 1, "{keys:?}");
    }
}

#[test]
fn the_readmes_simulate_tour_shows_what_the_command_prints() {
    // The tour's lines are the command's own, in order (the last shown one ends in "..."
    // where the README cuts it short): a wording changed in the summary changes the README.
    let readme =
        std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/README.md")).unwrap();
    let start = "$ snooker simulate scenes/break-off.toml --json out/break-off.json\n";
    let block = &readme[readme.find(start).expect("the tour's simulate block") + start.len()..];
    let shown: Vec<&str> = block
        .lines()
        .take_while(|l| !l.starts_with("```"))
        .collect();
    assert!(shown.len() >= 3, "{shown:?}");
    let o = snooker(&["simulate", "scenes/break-off.toml"]);
    assert!(o.status.success());
    let printed = String::from_utf8(o.stdout).unwrap();
    let printed: Vec<&str> = printed.lines().collect();
    for (k, line) in shown.iter().enumerate() {
        match line.strip_suffix("...") {
            Some(head) => assert!(printed[k].starts_with(head), "{line}\n{}", printed[k]),
            None => assert_eq!(*line, printed[k]),
        }
    }
}
