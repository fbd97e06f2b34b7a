//! A ball's orientation along its trajectory, integrated from its spin: the rigid body's
//! kinematics in quaternion form, dq/dt = (1/2) w q with w in the table frame (a standard
//! identity of rigid-body kinematics; no law of the thesis's is involved).
//! Rendering needs it (the balls' markings turn); so does a robot tracking a marked ball.

use crate::sim::Track;
use crate::{Params, Vec3};
use nalgebra::{Quaternion, UnitQuaternion};

/// Largest rotation in one integration substep, rad. The midpoint rule's error per substep is
/// third order in the step, so this keeps the orientation well below a visible error.
const MAX_SUBSTEP_ANGLE: f64 = 0.01;

/// The ball's orientation (body to table frame) at each of `times` (in order), starting from
/// the identity at the first:
/// dq/dt = (1/2) w q with the exact w(t) of the trajectory, integrated by the exponential
/// midpoint rule over substeps of at most `MAX_SUBSTEP_ANGLE`. Where no event lies strictly
/// between two times (every event time among `times`, as a recording samples them), w(t) is
/// smooth between them except where a decaying sidespin reaches zero; a time repeated (an
/// event's before and after) keeps the orientation.
pub fn orientations(track: &Track, params: &Params, times: &[f64]) -> Vec<UnitQuaternion<f64>> {
    let mut q = UnitQuaternion::identity();
    let mut out = Vec::with_capacity(times.len());
    let mut prev: Option<f64> = None;
    for &t in times {
        if let Some(t0) = prev {
            q = advance(track, params, q, t0, t);
        }
        out.push(q);
        prev = Some(t);
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
    use crate::sim::Segment;
    use crate::{BallKind, BallState, Motion};

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

    fn grid(t_end: f64, n: usize) -> Vec<f64> {
        (0..=n).map(|k| t_end * k as f64 / n as f64).collect()
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
        // An event at 0.1 s: sampled just before and just after, at one time.
        let inst = vec![0.0, 0.1, 0.1];
        let q = orientations(&track, &p, &inst);
        assert_eq!(q[1], q[2]);
        assert!(q[1].angle() > 0.1);
    }
}
