//! The balls' paths as the page draws and animates them: each ball's exact trajectory (the
//! engine's `Shot`, evaluated by [`snooker_engine::sim::Track::state_at`]) sampled at every
//! instant its law changes (its events) and on a fixed grid while it moves, until it leaves
//! play. The page joins the samples with straight lines; every event position is a sample, so
//! the drawn path passes through it exactly.

use serde::Serialize;
use snooker_engine::{BallKind, Motion, Shot};

/// One ball's path.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Path {
    /// The ball's id.
    pub id: String,
    /// Its colour.
    pub kind: BallKind,
    /// Sample times, s, increasing.
    pub t: Vec<f64>,
    /// Centre x at each time, m.
    pub x: Vec<f64>,
    /// Centre y at each time, m.
    pub y: Vec<f64>,
    /// Centre height at each time, m (R on the cloth).
    pub z: Vec<f64>,
    /// When the ball left play (pocketed or off the table), s; its last sample is then.
    pub gone_at: Option<f64>,
}

/// The paths of a shot and the grid they were sampled on.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Paths {
    /// The grid's rate, Hz (lowered from the one asked for when the points would exceed the
    /// limit).
    pub rate: f64,
    /// Duration of the shot, s.
    pub duration: f64,
    /// One path per ball, in the scene's order.
    pub balls: Vec<Path>,
}

/// The stretches of one ball's track: `(start, end, motion)` with `end` the next segment's
/// start (the shot's end for the last), cut where the ball leaves play.
fn stretches(shot: &Shot, i: usize) -> (Vec<(f64, f64, Motion)>, Option<f64>) {
    let segs = &shot.tracks[i].segments;
    let mut out = Vec::with_capacity(segs.len());
    for (k, s) in segs.iter().enumerate() {
        if !s.state.motion.in_play() {
            return (out, Some(s.t));
        }
        let end = segs.get(k + 1).map_or(shot.duration, |n| n.t);
        out.push((s.t, end.max(s.t), s.state.motion));
    }
    (out, None)
}

/// Samples every ball's path of `shot` at `rate` Hz while it moves, lowering the rate so that
/// the grid's points stay within `max_points` (the event instants are always sampled).
pub fn sample(shot: &Shot, rate: f64, max_points: usize) -> Paths {
    let all: Vec<_> = (0..shot.tracks.len()).map(|i| stretches(shot, i)).collect();
    let moving: f64 = all
        .iter()
        .flat_map(|(s, _)| s.iter())
        .filter(|(_, _, m)| m.is_moving())
        .map(|(a, b, _)| b - a)
        .sum();
    // Each stretch: its start, and at most one grid point more than its length times the rate.
    let boundaries: usize = all.iter().map(|(s, _)| 2 * s.len() + 2).sum();
    let room = max_points.saturating_sub(boundaries).max(1) as f64;
    let rate = if moving * rate > room {
        room / moving
    } else {
        rate
    };
    let balls = all
        .iter()
        .enumerate()
        .map(|(i, (stretches, gone_at))| {
            let track = &shot.tracks[i];
            let mut times: Vec<f64> = Vec::new();
            let mut push = |t: f64| {
                if times.last().is_none_or(|&last| t > last) {
                    times.push(t);
                }
            };
            for &(a, b, m) in stretches {
                push(a);
                if m.is_moving() && rate > 0.0 {
                    let first = (a * rate).floor() as u64 + 1;
                    let mut k = first;
                    loop {
                        let t = k as f64 / rate;
                        if t >= b {
                            break;
                        }
                        push(t);
                        k += 1;
                    }
                }
            }
            match gone_at {
                Some(t) => push(*t),
                None => push(shot.duration),
            }
            let states: Vec<_> = times
                .iter()
                .map(|&t| track.state_at(t, &shot.params))
                .collect();
            Path {
                id: track.id.clone(),
                kind: track.kind,
                x: states.iter().map(|s| s.pos.x).collect(),
                y: states.iter().map(|s| s.pos.y).collect(),
                z: states.iter().map(|s| s.pos.z).collect(),
                t: times,
                gone_at: *gone_at,
            }
        })
        .collect();
    Paths {
        rate,
        duration: shot.duration,
        balls,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn shot() -> Shot {
        let scene =
            snooker_scene::parse(snooker_scene::DEFAULT_SCENE, "break-off.toml").expect("scene");
        snooker_engine::simulate(&scene.setup, &scene.options).expect("shot")
    }

    #[test]
    fn every_event_position_is_a_sample_of_the_path() {
        let shot = shot();
        let paths = sample(&shot, 120.0, 1_000_000);
        for e in &shot.events {
            for (k, &b) in e.balls.iter().enumerate() {
                let p = &paths.balls[b];
                let j = p.t.iter().position(|&t| t == e.t);
                let j = j.unwrap_or_else(|| panic!("{} has no sample at {}", p.id, e.t));
                let at = e.after[k].pos;
                assert_eq!(
                    [p.x[j], p.y[j]],
                    [at.x, at.y],
                    "{} at {} ({})",
                    p.id,
                    e.t,
                    e.kind.name()
                );
            }
        }
        // The last sample is where the ball ends (or where it left play).
        for (p, s) in paths.balls.iter().zip(shot.final_states()) {
            if s.motion.in_play() {
                assert_eq!(
                    [*p.x.last().unwrap(), *p.y.last().unwrap()],
                    [s.pos.x, s.pos.y]
                );
            } else {
                assert!(p.gone_at.is_some());
            }
        }
    }

    #[test]
    fn the_rate_is_lowered_to_keep_within_the_points() {
        let shot = shot();
        let full = sample(&shot, 240.0, 1_000_000);
        let n: usize = full.balls.iter().map(|p| p.t.len()).sum();
        let cut = sample(&shot, 240.0, n / 4);
        let m: usize = cut.balls.iter().map(|p| p.t.len()).sum();
        assert!(
            cut.rate < 240.0 && m <= n / 4,
            "{m} points of {n}, rate {}",
            cut.rate
        );
        assert!(full.rate == 240.0);
    }
}
