//! Ball-ball contact: the centres' distance reaches 2R while they approach. In 3D, so that an
//! airborne ball can pass over or land on another.

use super::roots::first_entry;
use crate::motion::Path;

/// First time in [0, window] at which balls on paths `a` and `b` (from the same instant)
/// touch while approaching; `radius` is the balls' radius.
pub fn contact_time(a: &Path, b: &Path, window: f64, radius: f64) -> Option<f64> {
    first_entry(&b.minus(a), 2.0 * radius, window)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ball::{BallState, Motion, Vec3};
    use crate::motion;
    use crate::params::Params;

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
        let (a, b) = (motion::path(&cue, &p), motion::path(&red, &p));
        let t = contact_time(&a, &b, motion::duration(&cue, &p), r).unwrap();
        let at = motion::state_at(&cue, t, &p);
        assert!(((at.pos - red.pos).norm() - 2.0 * r).abs() < 2.0 * crate::detect::SKIN);
    }
}
