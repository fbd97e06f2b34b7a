//! The bed's rebound: the cloth on the slate stops a ball's downward motion and, with the
//! restitution `e_bed`, gives back e_bed of that speed upwards (Newton's restitution). A ball
//! bounces when it lands from a flight, and a cue inclined down drives the ball into the bed,
//! which throws it up: the jump shot ([`crate::cue`]). The thesis takes e_bed = 0: its cloth
//! stops a landing ball's fall (§6.1.6) and takes the cue's downward impulse (§7.1.3), so both
//! are off by default. Friction during a bounce is the thesis's landing's: neglected, horizontal
//! velocity and spin unchanged.

use crate::params::Params;

/// A rebound slower than this, m/s, is taken by the cloth: a hop of v^2 / 2g = 0.13 mm lasting
/// 2v / g = 10 ms, under the cloth's own thickness. Without it the bounces, each e_bed times
/// slower, would be infinitely many in a finite time (the bouncing ball's series).
pub const MIN_REBOUND: f64 = 0.05;

/// The upward speed the bed gives a ball that meets it moving down at `down` m/s (>= 0):
/// e_bed `down`, or 0 (the ball stays on the cloth) below [`MIN_REBOUND`].
pub fn rebound(down: f64, p: &Params) -> f64 {
    let up = p.e_bed * down.max(0.0);
    if up < MIN_REBOUND { 0.0 } else { up }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_thesis_bed_never_rebounds() {
        let p = Params::default();
        assert_eq!(rebound(5.0, &p), 0.0);
    }

    #[test]
    fn a_rebound_is_e_times_the_fall_until_it_is_too_small() {
        let p = Params {
            e_bed: 0.5,
            ..Params::default()
        };
        assert_eq!(rebound(2.0, &p), 1.0);
        assert_eq!(rebound(0.2, &p), 0.1);
        assert_eq!(rebound(0.099, &p), 0.0);
        assert_eq!(rebound(-1.0, &p), 0.0);
    }
}
