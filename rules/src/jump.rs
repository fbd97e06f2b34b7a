//! The jump shot (WPBSA Section 2 Rule 20 "Jump Shot"; a foul by Section 3 Rule 10): the cue
//! ball passes over any part of an object ball, touching it or not, except (a) over another
//! ball after it first struck one, (b) when it jumps and strikes a ball but does not land on
//! that ball's far side, (c) over the ball it struck after a cushion or another ball. In the
//! engine a cue ball leaves the cloth from a steep strike with the bed's restitution set
//! (`e_bed`, off by default), off a ball or off a cushion.
//!
//! Judged on the cue ball's flights, sampled every [`STEP`] the balls move apart: before its first
//! contact with a ball, it is over a ball when their centres are less than 2R apart in plan
//! and the balls do not touch (it can only be above it); after that contact, over the ball it
//! struck only while still in the flight that struck it, before it meets anything else (c),
//! and beyond that ball's centre along its approach (b: the far side); over other balls then
//! no longer counts (a).

use snooker_engine::{BallState, Motion, Shot, Vec3, motion};

/// How far the balls move apart between the samples of a flight, m: a fiftieth of a ball's
/// diameter.
pub const STEP: f64 = 1e-3;
/// The most samples of one flight (a flight's plan way is a few metres at most).
const MAX_SAMPLES: usize = 20_000;
/// Two balls closer than 2R + this, m, touch (the engine's contact tolerance is 1 nm).
const TOUCH: f64 = 1e-6;

/// True when the cue ball (`cue`, an index of `shot`'s tracks) made a jump shot; `first` is
/// the time of its first contact with a ball and the balls it met then (none: no ball hit).
pub fn jump_shot(shot: &Shot, cue: usize, first: Option<(f64, &[usize])>) -> bool {
    let p = &shot.params;
    let r = p.ball_radius;
    let track = &shot.tracks[cue];
    let t_first = first.map_or(f64::INFINITY, |f| f.0);
    let struck: &[usize] = first.map_or(&[], |f| f.1);
    let segments = &track.segments;
    for (k, seg) in segments.iter().enumerate() {
        if seg.state.motion != Motion::Airborne || seg.t > t_first {
            continue;
        }
        let end = segments.get(k + 1).map_or(shot.duration, |s| s.t);
        // Before the first contact: over any ball, but in the flight that strikes, over the
        // balls struck (coming down onto one is judged by (b) below).
        let coming_down_on: &[usize] = if end >= t_first { struck } else { &[] };
        let over_any = samples(seg.t, end.min(t_first), plan_speed(seg.state.vel)).any(|t| {
            let c = track.state_at(t, p);
            (0..shot.tracks.len())
                .filter(|&j| j != cue && !coming_down_on.contains(&j))
                .any(|j| above(&c, &shot.tracks[j].state_at(t, p), r, None))
        });
        if over_any {
            return true;
        }
        // The flight that struck: over a ball it struck and past its centre, before the cue
        // ball's next event (the segment's end).
        if seg.t <= t_first && t_first < end {
            // The way it came: the segment before the contact's, at the contact.
            let before = segments.partition_point(|s| s.t < t_first).max(1) - 1;
            let b = &segments[before];
            let c0 = motion::state_at(&b.state, t_first - b.t, p);
            let approach = Vec3::new(c0.vel.x, c0.vel.y, 0.0);
            // Sampled on the way the two balls move apart: the struck ones move too.
            let relative = plan_speed(seg.state.vel)
                + struck
                    .iter()
                    .map(|&j| plan_speed(shot.tracks[j].state_at(t_first, p).vel))
                    .fold(0.0, f64::max);
            let past = samples(t_first, end, relative).any(|t| {
                let c = track.state_at(t, p);
                struck
                    .iter()
                    .any(|&j| above(&c, &shot.tracks[j].state_at(t, p), r, Some(approach)))
            });
            if past {
                return true;
            }
        }
    }
    false
}

/// The speed of a velocity's plan part, m/s.
fn plan_speed(v: Vec3) -> f64 {
    Vec3::new(v.x, v.y, 0.0).norm()
}

/// Instants from `t0` to `t1` (both included) about [`STEP`] of the way apart for balls
/// moving apart at `speed` m/s in plan (a flight's plan velocity is constant: thesis §6.1.6).
fn samples(t0: f64, t1: f64, speed: f64) -> impl Iterator<Item = f64> {
    let span = (t1 - t0).max(0.0);
    let n = ((span * speed / STEP).ceil() as usize).clamp(1, MAX_SAMPLES);
    (0..=n).map(move |i| t0 + span * i as f64 / n as f64)
}

/// True when the cue ball `c` is over the ball `o` (in play): less than 2R apart in plan and
/// not touching, and, given the cue ball's `approach`, beyond `o`'s centre along it.
fn above(c: &BallState, o: &BallState, r: f64, approach: Option<Vec3>) -> bool {
    if !o.motion.in_play() {
        return false;
    }
    let d = c.pos - o.pos;
    let plan = Vec3::new(d.x, d.y, 0.0);
    let over = plan.norm() < 2.0 * r && d.norm() > 2.0 * r + TOUCH && d.z > 0.0;
    over && approach.is_none_or(|a| plan.dot(&a) > 0.0)
}

#[cfg(test)]
mod tests {
    use super::*;
    use snooker_engine::sim::{Segment, Stats, Track};
    use snooker_engine::{BallKind, Ending, Params};

    /// A cue ball coming down (heading +x) onto the back of a red that the bed holds, touching
    /// it at t = 0.1 s 20 mm behind its centre in plan, and leaving it in the air at `after`.
    fn struck_from_above(after: Vec3) -> Shot {
        let p = Params::default();
        let r = p.ball_radius;
        let red = Vec3::new(1.0, 0.5, r);
        let contact = red + Vec3::new(-0.02, 0.0, ((2.0 * r).powi(2) - 0.02f64.powi(2)).sqrt());
        let flying = |pos: Vec3, vel: Vec3| BallState {
            pos,
            vel,
            spin: Vec3::zeros(),
            motion: Motion::Airborne,
        };
        // Coming in at 1 m/s along +x, 0.1 s before the contact (gravity brought back).
        let (v_in, dt) = (Vec3::new(1.0, 0.0, -0.2), 0.1);
        let g = Vec3::new(0.0, 0.0, -p.g);
        let v0 = v_in - g * dt;
        let start = contact - v0 * dt - 0.5 * g * dt * dt;
        let track = |id: &str, kind, segments| Track {
            id: id.into(),
            kind,
            segments,
        };
        Shot {
            params: p,
            events: Vec::new(),
            tracks: vec![
                track(
                    "cue",
                    BallKind::Cue,
                    vec![
                        Segment {
                            t: 0.0,
                            state: flying(start, v0),
                        },
                        Segment {
                            t: dt,
                            state: flying(contact, after),
                        },
                    ],
                ),
                track(
                    "red",
                    BallKind::Red,
                    vec![Segment {
                        t: 0.0,
                        state: BallState::at_rest(red.x, red.y, r),
                    }],
                ),
            ],
            duration: 0.3,
            ending: Ending::AtRest,
            stats: Stats::default(),
        }
    }

    #[test]
    fn over_the_ball_struck_counts_only_beyond_its_centre_along_the_approach() {
        let first = Some((0.1, &[1usize][..]));
        // Thrown back and up, it stays over the red's near half: no jump shot (Rule 20(b)),
        // though it is over the red and beyond its centre along its new heading.
        let back = struck_from_above(Vec3::new(-0.1, 0.0, 0.5));
        assert!(!jump_shot(&back, 0, first));
        // Carried on over the red's centre: a jump shot.
        let on = struck_from_above(Vec3::new(0.3, 0.0, 0.5));
        assert!(jump_shot(&on, 0, first));
        // The same flight judged as one that struck nothing: over the red before the contact
        // (which the approach to the ball struck is not), so a jump shot.
        assert!(jump_shot(&back, 0, None));
    }
}
