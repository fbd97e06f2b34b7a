//! Where and what a recording samples: a fixed-rate grid plus every event instant taken twice
//! (just before and just after), the exact states there, and each ball's orientation
//! integrated from its spin.

use nalgebra::{Quaternion, UnitQuaternion};
use snooker_engine::sim::Track;
use snooker_engine::{BallState, Params, Shot, Vec3};

/// Why a sample was taken.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Side {
    /// A point of the fixed-rate grid (or the end of the shot).
    Grid,
    /// The state just before the events of group `.0` (see [`Schedule::groups`]).
    Before(usize),
    /// The state just after the events of group `.0`.
    After(usize),
}

/// One sample instant, shared by every ball.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Instant {
    /// Simulated time, s.
    pub t: f64,
    /// Grid point, or which side of an event instant.
    pub side: Side,
}

/// The sample instants of a shot, in time order (a `Before` and its `After` share their time).
#[derive(Clone, Debug, PartialEq)]
pub struct Schedule {
    /// The instants.
    pub instants: Vec<Instant>,
    /// Events grouped by identical time: `(t, first event index, one past the last)`.
    pub groups: Vec<(f64, usize, usize)>,
}

impl Schedule {
    /// Grid `k / rate` for every `k` with `k / rate <= duration`, the end of the shot, and every
    /// distinct event time twice; a grid point equal to an event time is covered by the pair.
    pub fn new(shot: &Shot, rate: f64) -> Schedule {
        let mut groups: Vec<(f64, usize, usize)> = Vec::new();
        for (i, e) in shot.events.iter().enumerate() {
            match groups.last_mut() {
                Some(g) if g.0 == e.t => g.2 = i + 1,
                _ => groups.push((e.t, i, i + 1)),
            }
        }
        let mut grid: Vec<f64> = (0u64..)
            .map(|k| k as f64 / rate)
            .take_while(|&t| t <= shot.duration)
            .collect();
        if grid.last() != Some(&shot.duration) {
            grid.push(shot.duration);
        }
        let mut instants = Vec::with_capacity(grid.len() + 2 * groups.len());
        let mut g = 0;
        for &t in &grid {
            while g < groups.len() && groups[g].0 <= t {
                instants.push(Instant {
                    t: groups[g].0,
                    side: Side::Before(g),
                });
                instants.push(Instant {
                    t: groups[g].0,
                    side: Side::After(g),
                });
                g += 1;
            }
            if instants.last().is_none_or(|i| i.t != t) {
                instants.push(Instant {
                    t,
                    side: Side::Grid,
                });
            }
        }
        Schedule { instants, groups }
    }

    /// Ball `ball`'s state at every instant: the exact trajectory, and at a `Before` instant
    /// the `before` state of the first event of the group that involves the ball (the
    /// trajectory itself gives the state after an instant's events).
    pub fn states(&self, shot: &Shot, ball: usize) -> Vec<BallState> {
        let track = &shot.tracks[ball];
        self.instants
            .iter()
            .map(|i| {
                if let Side::Before(g) = i.side {
                    let (_, lo, hi) = self.groups[g];
                    let before = shot.events[lo..hi].iter().find_map(|e| {
                        let k = e.balls.iter().position(|&b| b == ball)?;
                        e.before.get(k).copied()
                    });
                    if let Some(s) = before {
                        return s;
                    }
                }
                track.state_at(i.t, &shot.params)
            })
            .collect()
    }
}

/// Largest rotation in one integration substep, rad. The midpoint rule's error per substep is
/// third order in the step, so this keeps the orientation well below a visible error.
const MAX_SUBSTEP_ANGLE: f64 = 0.01;

/// The ball's orientation (body to table frame) at every instant, starting from the identity:
/// dq/dt = (1/2) w q with the exact w(t) of the trajectory, integrated by the exponential
/// midpoint rule over substeps of at most [`MAX_SUBSTEP_ANGLE`]. No instant lies inside an
/// interval, so w(t) is smooth there except where a decaying sidespin reaches zero; at an
/// event (two instants at one time) the orientation carries over unchanged.
pub fn orientations(
    track: &Track,
    params: &Params,
    instants: &[Instant],
) -> Vec<UnitQuaternion<f64>> {
    let mut q = UnitQuaternion::identity();
    let mut out = Vec::with_capacity(instants.len());
    let mut prev: Option<f64> = None;
    for i in instants {
        if let Some(t0) = prev {
            q = advance(track, params, q, t0, i.t);
        }
        out.push(q);
        prev = Some(i.t);
    }
    out
}

/// Rotates `q` by the spin over `[t0, t1]` (no event strictly inside).
fn advance(
    track: &Track,
    params: &Params,
    mut q: UnitQuaternion<f64>,
    t0: f64,
    t1: f64,
) -> UnitQuaternion<f64> {
    let dt = t1 - t0;
    if dt <= 0.0 {
        return q;
    }
    let w = |t: f64| track.state_at(t, params).spin;
    // w(t) is smooth on such an interval (linear under the thesis's laws), so its largest
    // value over five points bounds the step well; the ends are taken just inside the
    // interval to stay off the next segment.
    let peak = [1e-3, 0.25, 0.5, 0.75, 1.0 - 1e-3]
        .iter()
        .map(|f| w(t0 + f * dt).norm())
        .fold(0.0, f64::max);
    if peak == 0.0 {
        return q;
    }
    let n = ((peak * dt / MAX_SUBSTEP_ANGLE).ceil() as usize).max(1);
    let h = dt / n as f64;
    for k in 0..n {
        let mid = t0 + (k as f64 + 0.5) * h;
        q = rotation(w(mid) * h) * q;
    }
    // Renormalise against the slow drift of many products.
    UnitQuaternion::new_normalize(*q.quaternion())
}

/// The rotation by the rotation vector `v` (axis times angle).
fn rotation(v: Vec3) -> UnitQuaternion<f64> {
    let angle = v.norm();
    if angle == 0.0 {
        return UnitQuaternion::identity();
    }
    let (s, c) = (0.5 * angle).sin_cos();
    let a = v / angle * s;
    UnitQuaternion::new_unchecked(Quaternion::new(c, a.x, a.y, a.z))
}

#[cfg(test)]
mod tests {
    use super::*;
    use snooker_engine::sim::Segment;
    use snooker_engine::{BallKind, Motion};

    fn rolling_track(p: &Params, v: Vec3, sidespin: f64) -> Track {
        let s = BallState {
            pos: Vec3::new(0.5, 0.5, p.ball_radius),
            vel: v,
            spin: Vec3::z().cross(&v) / p.ball_radius + Vec3::new(0.0, 0.0, sidespin),
            motion: Motion::Rolling,
        };
        Track {
            id: "cue".into(),
            kind: BallKind::Cue,
            segments: vec![Segment { t: 0.0, state: s }],
        }
    }

    fn grid(t_end: f64, n: usize) -> Vec<Instant> {
        (0..=n)
            .map(|k| Instant {
                t: t_end * k as f64 / n as f64,
                side: Side::Grid,
            })
            .collect()
    }

    #[test]
    fn straight_roll_turns_by_distance_over_radius() {
        let p = Params::default();
        let v = Vec3::new(0.6, 0.8, 0.0);
        let track = rolling_track(&p, v, 0.0);
        let inst = grid(1.5, 360);
        let q = orientations(&track, &p, &inst);
        let end = track.state_at(1.5, &p);
        let dist = (end.pos - track.segments[0].state.pos).norm();
        let axis = Vec3::z().cross(&v).normalize();
        let (got_axis, got_angle) = q.last().unwrap().axis_angle().unwrap();
        let expect = (dist / p.ball_radius) % std::f64::consts::TAU;
        // The rotation angle is reported in [0, pi]; fold the expectation the same way.
        let expect = if expect > std::f64::consts::PI {
            std::f64::consts::TAU - expect
        } else {
            expect
        };
        assert!((got_angle - expect).abs() < 1e-9, "{got_angle} vs {expect}");
        assert!(got_axis.dot(&axis).abs() > 1.0 - 1e-12);
    }

    #[test]
    fn pure_sidespin_turns_about_the_vertical() {
        let p = Params::default();
        let w0 = 20.0;
        let s = BallState {
            pos: Vec3::new(0.5, 0.5, p.ball_radius),
            vel: Vec3::zeros(),
            spin: Vec3::new(0.0, 0.0, w0),
            motion: Motion::Spinning,
        };
        let track = Track {
            id: "cue".into(),
            kind: BallKind::Cue,
            segments: vec![Segment { t: 0.0, state: s }],
        };
        // Sidespin decays linearly to zero: the total angle is w0^2 / (2 decel); sample past it.
        let t_stop = w0 / p.sidespin_decel;
        let inst = grid(0.1, 24);
        let q = orientations(&track, &p, &inst);
        let t = 0.1f64.min(t_stop);
        let expect = w0 * t - 0.5 * p.sidespin_decel * t * t;
        let got = q.last().unwrap().scaled_axis();
        assert!((got.z - expect).abs() < 1e-9, "{} vs {expect}", got.z);
        assert!(got.xy().norm() < 1e-12);
    }

    #[test]
    fn event_pairs_keep_the_orientation() {
        let p = Params::default();
        let track = rolling_track(&p, Vec3::new(1.0, 0.0, 0.0), 5.0);
        let inst = vec![
            Instant {
                t: 0.0,
                side: Side::Grid,
            },
            Instant {
                t: 0.1,
                side: Side::Before(0),
            },
            Instant {
                t: 0.1,
                side: Side::After(0),
            },
        ];
        let q = orientations(&track, &p, &inst);
        assert_eq!(q[1], q[2]);
        assert!(q[1].angle() > 0.1);
    }
}
