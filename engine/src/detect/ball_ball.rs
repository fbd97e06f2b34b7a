//! Ball-ball contact: the centres' distance reaches 2R while they approach. In 3D, so that an
//! airborne ball can pass over or land on another.

use super::roots::first_entry;
use crate::ball::BallState;
use crate::motion;
use crate::params::Params;

/// First time in [0, window] at which balls `a` and `b` (states at the same instant) touch
/// while approaching.
pub fn contact_time(a: &BallState, b: &BallState, window: f64, p: &Params) -> Option<f64> {
    let rel = motion::path(b, p).minus(&motion::path(a, p));
    first_entry(&rel, 2.0 * p.ball_radius, window)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ball::{Motion, Vec3};

    #[test]
    fn sliding_ball_hits_resting_ball_where_the_law_says() {
        let p = Params::default();
        let r = p.ball_radius;
        let cue = motion::settle(
            BallState {
                pos: Vec3::new(0.0, 0.0, r),
                vel: Vec3::new(2.0, 0.0, 0.0),
                spin: Vec3::zeros(),
                motion: Motion::Sliding,
            },
            &p,
        );
        let red = BallState::at_rest(0.5, 0.01, r);
        let t = contact_time(&cue, &red, motion::duration(&cue, &p), &p).unwrap();
        let at = motion::state_at(&cue, t, &p);
        assert!(((at.pos - red.pos).norm() - 2.0 * r).abs() < 2.0 * crate::detect::SKIN);
    }
}
