//! `snooker referee` as a script outside the project uses it (formats.md, "Frame" and
//! "Referee result"): the JSON's fields by name and in order, three strokes chained through
//! `--frame-out` (the README's example) and played again as one sequence with a recording
//! read back by Rerun's decoder, the end of a frame, and bad frames (exit 2, the key named,
//! nothing written).

mod common;

use common::{snooker, temp_dir};
use serde_json::Value;
use std::path::{Path, PathBuf};

const FRAMES: &str = "rules/tests/frames";

fn json(path: &Path) -> Value {
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

fn keys(v: &Value) -> Vec<&str> {
    v.as_object().unwrap().keys().map(String::as_str).collect()
}

fn ok(args: &[&str]) -> String {
    let o = snooker(args);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    String::from_utf8(o.stdout).unwrap()
}

#[test]
fn the_result_has_the_contracts_fields_in_its_order() {
    let dir = temp_dir("referee-fields");
    let out = dir.join("r.json");
    let frame = format!("{FRAMES}/first_hit_not_on.toml");
    ok(&["referee", &frame, "--json", out.to_str().unwrap()]);
    let r = json(&out);
    assert_eq!(
        keys(&r),
        [
            "legal",
            "foul",
            "first_hit",
            "potted",
            "off_table",
            "points",
            "scores",
            "next",
            "respotted",
            "frame_over",
            "winner",
            "shot"
        ]
    );
    assert_eq!(r["legal"], false);
    assert_eq!(keys(&r["foul"])[..2], ["reason", "points"]);
    assert_eq!(r["foul"]["reason"], "first_hit_not_on");
    assert_eq!(r["foul"]["points"], 5);
    assert_eq!(r["first_hit"], "blue");
    assert_eq!(r["potted"], serde_json::json!([]));
    assert_eq!(r["off_table"], serde_json::json!([]));
    assert_eq!(r["points"], 0);
    assert_eq!(r["scores"], serde_json::json!([12, 5]));
    assert_eq!(
        keys(&r["next"]),
        ["to_play", "on", "nominated", "ball_in_hand", "free_ball"]
    );
    assert_eq!(
        r["next"],
        serde_json::json!({"to_play": 1, "on": "red", "nominated": "", "ball_in_hand": false, "free_ball": false})
    );
    assert_eq!(r["respotted"], serde_json::json!([]));
    assert_eq!(
        (&r["frame_over"], &r["winner"]),
        (&Value::Bool(false), &Value::Null)
    );
    // The shot is the Result (JSON) of the strike, as `snooker simulate` writes it.
    for k in ["scene", "events", "final"] {
        assert!(r["shot"].get(k).is_some(), "no shot.{k}");
    }
    // To standard output with `-`, the summary going to standard error.
    let o = snooker(&["referee", &frame, "--json", "-"]);
    assert!(o.status.success());
    let from_stdout: Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(from_stdout, r);
    assert!(String::from_utf8_lossy(&o.stderr).contains("foul, first_hit_not_on"));
    // Respots: each with its ball and position.
    ok(&[
        "referee",
        &format!("{FRAMES}/two_colours_potted.toml"),
        "--json",
        out.to_str().unwrap(),
    ]);
    let r = json(&out);
    assert_eq!(r["respotted"][0]["ball"], "black");
    assert_eq!(r["respotted"][0]["pos"], serde_json::json!([3.245, 0.889]));
    assert_eq!(keys(&r["respotted"][1]), ["ball", "pos"]);
}

/// Appends a strike to a frame file as its `[cue]`.
fn with_strike(from: &Path, to: &Path, speed: f64, aim: f64) {
    let text = std::fs::read_to_string(from).unwrap();
    let cue = format!("[cue]\nball = \"cue\"\nspeed = {speed}\naim = {aim}\n");
    std::fs::write(to, text + &cue).unwrap();
}

#[test]
fn three_strokes_chain_through_frame_out_and_play_again_as_one_recorded_sequence() {
    // The README's example.
    let dir = temp_dir("referee-chain");
    let p = |n: &str| dir.join(n);
    let s = |p: &PathBuf| p.to_str().unwrap().to_string();
    ok(&[
        "referee",
        "scenes/frames/break-off.toml",
        "--frame-out",
        &s(&p("f1.toml")),
    ]);
    with_strike(&p("f1.toml"), &p("s1.toml"), 2.5, -0.15);
    ok(&[
        "referee",
        &s(&p("s1.toml")),
        "--frame-out",
        &s(&p("f2.toml")),
    ]);
    with_strike(&p("f2.toml"), &p("s2.toml"), 4.0, 0.2);
    ok(&[
        "referee",
        &s(&p("s2.toml")),
        "--json",
        &s(&p("r3.json")),
        "--frame-out",
        &s(&p("f3.toml")),
    ]);
    let r3 = json(&p("r3.json"));
    // Player 1 played the second stroke, player 0 the third: a red, 1 point, on a colour next.
    assert_eq!(r3["potted"], serde_json::json!(["red15"]));
    assert_eq!(r3["scores"], serde_json::json!([1, 0]));
    assert_eq!(r3["next"]["on"], "colour");
    assert_eq!(r3["next"]["to_play"], 0);
    let f3 = std::fs::read_to_string(p("f3.toml")).unwrap();
    assert!(
        f3.contains("[frame]\non = \"colour\"\nscores = [1, 0]\nto_play = 0"),
        "{f3}"
    );
    assert!(!f3.contains("[cue]") && !f3.contains("red15"));

    // The three as one sequence: the same last result, and one recording of them all.
    let out = ok(&[
        "referee",
        "scenes/frames/break-off.toml",
        &s(&p("s1.toml")),
        &s(&p("s2.toml")),
        "--json",
        &s(&p("all.json")),
        "--frame-out",
        &s(&p("all.toml")),
        "--record",
        &s(&p("frame.rrd")),
    ]);
    assert_eq!(
        out.lines().filter(|l| l.starts_with("stroke ")).count(),
        3,
        "{out}"
    );
    assert_eq!(json(&p("all.json")), r3);
    assert_eq!(std::fs::read_to_string(p("all.toml")).unwrap(), f3);

    let d = common::decode_recording(&std::fs::read(p("frame.rrd")).unwrap());
    let labels = rerun::Points3D::descriptor_labels().component;
    let board = common::rows_of::<rerun::components::Text>(&d, "frame/scoreboard", labels);
    // Before and after each stroke.
    assert_eq!(board.len(), 6, "{board:?}");
    let text: Vec<&str> = board.iter().map(|(_, v)| v[0].as_str()).collect();
    assert!(
        text[0].contains("player 0 to play, on red, ball in hand"),
        "{}",
        text[0]
    );
    assert!(text[2].contains("player 1 to play, on red"), "{}", text[2]);
    assert!(
        text[5].contains("player 0: 1   player 1: 0") && text[5].contains("on colour"),
        "{}",
        text[5]
    );
    // One timeline: each stroke starts after the one before has ended.
    assert!(board.windows(2).all(|w| w[0].0 < w[1].0));
    let calls = common::rows_of::<rerun::components::Text>(
        &d,
        "events/frame",
        rerun::TextLog::descriptor_text().component,
    );
    assert_eq!(calls.len(), 6);
    assert!(
        calls[5].1[0]
            .as_str()
            .contains("stroke 3: legal, 1 point(s); potted red15")
    );
    // Every ball of the first frame is drawn, red15 among them.
    assert!(d.contains_key("balls/red15"));
    let pots = common::rows_of::<rerun::components::Text>(
        &d,
        "events/log",
        rerun::TextLog::descriptor_text().component,
    );
    let pot = pots
        .iter()
        .find(|(_, e)| e[0].as_str().starts_with("ball_pocket: red15"))
        .unwrap();
    assert!(pot.0 > board[4].0, "potted in the third stroke");

    // A frame that does not follow from the stroke before is refused, naming the key.
    let text = std::fs::read_to_string(p("s2.toml"))
        .unwrap()
        .replace("scores = [0, 0]", "scores = [0, 4]");
    std::fs::write(p("bad2.toml"), text).unwrap();
    let o = snooker(&[
        "referee",
        "scenes/frames/break-off.toml",
        &s(&p("s1.toml")),
        &s(&p("bad2.toml")),
    ]);
    assert_eq!(o.status.code(), Some(2));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(
        err.contains("key `frame.scores`") && err.contains("does not follow"),
        "{err}"
    );
}

#[test]
fn after_a_foul_a_sequence_takes_the_offender_playing_again_put_back_or_a_free_ball_declined() {
    // WPBSA Section 3 Rule 3(b) and Rule 13 (play again), Rule 14 (put back after a miss),
    // Rule 12 (a free ball may be declined, and is void when the offender plays again).
    let dir = temp_dir("referee-again");
    let p = |n: &str| dir.join(n);
    let s = |p: &PathBuf| p.to_str().unwrap().to_string();
    let first = format!("{FRAMES}/free_ball_awarded.toml");
    ok(&["referee", &first, "--frame-out", &s(&p("n1.toml"))]);
    let n1 = std::fs::read_to_string(p("n1.toml")).unwrap();
    assert!(
        n1.contains("to_play = 1") && n1.contains("free_ball = true"),
        "{n1}"
    );
    let cue = "[cue]\nball = \"cue\"\nspeed = 1.0\naim = 1.5707963267948966\n";
    let write = |name: &str, text: String| {
        std::fs::write(p(name), text + cue).unwrap();
        s(&p(name))
    };
    let declined = write(
        "declined.toml",
        n1.replace("free_ball = true", "free_ball = false"),
    );
    let again = write(
        "again.toml",
        n1.replace("to_play = 1", "to_play = 0")
            .replace("free_ball = true", "free_ball = false"),
    );
    for next in [&declined, &again] {
        let out = ok(&["referee", &first, next]);
        assert_eq!(out.lines().filter(|l| l.starts_with("stroke ")).count(), 2);
    }
    let out = ok(&["referee", &first, &again]);
    assert!(
        out.contains("stroke 2 (") && out.contains("player 0 on pink"),
        "{out}"
    );
    // After a miss, the balls put back: the frame before with the foul's points.
    let text = std::fs::read_to_string(&first).unwrap();
    assert!(text.contains("scores = [30, 30]"));
    std::fs::write(
        p("back.toml"),
        text.replace("scores = [30, 30]", "scores = [30, 36]"),
    )
    .unwrap();
    let out = ok(&["referee", &first, &s(&p("back.toml"))]);
    assert!(
        out.contains("stroke 2 (") && out.contains("player 0 on pink"),
        "{out}"
    );
    // The offender playing again has no free ball.
    let with_free = write(
        "again_free.toml",
        n1.replace("to_play = 1", "to_play = 0")
            .replace("on = \"pink\"", "on = \"pink\"\nnominated = \"black\""),
    );
    let o = snooker(&["referee", &first, &with_free]);
    assert_eq!(o.status.code(), Some(2));
    // Named as the play-again it is, the free ball kept, not by the player (the message was
    // "frame.to_play: to_play is 0, the stroke left 1", against the frame the stroke left).
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("key `frame.free_ball`"), "{err}");
    // No play again after a legal stroke: the table goes to the other player.
    let miss = format!("{FRAMES}/safety_miss.toml");
    ok(&["referee", &miss, "--frame-out", &s(&p("m1.toml"))]);
    let m1 = std::fs::read_to_string(p("m1.toml")).unwrap();
    assert!(m1.contains("to_play = 1"), "{m1}");
    let stay = write("stay.toml", m1.replace("to_play = 1", "to_play = 0"));
    let o = snooker(&["referee", &miss, &stay]);
    assert_eq!(o.status.code(), Some(2));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("key `frame.to_play`"), "{err}");
}

#[test]
fn a_stroke_that_ends_the_frame_writes_no_next_frame() {
    let dir = temp_dir("referee-over");
    let (out, next) = (dir.join("r.json"), dir.join("next.toml"));
    let o = snooker(&[
        "referee",
        &format!("{FRAMES}/last_black.toml"),
        "--json",
        out.to_str().unwrap(),
        "--frame-out",
        next.to_str().unwrap(),
    ]);
    assert!(o.status.success());
    assert!(!next.exists());
    assert!(String::from_utf8_lossy(&o.stderr).contains("the frame is over"));
    let r = json(&out);
    assert_eq!(
        (&r["frame_over"], &r["winner"], &r["next"]),
        (&Value::Bool(true), &Value::from(0), &Value::Null)
    );
}

#[test]
fn simulate_runs_a_frame_file_as_its_scene() {
    let frame: Value = serde_json::from_str(&ok(&[
        "simulate",
        "scenes/frames/break-off.toml",
        "--quiet",
        "--json",
        "-",
    ]))
    .unwrap();
    let scene: Value = serde_json::from_str(&ok(&[
        "simulate",
        "scenes/break-off.toml",
        "--quiet",
        "--json",
        "-",
    ]))
    .unwrap();
    assert_eq!(frame["final"], scene["final"]);
    assert_eq!(frame["events"], scene["events"]);
}

const COLOURS: &str = "[[balls]]\nid = \"yellow\"\npos = [0.737, 0.597]\n[[balls]]\nid = \"green\"\npos = [0.737, 1.181]\n\
[[balls]]\nid = \"brown\"\npos = [0.737, 0.889]\n[[balls]]\nid = \"blue\"\npos = [1.7845, 0.889]\n\
[[balls]]\nid = \"pink\"\npos = [2.67675, 0.889]\n[[balls]]\nid = \"black\"\npos = [3.245, 0.889]\n";

#[test]
fn bad_frames_exit_2_naming_the_key_and_write_nothing() {
    let dir = temp_dir("referee-bad");
    let cue = "[cue]\nball = \"cue\"\nspeed = 1.0\naim = 0.0\n";
    let red = "[[balls]]\nid = \"red1\"\npos = [2.0, 0.4]\n";
    let cue_at = |x: f64, y: f64| format!("[[balls]]\nid = \"cue\"\npos = [{x}, {y}]\n");
    let cases = [
        (
            "colour-no-nomination",
            format!(
                "{cue}[frame]\non = \"colour\"\n{COLOURS}{red}{}",
                cue_at(1.2, 0.4)
            ),
            "frame.nominated",
        ),
        (
            "red-without-reds",
            format!("{cue}[frame]\non = \"red\"\n{COLOURS}{}", cue_at(1.2, 0.4)),
            "frame.on",
        ),
        (
            "scores",
            format!(
                "{cue}[frame]\non = \"red\"\nscores = [3, -1]\n{COLOURS}{red}{}",
                cue_at(1.2, 0.4)
            ),
            "frame.scores",
        ),
        (
            "scores-three",
            format!(
                "{cue}[frame]\non = \"red\"\nscores = [3, 1, 0]\n{COLOURS}{red}{}",
                cue_at(1.2, 0.4)
            ),
            "frame.scores",
        ),
        (
            "to-play",
            format!(
                "{cue}[frame]\non = \"red\"\nto_play = 2\n{COLOURS}{red}{}",
                cue_at(1.2, 0.4)
            ),
            "frame.to_play",
        ),
        (
            "outside-d",
            format!(
                "{cue}[frame]\non = \"red\"\nball_in_hand = true\n{COLOURS}{red}{}",
                cue_at(1.2, 0.4)
            ),
            "balls[7].pos",
        ),
        (
            "touching",
            format!(
                "{cue}[frame]\non = \"red\"\nball_in_hand = true\n{COLOURS}{red}{}",
                cue_at(0.737 - 0.0524, 0.889)
            ),
            "balls[7].pos",
        ),
        (
            "no-strike",
            format!("[frame]\non = \"red\"\n{COLOURS}{red}{}", cue_at(1.2, 0.4)),
            "cue",
        ),
        (
            "no-frame",
            format!("{cue}{COLOURS}{red}{}", cue_at(1.2, 0.4)),
            "frame",
        ),
    ];
    for (name, text, key) in cases {
        let file = dir.join(format!("{name}.toml"));
        std::fs::write(&file, text).unwrap();
        let outs = [
            dir.join(format!("{name}.json")),
            dir.join(format!("{name}-next.toml")),
            dir.join(format!("{name}.rrd")),
        ];
        let o = snooker(&[
            "referee",
            file.to_str().unwrap(),
            "--json",
            outs[0].to_str().unwrap(),
            "--frame-out",
            outs[1].to_str().unwrap(),
            "--record",
            outs[2].to_str().unwrap(),
        ]);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{name}: {err}");
        assert!(err.contains(&format!("key `{key}`")), "{name}: {err}");
        assert_eq!(err.lines().count(), 1, "{name}: one message: {err}");
        assert!(o.stdout.is_empty(), "{name}");
        for out in &outs {
            assert!(!out.exists(), "{name}: {} written", out.display());
        }
    }
}

#[test]
fn an_output_that_is_an_input_another_output_or_a_dash_is_refused() {
    // `--frame-out` onto the frame played replaced it (its [cue] lost); `--json` and
    // `--frame-out` on one file left TOML in it; `--frame-out -` made a file named `-`. Each
    // exited 0.
    let dir = temp_dir("referee-outputs");
    let frame = dir.join("f.toml");
    std::fs::copy(Path::new(FRAMES).join("pot_red.toml"), &frame).unwrap();
    let before = std::fs::read(&frame).unwrap();
    let f = frame.to_str().unwrap();
    let o = dir.join("o.json");
    let o = o.to_str().unwrap();
    for (args, says) in [
        (vec!["referee", f, "--frame-out", f], "is an input"),
        (
            vec!["referee", f, "--json", o, "--frame-out", o],
            "is also --json's file",
        ),
        (
            vec!["referee", f, "--frame-out", "-"],
            "standard output only for --json",
        ),
        (vec!["simulate", f, "--record", f], "is an input"),
        (
            vec!["play", f, "--log", o, "--json", o, "--effort", "10"],
            "is also --json's",
        ),
    ] {
        let out = snooker(&args);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
        assert!(err.contains(says), "{args:?}: {err}");
        assert_eq!(err.trim_end().lines().count(), 1, "{err}");
    }
    assert_eq!(std::fs::read(&frame).unwrap(), before);
    assert!(!Path::new(o).exists() && !Path::new("-").exists());
}

#[test]
fn the_recordings_call_of_a_stroke_names_the_colours_put_back() {
    // A tie on the last black: the scoreboard said the black was respotted for the
    // re-spotted black game, the stroke's line in `events/frame` did not.
    let dir = temp_dir("referee-respot-call");
    let rrd = dir.join("t.rrd");
    let tied = format!("{FRAMES}/tied_frame.toml");
    ok(&["referee", &tied, "--record", rrd.to_str().unwrap(), "-q"]);
    let d = common::decode_recording(&std::fs::read(&rrd).unwrap());
    let calls = common::rows_of::<rerun::components::Text>(
        &d,
        "events/frame",
        rerun::TextLog::descriptor_text().component,
    );
    let last = calls.last().unwrap().1[0].as_str();
    assert!(last.contains("potted black; respotted black"), "{last}");
}

#[test]
fn a_jump_shot_is_named_and_its_bounces_are_listed() {
    // formats.md, extended: a `[params] e_bed` frame whose steep strike jumps over a red gives
    // the foul `jump_shot`; each bounce is a `landing` whose `after` is in the air, followed
    // at the same `t` by the ball's `lift_off`.
    let dir = temp_dir("referee-jump");
    let out = dir.join("r.json");
    let frame = format!("{FRAMES}/jump_shot.toml");
    ok(&["referee", &frame, "--json", out.to_str().unwrap()]);
    let r = json(&out);
    assert_eq!(r["legal"], false);
    assert_eq!(r["foul"]["reason"], "jump_shot");
    assert_eq!(r["foul"]["reasons"], serde_json::json!(["jump_shot"]));
    assert_eq!(r["foul"]["points"], 4);
    assert_eq!(r["first_hit"], "red2");
    let events = r["shot"]["events"].as_array().unwrap();
    let bounces: Vec<usize> = (0..events.len())
        .filter(|&k| {
            events[k]["kind"] == "landing" && events[k]["after"]["cue"]["motion"] == "airborne"
        })
        .collect();
    assert!(bounces.len() >= 2, "{events:?}");
    for k in bounces {
        assert_eq!(events[k + 1]["kind"], "lift_off");
        assert_eq!(events[k + 1]["t"], events[k]["t"]);
        assert_eq!(events[k + 1]["balls"], serde_json::json!(["cue"]));
    }
    assert_eq!(r["shot"]["params"]["e_bed"], 0.5);
    assert_eq!(r["shot"]["strike"]["after"]["motion"], "airborne");
}
