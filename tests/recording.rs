//! Rerun recordings, read back with Rerun's own decoder (the crates of the version that wrote
//! them): entity paths, samples per ball, positions and speeds against the engine at the
//! logged times, the pre/post pairs at events, orientations, events, the blueprint, and the
//! CLI's `--record` errors.

use rerun::external::re_log_encoding::DecoderApp;
use rerun::log::{Chunk, LogMsg};
use rerun::{Component, StoreKind, Transform3D};
use snooker::record::{self, RecordOptions};
use snooker_engine::{Motion, Shot, simulate};
use snooker_scene::{self as scene, Scene};
use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};
use std::process::Command;

/// Everything a file holds, split by store.
struct Decoded {
    /// Recording chunks by entity path (without the leading `/`), in file order.
    chunks: BTreeMap<String, Vec<Chunk>>,
    /// Number of blueprint chunks.
    blueprint_chunks: usize,
    /// Whether the blueprint is marked as the default.
    blueprint_default: bool,
}

fn decode(bytes: &[u8]) -> Decoded {
    let mut out = Decoded {
        chunks: BTreeMap::new(),
        blueprint_chunks: 0,
        blueprint_default: false,
    };
    for msg in DecoderApp::decode_lazy(bytes) {
        match msg.expect("a valid .rrd stream") {
            LogMsg::ArrowMsg(store, arrow) => {
                let chunk = Chunk::from_arrow_msg(&arrow).expect("a valid chunk");
                match store.kind() {
                    StoreKind::Recording => out
                        .chunks
                        .entry(
                            chunk
                                .entity_path()
                                .to_string()
                                .trim_start_matches('/')
                                .into(),
                        )
                        .or_default()
                        .push(chunk),
                    StoreKind::Blueprint => out.blueprint_chunks += 1,
                }
            }
            LogMsg::BlueprintActivationCommand(cmd) => out.blueprint_default |= cmd.make_default,
            LogMsg::SetStoreInfo(_) => {}
        }
    }
    out
}

/// One component's rows at an entity, in logging order: (time in ns, values).
fn rows<C: Component + Clone>(
    d: &Decoded,
    entity: &str,
    component: rerun::ComponentIdentifier,
) -> Vec<(i64, Vec<C>)> {
    let mut out: Vec<(rerun::log::RowId, i64, Vec<C>)> = Vec::new();
    for chunk in d.chunks.get(entity).into_iter().flatten() {
        if chunk.is_static() || chunk.components().get_array(component).is_none() {
            continue;
        }
        let times = chunk
            .timelines()
            .get(&rerun::TimelineName::from(record::TIMELINE))
            .expect("the sim_time timeline")
            .times_raw()
            .to_vec();
        for ((row, t), v) in chunk
            .row_ids()
            .zip(times)
            .zip(chunk.iter_component::<C>(component))
        {
            out.push((row, t, v.to_vec()));
        }
    }
    // Rows are ordered by their ids, which follow the logging order.
    out.sort_by_key(|r| r.0);
    out.into_iter().map(|(_, t, v)| (t, v)).collect()
}

/// A scene from its text, and its shot.
fn shot_of(text: &str, file: &str) -> (Scene, Shot) {
    let scene = scene::parse(text, file).unwrap();
    let shot = simulate(&scene.setup, &scene.options).unwrap();
    (scene, shot)
}

/// A cue ball sent at `vel` (no spin) and a red at rest, on the table of kind `table`.
fn cue_and_red(table: &str, cue: [f64; 2], vel: [f64; 2], red: [f64; 2]) -> (Scene, Shot) {
    let text = format!(
        "name = \"cue-and-red\"\n[table]\nkind = \"{table}\"\n\
         [[balls]]\nid = \"cue\"\npos = {cue:?}\nvel = [{}, {}, 0.0]\n\
         [[balls]]\nid = \"red\"\npos = {red:?}\n",
        vel[0], vel[1]
    );
    shot_of(&text, "cue-and-red.toml")
}

fn break_off() -> (Scene, Shot) {
    shot_of(scene::DEFAULT_SCENE, scene::DEFAULT_SCENE_FILE)
}

/// The instants a recording must hold, built here from their definition: the grid k/rate up
/// to the end, the end itself, and every distinct event time twice (before, after); a grid
/// point equal to an event time is not repeated. `Some(g)` marks the pair of event group g.
fn expected_instants(shot: &Shot, rate: f64) -> Vec<(f64, Option<(usize, bool)>)> {
    let mut event_times: Vec<f64> = shot.events.iter().map(|e| e.t).collect();
    event_times.dedup();
    let mut grid: BTreeSet<u64> = BTreeSet::new();
    let mut k = 0u64;
    while k as f64 / rate <= shot.duration {
        grid.insert((k as f64 / rate).to_bits());
        k += 1;
    }
    grid.insert(shot.duration.to_bits());
    for t in &event_times {
        grid.remove(&t.to_bits());
    }
    let mut out: Vec<(f64, Option<(usize, bool)>)> =
        grid.iter().map(|&b| (f64::from_bits(b), None)).collect();
    for (g, &t) in event_times.iter().enumerate() {
        out.push((t, Some((g, false))));
        out.push((t, Some((g, true))));
    }
    // Stable: a before stays ahead of its after.
    out.sort_by(|a, b| a.0.total_cmp(&b.0));
    out
}

fn ns(t: f64) -> i64 {
    (t * 1e9).round() as i64
}

/// The state ball `b` must show at each of `instants`: after the instant's events, or before
/// them at the first of a pair.
fn states_at(
    shot: &Shot,
    b: usize,
    instants: &[(f64, Option<(usize, bool)>)],
) -> Vec<snooker_engine::BallState> {
    let tr = &shot.tracks[b];
    instants
        .iter()
        .map(|&(t, side)| {
            let first_event = shot
                .events
                .iter()
                .find(|e| e.t == t && e.balls.contains(&b));
            match (side, first_event) {
                (Some((_, false)), Some(e)) => {
                    let k = e.balls.iter().position(|&x| x == b).unwrap();
                    e.before[k]
                }
                _ => tr.state_at(t, &shot.params),
            }
        })
        .collect()
}

/// The instants a ball gets a row at, from their definition: the first and the last, and
/// both ends of every run of instants with the same state (the viewer shows the latest row,
/// so the state at any instant is the row at or before it).
fn kept(states: &[snooker_engine::BallState]) -> Vec<usize> {
    let n = states.len();
    (0..n)
        .filter(|&i| {
            i == 0 || i + 1 == n || states[i] != states[i - 1] || states[i] != states[i + 1]
        })
        .collect()
}

/// Checks a decoded recording against the engine's shot: every ball sampled at exactly the
/// expected instants where its state changes (both ends of every run of one state),
/// positions to f32 precision and speeds exactly (the pre-event state at the first of a
/// pair, NaN once pocketed), unit orientations that do not jump at events and stay put for a
/// ball that never moves; one log entry per event and a live marker at each.
fn check_against_engine(d: &Decoded, shot: &Shot, rate: f64) {
    let instants = expected_instants(shot, rate);
    let translation = Transform3D::descriptor_translation().component;
    let quaternion = Transform3D::descriptor_quaternion().component;
    let scalars = rerun::Scalars::descriptor_scalars().component;
    let mut worst_pos = 0.0f64;
    let mut rows_total = 0;
    for (b, tr) in shot.tracks.iter().enumerate() {
        let id = &tr.id;
        let states = states_at(shot, b, &instants);
        let keep = kept(&states);
        rows_total += keep.len();
        let pos = rows::<rerun::components::Translation3D>(d, &format!("balls/{id}"), translation);
        assert_eq!(pos.len(), keep.len(), "samples of {id}");
        let speed = rows::<rerun::components::Scalar>(d, &format!("plots/speed/{id}"), scalars);
        assert_eq!(speed.len(), keep.len(), "speed samples of {id}");
        let quat =
            rows::<rerun::components::RotationQuat>(d, &format!("balls/{id}/body"), quaternion);
        assert_eq!(quat.len(), keep.len(), "orientations of {id}");

        for (row, &i) in keep.iter().enumerate() {
            let (t, side) = instants[i];
            let state = states[i];
            assert_eq!(pos[row].0, ns(t), "time of sample {i} of {id}");
            assert_eq!(speed[row].0, ns(t));
            let logged = pos[row].1[0].0.0;
            for (a, e) in logged.iter().zip(state.pos.iter()) {
                // f32 precision: the f64 position rounded once.
                let err = (f64::from(*a) - e).abs();
                worst_pos = worst_pos.max(err);
                assert!(
                    err <= f64::from(f32::EPSILON) * e.abs().max(1e-3),
                    "{id} at t = {t}: logged {logged:?}, engine {:?}",
                    state.pos
                );
            }
            let v = speed[row].1[0].0.0;
            if state.motion == Motion::Pocketed {
                assert!(v.is_nan(), "{id} pocketed at {t} but speed {v}");
            } else {
                assert!(
                    (v - state.vel.norm()).abs() <= 1e-12,
                    "{id} at t = {t}: speed {v}, engine {}",
                    state.vel.norm()
                );
            }
            let q = quat[row].1[0].0.0;
            let norm = q.iter().map(|c| f64::from(*c).powi(2)).sum::<f64>().sqrt();
            assert!((norm - 1.0).abs() < 1e-6, "{id}: |q| = {norm}");
            if let (Some((_, true)), true) = (side, row > 0 && keep[row - 1] + 1 == i) {
                // The orientation does not jump at an event.
                assert_eq!(quat[row].1, quat[row - 1].1, "{id} at event time {t}");
            }
        }
        // Every instant left out shows the state of the row before it.
        for (i, s) in states.iter().enumerate() {
            let row = keep.partition_point(|&k| k <= i) - 1;
            assert_eq!(
                *s, states[keep[row]],
                "{id}: instant {i} left out but changed"
            );
        }
        // A ball that never moves never turns.
        if tr
            .segments
            .iter()
            .all(|s| s.state.motion == Motion::Stationary)
        {
            assert!(quat.iter().all(|(_, q)| q[0].0.0 == [0.0, 0.0, 0.0, 1.0]));
            assert_eq!(keep.len(), 2, "{id} at rest: a row at each end");
        }
    }
    eprintln!(
        "{} instants per ball, {rows_total} rows for {} balls, worst position error {worst_pos:.2e} m",
        instants.len(),
        shot.tracks.len()
    );

    // Events: one log entry each at its exact time, in order, naming its kind.
    let text = rerun::TextLog::descriptor_text().component;
    let log = rows::<rerun::components::Text>(d, "events/log", text);
    assert_eq!(log.len(), shot.events.len());
    for (e, (t, entry)) in shot.events.iter().zip(&log) {
        assert_eq!(*t, ns(e.t));
        assert!(
            entry[0].as_str().starts_with(e.kind.name()),
            "{}",
            entry[0].as_str()
        );
    }
    // A pot's entry names the pocket.
    let pots: Vec<_> = log
        .iter()
        .filter(|(_, e)| e[0].as_str().starts_with("ball_pocket"))
        .collect();
    let n_pots = shot
        .events
        .iter()
        .filter(|e| e.kind.name() == "ball_pocket")
        .count();
    assert_eq!(pots.len(), n_pots);
    assert!(pots.iter().all(|(_, e)| e[0].as_str().contains(" in ")));
    // Markers: live at each event's time.
    let positions = rerun::Points3D::descriptor_positions().component;
    let markers = rows::<rerun::components::Position3D>(d, "events/markers", positions);
    for e in &shot.events {
        let at = markers
            .iter()
            .rev()
            .find(|(t, _)| *t <= ns(e.t))
            .expect("a marker row at or before each event");
        assert!(!at.1.is_empty());
    }
}

#[test]
fn break_off_recording_matches_the_engine() {
    let (scene, shot) = break_off();
    let rate = record::DEFAULT_RATE;
    let bytes = record::encode(&scene, &shot, &RecordOptions::default()).unwrap();
    let d = decode(&bytes);

    // The layout ships with the recording and is the default.
    assert!(d.blueprint_chunks > 0 && d.blueprint_default);

    // Entity paths.
    let mut expect: BTreeSet<String> = [
        "table/cloth",
        "table/cushions",
        "table/rails",
        "table/noses",
        "table/pockets",
        "table/markings",
        "table/spots",
        "events/log",
        "events/markers",
    ]
    .iter()
    .map(|s| s.to_string())
    .collect();
    for tr in &shot.tracks {
        let id = &tr.id;
        for e in [
            format!("balls/{id}"),
            format!("balls/{id}/body"),
            format!("balls/{id}/body/marker"),
            format!("balls/{id}/velocity"),
            format!("balls/{id}/spin"),
            format!("trails/{id}"),
            format!("motion/{id}"),
            format!("plots/speed/{id}"),
            format!("plots/slip/{id}"),
            format!("plots/spin/{id}"),
        ] {
            expect.insert(e);
        }
    }
    let got: BTreeSet<String> = d.chunks.keys().cloned().collect();
    let missing: Vec<_> = expect.difference(&got).collect();
    assert!(missing.is_empty(), "missing entities: {missing:?}");
    assert_eq!(shot.tracks.len(), 22);
    check_against_engine(&d, &shot, rate);
}

/// A recording's content as text: per entity, each chunk's times and component values (but the
/// recording's properties, which hold the wall time it was made).
fn content(d: &Decoded) -> Vec<String> {
    let timeline = rerun::TimelineName::from(record::TIMELINE);
    let mut out = Vec::new();
    for (entity, chunks) in &d.chunks {
        if entity.starts_with("__properties") {
            continue;
        }
        for c in chunks {
            let times = c
                .timelines()
                .get(&timeline)
                .map_or_else(Vec::new, |t| t.times_raw().to_vec());
            let mut columns: Vec<String> = c
                .components()
                .component_descriptors()
                .map(|desc| format!("{desc:?}: {:?}", c.components().get_array(desc.component)))
                .collect();
            columns.sort();
            out.push(format!("{entity} {times:?} {columns:?}"));
        }
    }
    out
}

#[test]
fn the_same_shot_records_the_same_content() {
    let (scene, shot) = break_off();
    let opts = RecordOptions::default();
    let a = decode(&record::encode(&scene, &shot, &opts).unwrap());
    let b = decode(&record::encode(&scene, &shot, &opts).unwrap());
    let (a, b) = (content(&a), content(&b));
    assert!(a.len() > 100);
    assert_eq!(a, b);
}

#[test]
fn the_chunks_do_not_follow_the_wall_clock() {
    // rerun's batcher cut chunks every 200 ms of wall clock by default (or every tick of
    // RERUN_FLUSH_TICK_SECS), so the same shot recorded on a loaded machine came out in other
    // chunks. Recorded twice by the command with a 1 microsecond tick asked for, the content
    // must still be the same (on the old builder it was cut wherever the clock ticked).
    let dir = scratch("cli-record-tick");
    let decoded: Vec<Vec<String>> = ["a.rrd", "b.rrd"]
        .iter()
        .map(|name| {
            let out = dir.join(name);
            let run = Command::new(env!("CARGO_BIN_EXE_snooker"))
                .args(["simulate", "--quiet", "--record", out.to_str().unwrap()])
                .env("RERUN_FLUSH_TICK_SECS", "0.000001")
                .output()
                .unwrap();
            assert!(
                run.status.success(),
                "{}",
                String::from_utf8_lossy(&run.stderr)
            );
            content(&decode(&std::fs::read(&out).unwrap()))
        })
        .collect();
    assert!(decoded[0].len() > 100);
    assert_eq!(decoded[0], decoded[1]);
}

#[test]
fn a_potted_ball_leaves_the_view_and_the_plots() {
    let (scene, shot) = cue_and_red("snooker", [2.9, 1.1], [1.2, 1.22], [1.0, 0.5]);
    let pot = shot
        .events
        .iter()
        .find(|e| e.kind.name() == "ball_pocket")
        .expect("the scene pots the cue ball");
    let rate = 120.0;
    let d = decode(
        &record::encode(
            &scene,
            &shot,
            &RecordOptions {
                rate,
                ..Default::default()
            },
        )
        .unwrap(),
    );
    check_against_engine(&d, &shot, rate);

    // The sphere: one row showing it at the start, one hiding it at the pot.
    let half = rerun::Ellipsoids3D::descriptor_half_sizes().component;
    let body = rows::<rerun::components::HalfSize3D>(&d, "balls/cue/body", half);
    assert_eq!(body.len(), 2);
    assert_eq!((body[0].0, body[0].1.len()), (0, 1));
    assert_eq!((body[1].0, body[1].1.len()), (ns(pot.t), 0));
    // No arrows once it is gone, and a gap in the speed plot.
    let vectors = rerun::Arrows3D::descriptor_vectors().component;
    let arrows = rows::<rerun::components::Vector3D>(&d, "balls/cue/velocity", vectors);
    let gone: Vec<_> = arrows.iter().filter(|(t, _)| *t >= ns(pot.t)).collect();
    assert!(gone.len() >= 2);
    assert!(!gone[0].1.is_empty(), "the pre-pot sample still moves");
    assert!(gone[1..].iter().all(|(_, a)| a.is_empty()));
    let scalars = rerun::Scalars::descriptor_scalars().component;
    let speed = rows::<rerun::components::Scalar>(&d, "plots/speed/cue", scalars);
    assert!(speed.last().unwrap().1[0].0.0.is_nan());
    let text = rerun::TextLog::descriptor_text().component;
    let log = rows::<rerun::components::Text>(&d, "events/log", text);
    let entry = format!(
        "ball_pocket: cue in {}",
        pot.feature.as_deref().unwrap_or("?")
    );
    assert!(log.iter().any(|(_, e)| e[0].as_str() == entry), "{entry}");
}

#[test]
fn cloth_effects_stay_exact() {
    // A tilted bed, nap and slip-dependent friction: laws renewed between events.
    let text = r#"
name = "cloth"
[params]
slope_x = 0.002
nap_drift = 0.01
mu_slide_low = 0.14
slide_speed_scale = 0.2
[[balls]]
id = "cue"
pos = [0.5, 0.4]
vel = [2.0, 0.3, 0.0]
spin = [0.0, -30.0, 20.0]
[[balls]]
id = "red"
pos = [1.5, 0.55]
"#;
    let (scene, shot) = shot_of(text, "cloth.toml");
    let d = decode(&record::encode(&scene, &shot, &RecordOptions::default()).unwrap());
    check_against_engine(&d, &shot, record::DEFAULT_RATE);
}

#[test]
fn table_geometry_is_static_and_complete() {
    let (scene, shot) = break_off();
    let bytes = record::encode(
        &scene,
        &shot,
        &RecordOptions {
            rate: 30.0,
            ..Default::default()
        },
    )
    .unwrap();
    let d = decode(&bytes);
    let table = &scene.setup.table;
    for entity in [
        "table/cloth",
        "table/noses",
        "table/pockets",
        "table/markings",
    ] {
        assert!(
            d.chunks[entity].iter().all(Chunk::is_static),
            "{entity} must be static"
        );
    }
    let count = |entity: &str, c: rerun::ComponentIdentifier| -> usize {
        d.chunks[entity]
            .iter()
            .map(|ch| ch.components().get_array(c).map_or(0, |a| a.values().len()))
            .sum()
    };
    let strips = rerun::LineStrips3D::descriptor_strips().component;
    assert_eq!(
        count("table/noses", strips),
        table.cushions.len() + table.jaws.len()
    );
    let lengths = rerun::Cylinders3D::descriptor_lengths().component;
    assert_eq!(count("table/pockets", lengths), table.pockets.len());
    let spots = rerun::Points3D::descriptor_positions().component;
    assert_eq!(count("table/spots", spots), 6);
}

#[test]
fn open_table_gets_a_cloth_patch_and_a_slower_rate_fewer_samples() {
    let (scene, shot) = cue_and_red("open", [0.0, 0.0], [1.5, 0.0], [0.8, 0.02]);
    for rate in [50.0, 333.0] {
        let bytes = record::encode(
            &scene,
            &shot,
            &RecordOptions {
                rate,
                ..Default::default()
            },
        )
        .unwrap();
        let d = decode(&bytes);
        check_against_engine(&d, &shot, rate);
        assert!(d.chunks.contains_key("table/cloth"));
        assert!(!d.chunks.contains_key("table/pockets"));
        let translation = Transform3D::descriptor_translation().component;
        let pos = rows::<rerun::components::Translation3D>(&d, "balls/red", translation);
        let instants = expected_instants(&shot, rate);
        assert_eq!(pos.len(), kept(&states_at(&shot, 1, &instants)).len());
    }
    assert!(matches!(
        record::encode(
            &scene,
            &shot,
            &RecordOptions {
                rate: 0.0,
                ..Default::default()
            }
        ),
        Err(record::RecordError::Rate(_))
    ));
    assert!(matches!(
        record::encode(
            &scene,
            &shot,
            &RecordOptions {
                rate: f64::NAN,
                ..Default::default()
            }
        ),
        Err(record::RecordError::Rate(_))
    ));
}

fn scratch(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn snooker(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_snooker"))
        .args(args)
        .output()
        .unwrap()
}

#[test]
fn cli_writes_a_recording_and_rejects_bad_paths() {
    let dir = scratch("cli-record");
    let out = dir.join("break-off.rrd");
    let run = snooker(&["simulate", "--quiet", "--record", out.to_str().unwrap()]);
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    let d = decode(&std::fs::read(&out).unwrap());
    assert!(d.chunks.contains_key("balls/cue"));
    // Only the recording is left: no temporary file.
    assert_eq!(std::fs::read_dir(&dir).unwrap().count(), 1);

    // Missing directories on the way are created.
    let nested = dir.join("new/sub/x.rrd");
    let run = snooker(&["simulate", "--quiet", "--record", nested.to_str().unwrap()]);
    assert!(run.status.success() && nested.is_file());
    std::fs::remove_dir_all(dir.join("new")).unwrap();

    // A file where a directory should be.
    let file_in_the_way = out.join("x.rrd");
    let y = dir.join("y.rrd").display().to_string();
    // (arguments, whether our own one-line message is expected rather than clap's usage text)
    let bad: Vec<(Vec<String>, bool)> = vec![
        (
            vec!["--record".into(), file_in_the_way.display().to_string()],
            true,
        ),
        (vec!["--record".into(), dir.display().to_string()], true),
        // A path that names a directory by its final separator (refused after the run, and
        // a temporary file left beside it, before).
        (
            vec!["--record".into(), format!("{}/z.rrd/", dir.display())],
            true,
        ),
        (
            vec![
                "--record".into(),
                y.clone(),
                "--record-rate".into(),
                "0".into(),
            ],
            true,
        ),
        (
            vec![
                "--record".into(),
                y.clone(),
                "--record-rate".into(),
                "1e9".into(),
            ],
            true,
        ),
        (
            vec!["--record".into(), y, "--record-rate".into(), "1e300".into()],
            true,
        ),
        (vec!["--record-rate".into(), "100".into()], false),
    ];
    for (args, ours) in bad {
        let mut all = vec!["simulate", "--quiet"];
        all.extend(args.iter().map(String::as_str));
        let run = snooker(&all);
        let err = String::from_utf8_lossy(&run.stderr);
        assert_eq!(run.status.code(), Some(2), "{all:?}: {err}");
        assert!(err.contains("--record"), "{all:?}: {err}");
        if ours {
            assert!(
                err.starts_with("error: ") && err.trim().lines().count() == 1,
                "{err}"
            );
            // A number given is shown as given, not as hundreds of digits.
            assert!(err.len() < 200, "{err}");
        }
    }
    // Nothing else was written.
    assert_eq!(std::fs::read_dir(&dir).unwrap().count(), 1);
}

/// A path drawn through `record::sample::way_times` (the plan's alternatives, `play`'s paths)
/// keeps every corner: each event of the ball is one of its times, and between them the ball
/// moves at most about 5 cm. The plan's alternatives were drawn at 201 evenly spaced times,
/// which cut the corners by millimetres.
#[test]
fn a_way_is_drawn_through_every_event_of_its_ball() {
    let (_, shot) = break_off();
    let cue = 0;
    let speed = shot.tracks[cue].state_at(0.0, &shot.params).vel.norm();
    let times = record::sample::way_times(&shot, cue, speed);
    assert_eq!((times[0], *times.last().unwrap()), (0.0, shot.duration));
    assert!(times.windows(2).all(|w| w[0] < w[1]));
    let events: Vec<f64> = shot
        .events
        .iter()
        .filter(|e| e.balls.contains(&cue))
        .map(|e| e.t)
        .collect();
    assert!(
        events.len() >= 3,
        "the break-off's cue ball meets a red and cushions"
    );
    assert!(events.iter().all(|t| times.contains(t)));
    let at = |t: f64| shot.tracks[cue].state_at(t, &shot.params).pos;
    for w in times.windows(2) {
        assert!((at(w[1]) - at(w[0])).norm() <= 0.05 + 1e-9, "{w:?}");
    }
}
