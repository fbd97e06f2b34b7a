//! Shared checks for the integration tests.
#![allow(dead_code)]

use snooker_engine::{Motion, Setup, Shot};
use std::path::PathBuf;
use std::process::{Command, Output};

/// Runs the `snooker` command with `args`.
pub fn snooker(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_snooker"))
        .args(args)
        .output()
        .unwrap()
}

/// One cue ball in `state` on the open table with parameters `p`.
pub fn one_ball_setup(state: snooker_engine::BallState, p: snooker_engine::Params) -> Setup {
    Setup {
        table: snooker_engine::Table::open(),
        params: p,
        models: snooker_engine::Models::default(),
        balls: vec![snooker_engine::Ball {
            id: "cue".into(),
            kind: snooker_engine::BallKind::Cue,
            state,
        }],
    }
}

/// A fresh, empty temporary directory for test `tag`.
pub fn temp_dir(tag: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("snooker-test-{tag}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// What a brute-force sweep of a shot found.
#[derive(Debug, Default)]
pub struct Sweep {
    /// Largest overlap of two balls in play, m.
    pub max_overlap: f64,
    /// Where it happened.
    pub worst: Option<(f64, String, String)>,
    /// First time a ball in play was off the table, with its id.
    pub escaped: Option<(f64, String)>,
    /// Samples taken.
    pub samples: usize,
}

/// Samples every ball of `shot` every `dt` seconds and just before and after every event,
/// checking pairwise overlap and that balls in play stay on the table.
pub fn sweep(setup: &Setup, shot: &Shot, dt: f64) -> Sweep {
    let p = &shot.params;
    let r = p.ball_radius;
    let contact = p.cushion_contact_distance();
    let mut times: Vec<f64> = Vec::new();
    let n = (shot.duration / dt).ceil() as usize;
    times.extend((0..=n).map(|k| (k as f64 * dt).min(shot.duration)));
    for e in &shot.events {
        for d in [-1e-7, -1e-9, 0.0, 1e-9, 1e-7] {
            let t = e.t + d;
            if t >= 0.0 && t <= shot.duration {
                times.push(t);
            }
        }
    }
    let mut out = Sweep::default();
    for &t in &times {
        let states: Vec<_> = shot.tracks.iter().map(|tr| tr.state_at(t, p)).collect();
        out.samples += 1;
        for (i, a) in states.iter().enumerate() {
            if a.motion == Motion::Pocketed {
                continue;
            }
            assert!(a.is_finite(), "non-finite state at t = {t}");
            if out.escaped.is_none() && !setup.table.holds(a.pos, contact, 1e-6) {
                out.escaped = Some((t, shot.tracks[i].id.clone()));
            }
            for (j, b) in states.iter().enumerate().skip(i + 1) {
                if b.motion == Motion::Pocketed {
                    continue;
                }
                let overlap = 2.0 * r - (a.pos - b.pos).norm();
                if overlap > out.max_overlap {
                    out.max_overlap = overlap;
                    out.worst = Some((t, shot.tracks[i].id.clone(), shot.tracks[j].id.clone()));
                }
            }
        }
    }
    out
}

/// Asserts the invariants every finished shot must satisfy.
pub fn check_shot(setup: &Setup, shot: &Shot) {
    for w in shot.events.windows(2) {
        assert!(
            w[0].t <= w[1].t,
            "events out of order: {} then {}",
            w[0].t,
            w[1].t
        );
    }
    let sweep = sweep(setup, shot, 5e-4);
    assert!(
        sweep.max_overlap <= 1e-6,
        "balls overlap by {:.3e} m: {:?}",
        sweep.max_overlap,
        sweep.worst
    );
    assert!(
        sweep.escaped.is_none(),
        "a ball left the table: {:?}",
        sweep.escaped
    );
    for s in shot.final_states() {
        assert!(
            matches!(s.motion, Motion::Stationary | Motion::Pocketed),
            "a ball did not stop: {s:?}"
        );
    }
}
