//! `snooker play`: every logged stroke replays exactly through `snooker referee` (its frame
//! with `executed` as `[cue]` gives the logged verdict, and the strokes chain: each frame is
//! the one the stroke before left, but for the player's choices); the same seed and effort
//! give the same log on one thread and on two; a frame against the greedy baseline; the
//! recording read back against the log (scores, ball on, targets, the balls as each stroke
//! starts); bad input (exit 2, one message, nothing written).

mod common;

use common::{snooker, temp_dir};
use serde_json::Value;
use std::path::Path;

const OPEN: &str = "scenes/frames/open-table.toml";

fn lines(path: &Path) -> Vec<Value> {
    std::fs::read_to_string(path)
        .unwrap()
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect()
}

/// The log's line as a frame file to referee: its frame with `executed` as `[cue]`.
fn frame_with_strike(line: &Value) -> String {
    let e = &line["executed"];
    let num = |v: &Value| serde_json::to_string(v).unwrap();
    format!(
        "{}[cue]\nball = {}\nspeed = {}\naim = {}\noffset = [{}, {}]\nelevation = {}\n",
        line["frame"].as_str().unwrap(),
        num(&e["ball"]),
        num(&e["speed"]),
        num(&e["aim"]),
        num(&e["offset"][0]),
        num(&e["offset"][1]),
        num(&e["elevation"])
    )
}

/// `via` names what a line goes by (formats.md, "Play log"): nothing for a direct pot, a
/// double's cushions, the one ball of a plant (its `ball`, struck first) or a kiss, and for a
/// safety nothing or an escape's one or two cushions (the default table's noses).
fn check_via(k: usize, line: &Value) {
    let table = snooker_engine::Table::snooker(&snooker_engine::SnookerDims::default());
    let noses: Vec<&str> = table
        .cushions
        .iter()
        .map(|c| c.name.as_str())
        .filter(|n| !n.contains("facing"))
        .collect();
    let alternatives = line["plan"]["alternatives"].as_array().unwrap();
    for p in std::iter::once(&line["plan"]).chain(alternatives) {
        let via = p["via"].as_array().unwrap();
        let cushions = via.iter().all(|c| noses.contains(&c.as_str().unwrap()));
        match p["kind"].as_str().unwrap() {
            "direct" => assert!(via.is_empty(), "line {k}: {p}"),
            "safety" => assert!(via.len() <= 2 && cushions, "line {k}: {p}"),
            "double" => assert!(
                !via.is_empty() && cushions && p["ball"] == p["pot"],
                "line {k}: {p}"
            ),
            "plant" => assert!(via.len() == 1 && p["ball"] == via[0], "line {k}: {p}"),
            _ => assert!(via.len() == 1 && p["ball"] == p["pot"], "line {k}: {p}"),
        }
    }
}

/// One stroke, searched cheaply on one thread.
const ONE_QUICK_STROKE: [&str; 6] = ["--max-strokes", "1", "--effort", "50", "--threads", "1"];

fn play(dir: &Path, extra: &[&str], log: &str) -> std::process::Output {
    play_frame(OPEN, dir, extra, log)
}

fn play_frame(frame: &str, dir: &Path, extra: &[&str], log: &str) -> std::process::Output {
    let log = dir.join(log);
    let mut args = vec!["play", frame, "--log", log.to_str().unwrap(), "--quiet"];
    args.extend_from_slice(extra);
    snooker(&args)
}

#[test]
fn every_logged_stroke_replays_through_the_referee() {
    let dir = temp_dir("play-replay");
    // A frame against the greedy baseline, a few strokes: pots, misses and both players.
    let o = play(
        &dir,
        &[
            "--frame",
            "--opponent",
            "greedy",
            "--seed",
            "5",
            "--effort",
            "300",
            "--max-strokes",
            "8",
        ],
        "log.jsonl",
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let log = lines(&dir.join("log.jsonl"));
    assert!(log.len() >= 2, "{} strokes", log.len());
    let contract = [
        "stroke",
        "player",
        "frame",
        "nominated",
        "intended",
        "executed",
        "plan",
        "referee",
        "decision_time",
    ];
    let mut files = Vec::new();
    for (k, line) in log.iter().enumerate() {
        let keys: Vec<&String> = line.as_object().unwrap().keys().collect();
        assert_eq!(&keys[..contract.len()], contract, "line {k}");
        let plan: Vec<&String> = line["plan"].as_object().unwrap().keys().collect();
        assert_eq!(
            &plan[..5],
            ["pot", "pocket", "kind", "pot_probability", "cue_to"],
            "line {k}"
        );
        check_via(k, line);
        assert!(line["referee"].get("shot").is_none());
        assert_eq!(line["stroke"].as_u64(), Some(k as u64 + 1));
        let file = dir.join(format!("stroke{}.toml", k + 1));
        std::fs::write(&file, frame_with_strike(line)).unwrap();
        let out = dir.join(format!("referee{}.json", k + 1));
        let o = snooker(&[
            "referee",
            file.to_str().unwrap(),
            "--json",
            out.to_str().unwrap(),
            "--quiet",
        ]);
        assert!(
            o.status.success(),
            "line {k}: {}",
            String::from_utf8_lossy(&o.stderr)
        );
        let mut verdict: Value =
            serde_json::from_str(&std::fs::read_to_string(&out).unwrap()).unwrap();
        verdict.as_object_mut().unwrap().remove("shot");
        // Floats compared exactly: the same JSON text.
        assert_eq!(verdict, line["referee"], "line {k}");
        files.push(file);
    }
    // The strokes chain: the referee checks each frame is the one the stroke before left,
    // but for the cue ball placed in hand and the nomination.
    let mut args = vec!["referee", "--quiet"];
    args.extend(files.iter().map(|f| f.to_str().unwrap()));
    let o = snooker(&args);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
}

#[test]
fn the_same_seed_and_effort_give_the_same_log_on_one_thread_and_two() {
    let dir = temp_dir("play-threads");
    let common = ["--seed", "11", "--effort", "300", "--max-strokes", "6"];
    let mut one = common.to_vec();
    one.extend(["--threads", "1"]);
    let mut two = common.to_vec();
    two.extend(["--threads", "2"]);
    assert!(play(&dir, &one, "one.jsonl").status.success());
    assert!(play(&dir, &two, "two.jsonl").status.success());
    let strip = |mut v: Vec<Value>| {
        // The wall time of a decision is the one field that may differ.
        for l in &mut v {
            l.as_object_mut().unwrap().remove("decision_time");
        }
        v
    };
    let (a, b) = (
        strip(lines(&dir.join("one.jsonl"))),
        strip(lines(&dir.join("two.jsonl"))),
    );
    assert!(!a.is_empty());
    assert_eq!(a, b);
}

#[test]
fn bad_input_exits_2_with_one_message_and_writes_nothing() {
    let dir = temp_dir("play-bad");
    let log = dir.join("log.jsonl");
    for (extra, says) in [
        (vec!["--noise", "loud"], "--noise"),
        (vec!["--noise", "aim=0.002,speed=0.02,offset=0.001"], "m/s"),
        (vec!["--effort", "0"], "--effort"),
        // A safety's samples asked for more memory than exists (a panic).
        (vec!["--effort", "18446744073709551615"], "--effort"),
        (vec!["--opponent", "shark"], "--opponent"),
        (vec!["--visit", "--frame"], "--frame"),
        // rayon starts every thread asked for: 100,000 took minutes before this bound.
        (vec!["--threads", "100000"], "at most 1024"),
        (vec!["--threads", "0"], "at least one"),
    ] {
        let mut args = vec!["play", OPEN, "--log", log.to_str().unwrap()];
        args.extend(extra);
        let o = snooker(&args);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {err}");
        assert_eq!(err.trim_end().lines().count(), 1, "{args:?}: {err}");
        assert!(err.contains(says), "{args:?}: {err}");
        assert!(!log.exists());
    }
    // A frame file with a bad [frame] table names its key.
    let bad = dir.join("bad.toml");
    std::fs::write(
        &bad,
        std::fs::read_to_string(OPEN)
            .unwrap()
            .replace("on = \"red\"", "on = \"purple\""),
    )
    .unwrap();
    let o = snooker(&[
        "play",
        bad.to_str().unwrap(),
        "--log",
        log.to_str().unwrap(),
    ]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.contains("frame.on"), "{err}");
    assert!(!log.exists());
}

/// `play` ignores a frame file's `[cue]` (its help says so): a frame on a colour with no
/// colour nominated and a `[cue]` is a position to choose a stroke from, not a stroke to
/// judge. Before, it was refused (exit 2 on `frame.nominated`) though the same frame without
/// the `[cue]` played.
#[test]
fn a_frames_cue_is_ignored_not_judged() {
    let dir = temp_dir("play-cue-ignored");
    let frame = dir.join("on-colour.toml");
    let text = std::fs::read_to_string(OPEN)
        .unwrap()
        .replace("on = \"red\"", "on = \"colour\"")
        .replace("ball_in_hand = true", "ball_in_hand = false")
        + "[[balls]]\nid = \"cue\"\npos = [0.5, 0.3]\n[cue]\nball = \"cue\"\nspeed = 1.0\naim = 0.0\n";
    std::fs::write(&frame, &text).unwrap();
    // The referee, which plays the [cue], needs the nomination.
    let o = snooker(&["referee", frame.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("frame.nominated"));
    let o = play_frame(
        frame.to_str().unwrap(),
        &dir,
        &ONE_QUICK_STROKE,
        "log.jsonl",
    );
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(0), "{err}");
    let line = &lines(&dir.join("log.jsonl"))[0];
    assert_ne!(line["nominated"], "", "{line}");
    assert!(line["frame"].as_str().unwrap().contains("on = \"colour\""));
}

/// Any finite noise is played: a side error metres wide (`standard*10000`: 5 m) is pulled in
/// to a strike the tip can make. The offset was pulled in by at most 400 steps of 1 % (to 2 %
/// of it), so an error of more than about 0.7 m stopped the play with exit 1 and a message
/// blaming the frame file's `cue.offset`.
#[test]
fn a_huge_but_finite_noise_is_played() {
    let dir = temp_dir("play-loud");
    let extra = [&["--noise", "standard*10000"][..], &ONE_QUICK_STROKE].concat();
    let o = play(&dir, &extra, "log.jsonl");
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(0), "{err}");
    let log = lines(&dir.join("log.jsonl"));
    assert_eq!(log.len(), 1);
    let offset = &log[0]["executed"]["offset"];
    let miss = offset[0]
        .as_f64()
        .unwrap()
        .hypot(offset[1].as_f64().unwrap());
    assert!(
        miss < 0.0362,
        "the executed offset {offset} reaches the ball (R + tip)"
    );
}

#[test]
fn the_recording_opens_at_the_end_with_the_cue_balls_path_of_every_stroke() {
    use rerun::external::re_log_encoding::DecoderApp;
    use rerun::external::re_sdk_types::blueprint::archetypes::TimePanelBlueprint;
    use rerun::external::re_sdk_types::blueprint::components::PlayState;
    use rerun::log::{Chunk, LogMsg};
    use rerun::{LineStrips3D, Points3D, StoreKind};

    let dir = temp_dir("play-record");
    let rrd = dir.join("visit.rrd");
    let o = play(
        &dir,
        &[
            "--seed",
            "5",
            "--effort",
            "300",
            "--max-strokes",
            "4",
            "--record",
            rrd.to_str().unwrap(),
        ],
        "log.jsonl",
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let log = lines(&dir.join("log.jsonl"));
    let bytes = std::fs::read(&rrd).unwrap();
    let strips_of = LineStrips3D::descriptor_strips().component;
    let labels_of = Points3D::descriptor_labels().component;
    let play_state_of = TimePanelBlueprint::descriptor_play_state().component;
    let timeline = rerun::TimelineName::from(snooker::record::TIMELINE);
    let (mut played, mut board, mut states) = (Vec::new(), Vec::new(), Vec::new());
    for msg in DecoderApp::decode_lazy(bytes.as_slice()) {
        let LogMsg::ArrowMsg(store, arrow) = msg.expect("a valid .rrd stream") else {
            continue;
        };
        let chunk = Chunk::from_arrow_msg(&arrow).unwrap();
        let path = chunk.entity_path().to_string();
        let times: Vec<i64> = chunk
            .timelines()
            .get(&timeline)
            .map_or_else(Vec::new, |t| t.times_raw().to_vec());
        match (store.kind(), path.trim_start_matches('/')) {
            (StoreKind::Recording, "plan/played") => {
                for (t, v) in times
                    .iter()
                    .zip(chunk.iter_component::<rerun::components::LineStrip3D>(strips_of))
                {
                    played.push((*t, v.to_vec()));
                }
            }
            (StoreKind::Recording, "frame/scoreboard") => board.extend(
                times
                    .iter()
                    .zip(chunk.iter_component::<rerun::components::Text>(labels_of))
                    .map(|(t, _)| *t),
            ),
            (StoreKind::Blueprint, p) if p.ends_with("time_panel") => {
                for v in chunk.iter_component::<PlayState>(play_state_of) {
                    states.extend(v.iter().copied());
                }
            }
            _ => {}
        }
    }
    // Opens following the timeline to its end.
    assert_eq!(states, [PlayState::Following]);
    // One row, at the end of the last stroke (the scoreboard's last row), one strip a stroke.
    assert_eq!(played.len(), 1, "{played:?}");
    let (t, strips) = &played[0];
    assert_eq!(Some(t), board.iter().max());
    assert_eq!(strips.len(), log.len());
    assert!(log.len() >= 3, "{} strokes: too few to chain", log.len());
    // Each stroke's path starts where the one before left the cue ball, unless in hand.
    for k in 1..log.len() {
        let in_hand = log[k]["frame"]
            .as_str()
            .unwrap()
            .contains("ball_in_hand = true");
        let (Some(start), Some(end)) = (strips[k].0.first(), strips[k - 1].0.last()) else {
            panic!("stroke {k}: an empty path");
        };
        if !in_hand {
            assert_eq!(start, end, "stroke {}", k + 1);
        }
    }
    check_strokes_in_recording(&bytes, &log);
}

/// The latest row at or before `t` (what the viewer shows at `t`).
fn at<C: Clone>(rows: &[(i64, Vec<C>)], t: i64) -> Option<&Vec<C>> {
    rows.iter().rev().find(|r| r.0 <= t).map(|r| &r.1)
}

/// Each stroke of a play log as its recording shows it: at the stroke's start (where its
/// planned target is logged) the scoreboard has the log's scores, player and ball on, every
/// ball of the stroke's frame is shown where the frame has it (a respotted colour back on its
/// spot, the cue ball where it was placed), the cue ball is sampled at the very instant it is
/// struck, the target is the plan's and the path meant is the noise-free strike's, through each
/// of its cue-ball events; at its end the scoreboard has the referee's scores.
fn check_strokes_in_recording(bytes: &[u8], log: &[Value]) {
    use rerun::components::{HalfSize3D, Position3D, Text, Translation3D};
    let d = common::decode_recording(bytes);
    let positions = rerun::Points3D::descriptor_positions().component;
    let labels = rerun::Points3D::descriptor_labels().component;
    let translation = rerun::Transform3D::descriptor_translation().component;
    let half_sizes = rerun::Ellipsoids3D::descriptor_half_sizes().component;
    let targets = common::rows_of::<Position3D>(&d, "plan/target", positions);
    let board = common::rows_of::<Text>(&d, "frame/scoreboard", labels);
    let strips = rerun::LineStrips3D::descriptor_strips().component;
    let intended = common::rows_of::<rerun::components::LineStrip3D>(&d, "plan/intended", strips);
    assert_eq!(targets.len(), log.len());
    let close = |a: [f32; 3], b: [f64; 3]| {
        a.iter()
            .zip(b)
            .all(|(a, b)| (f64::from(*a) - b).abs() <= 4.0 * f64::from(f32::EPSILON))
    };
    for (k, (line, (t0, target))) in log.iter().zip(&targets).enumerate() {
        let n = k + 1;
        let file = snooker_rules::parse(line["frame"].as_str().unwrap(), "log").unwrap();
        let frame = &file.frame;
        let state = frame.state();
        let r = frame.params().ball_radius;
        let to = &line["plan"]["cue_to"];
        let to = [to[0].as_f64().unwrap(), to[1].as_f64().unwrap(), r];
        assert!(close(target[0].0.0, to), "stroke {n}: target {target:?}");
        let shown = at(&board, *t0).unwrap()[0].as_str().to_string();
        let want = format!(
            "player 0: {}   player 1: {}   | player {} to play, on {}",
            state.scores[0], state.scores[1], state.to_play, state.on
        );
        assert!(shown.starts_with(&want), "stroke {n}: {shown} / {want}");
        for ball in frame.balls() {
            let id = &ball.id;
            let pos = common::rows_of::<Translation3D>(&d, &format!("balls/{id}"), translation);
            let body = common::rows_of::<HalfSize3D>(&d, &format!("balls/{id}/body"), half_sizes);
            let p = at(&pos, *t0).unwrap()[0].0.0;
            let at_start = ball.state.pos;
            assert!(
                close(p, [at_start.x, at_start.y, at_start.z]),
                "stroke {n}: {id} shown at {p:?} as it starts, the frame has it at {at_start:?}"
            );
            assert!(
                !at(&body, *t0).unwrap().is_empty(),
                "stroke {n}: {id} is on the table but not shown as it starts"
            );
            if frame
                .cue_index()
                .is_some_and(|c| frame.balls()[c].id == *id)
            {
                assert!(
                    pos.iter().any(|r| r.0 == *t0),
                    "stroke {n}: the cue ball is not sampled as it is struck"
                );
            }
        }
        // The path meant: the noise-free strike's cue-ball path, through every place where the
        // cue ball's way turns (its events), ending at the planned target.
        let e = &line["intended"];
        let num = |v: &Value| v.as_f64().unwrap();
        let meant = snooker_engine::Cue {
            speed: num(&e["speed"]),
            aim: num(&e["aim"]),
            offset: [num(&e["offset"][0]), num(&e["offset"][1])],
            elevation: num(&e["elevation"]),
        };
        let shot =
            snooker_engine::simulate(&frame.setup(&meant).unwrap(), frame.options()).unwrap();
        let cue = frame.cue_index().unwrap();
        let intended = at(&intended, *t0).unwrap();
        let path = &intended[0].0;
        assert!(close(path.last().unwrap().0, to), "stroke {n}: {path:?}");
        for ev in shot.events.iter().filter(|ev| ev.balls.contains(&cue)) {
            let p = shot.tracks[cue].state_at(ev.t, &shot.params);
            if p.motion.in_play() {
                assert!(
                    path.iter().any(|q| close(q.0, [p.pos.x, p.pos.y, p.pos.z])),
                    "stroke {n}: the path meant misses the cue ball's {} at {:?} (nearest point {:?})",
                    ev.kind.name(),
                    p.pos,
                    path.iter().min_by(|a, b| {
                        let d = |q: &[f32; 3]| {
                            (f64::from(q[0]) - p.pos.x).hypot(f64::from(q[1]) - p.pos.y)
                        };
                        d(&a.0).total_cmp(&d(&b.0))
                    })
                );
            }
        }
        let end = board.iter().find(|r| r.0 > *t0).unwrap();
        let scores = &line["referee"]["scores"];
        let want = format!("player 0: {}   player 1: {}", scores[0], scores[1]);
        assert!(
            end.1[0].as_str().starts_with(&want),
            "stroke {n}: {:?}",
            end.1
        );
    }
}

/// Balls over the D covering every point of the player's 5 cm grid, a clear place left
/// between them: both agents play from it. Before, this valid frame exited 1 with "no strike
/// can be played from this frame".
#[test]
fn a_d_whose_grid_is_covered_still_gives_the_cue_ball_in_hand_a_place() {
    let dir = temp_dir("play-d-covered");
    let mut balls = String::new();
    let mut ball = |id: &str, x: f64, y: f64| {
        balls += &format!("[[balls]]\nid = \"{id}\"\npos = [{x}, {y}]\n");
    };
    ball("black", 3.245, 0.889);
    ball("pink", 2.67675, 0.889);
    ball("blue", 1.7845, 0.889);
    // A lattice over the D, 5 cm steps along x, 25 cm across, shifted every row.
    let mut red = 0;
    for (row, x) in [0.787, 0.737, 0.687, 0.637, 0.587, 0.537]
        .into_iter()
        .enumerate()
    {
        let ys: &[f64] = match row % 5 {
            0 => &[0.789, 1.039],
            1 => &[0.639, 0.889, 1.139],
            2 => &[0.739, 0.989],
            3 => &[0.589, 0.839, 1.089],
            _ => &[0.689, 0.939, 1.189],
        };
        for &y in ys {
            red += 1;
            ball(&format!("red{red}"), x, y);
        }
    }
    ball("yellow", 0.487, 0.889);
    ball("green", 0.437, 0.739);
    ball("brown", 0.437, 0.989);
    // Player 1, the opponent named, plays first in the second frame.
    for (to_play, opponent) in [(0, "player"), (1, "greedy")] {
        let frame = dir.join(format!("{opponent}.toml"));
        let head = format!("[frame]\non = \"red\"\nball_in_hand = true\nto_play = {to_play}\n");
        std::fs::write(&frame, head + &balls).unwrap();
        let log = dir.join(format!("{opponent}.jsonl"));
        let o = snooker(&[
            "play",
            frame.to_str().unwrap(),
            "--frame",
            "--opponent",
            opponent,
            "--max-strokes",
            "1",
            "--effort",
            "50",
            "--quiet",
            "--log",
            log.to_str().unwrap(),
        ]);
        assert!(
            o.status.success(),
            "{opponent}: {}",
            String::from_utf8_lossy(&o.stderr)
        );
        assert_eq!(lines(&log).len(), 1, "{opponent}");
    }
}

#[test]
fn a_snookered_player_escapes_and_its_line_and_log_name_the_cushions() {
    // The rules' frame: the cue ball behind the black, the pink on beyond it.
    let dir = temp_dir("play-escape");
    let log = dir.join("escape.jsonl");
    let o = snooker(&[
        "play",
        "rules/tests/frames/free_ball_awarded.toml",
        "--effort",
        "300",
        "--seed",
        "5",
        "--max-strokes",
        "1",
        "--log",
        log.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let out = String::from_utf8_lossy(&o.stdout);
    let first = lines(&log).remove(0);
    let via: Vec<&str> = first["plan"]["via"]
        .as_array()
        .unwrap()
        .iter()
        .map(|v| v.as_str().unwrap())
        .collect();
    check_via(0, &first);
    assert_eq!(first["plan"]["kind"], "safety");
    assert!(!via.is_empty(), "no cushion in the log: {}", first["plan"]);
    assert!(
        out.contains(&format!("safety off pink via {}", via.join(", "))),
        "{out}"
    );
    // The old player drove into the black (first_hit_not_on); this seed's executed escape
    // meets the pink.
    assert_eq!(
        first["referee"]["first_hit"], "pink",
        "{}",
        first["referee"]
    );
}
