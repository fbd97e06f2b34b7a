//! Where restitution ends: the work of the normal impulse the contact gives back of what it
//! stored in compression. A rigid contact gives back e^2 of it (energetic restitution, thesis
//! eq. 6.12b; Stronge 2000). A compliant cushion of finite travel ([`Backing`]) gives back
//! e^2 of what its rubber took and less of what the backing behind it took; with
//! rate-independent friction nothing else of the compliance shows in impulse space (Stronge
//! 2000, §2.3: the normal impulse stays the independent variable whatever the force law).

use super::problem::{Backing, Impact};

impl Backing {
    /// The backing in the solver's scaled units (work / (M V^2), damping x V) for a ball of
    /// `mass` approaching at `v_scale`.
    pub(super) fn scaled(self, mass: f64, v_scale: f64) -> Backing {
        Backing {
            bottom_energy: self.bottom_energy / (mass * v_scale * v_scale),
            damping: self.damping * v_scale,
        }
    }

    /// The restitution of a frictionless impact of a ball of `mass` whose contact approaches
    /// at `speed` (m/s), the rubber's own being `e`: the square root of the share of the
    /// compression's work M speed^2 / 2 that comes back. A time-stepped engine (the rapier
    /// cross-check) applies it as Newton's restitution.
    pub fn restitution(&self, e: f64, mass: f64, speed: f64) -> f64 {
        if speed.is_nan() || speed <= 0.0 {
            return e;
        }
        let scaled = self.scaled(mass, speed);
        if 0.5 <= scaled.bottom_energy {
            return e;
        }
        (scaled.given_back(e, 0.5) / 0.5).sqrt()
    }

    /// The work given back of `w_c` stored (the units of `self`, the mass 1): e^2 of the
    /// rubber's share, up to `bottom_energy`, and (1 - damping v)^2 of the rest, which met
    /// the backing at v = sqrt(2 W) (the speed at which the reference mass carries it).
    pub(super) fn given_back(&self, e: f64, w_c: f64) -> f64 {
        let rubber = w_c.min(self.bottom_energy);
        let backing = w_c - rubber;
        let e_backing = (1.0 - self.damping * (2.0 * backing).sqrt()).max(0.0);
        e * e * rubber + e_backing * e_backing * backing
    }
}

impl Impact {
    /// The work at which restitution ends, once compression has ended with the work `w_c`
    /// done: W_c less what the contact gives back ((1 - e^2) W_c for a rigid contact, thesis
    /// eq. 6.12b). None when nothing is left to restore (e = 0, or e so small that e^2 W_c
    /// rounds away): restitution is then over at once, not a phase searching for a crossing
    /// of the work it already has.
    pub(super) fn restitution_target(&self, w_c: f64) -> Option<f64> {
        let target = match self.backing {
            Some(b) if w_c > b.bottom_energy => w_c - b.given_back(self.e, w_c),
            _ => (1.0 - self.e * self.e) * w_c,
        };
        (target != w_c).then_some(target)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn within_the_travel_the_rubber_alone_gives_back() {
        let b = Backing {
            bottom_energy: 0.5,
            damping: 0.3,
        };
        assert_eq!(b.given_back(0.98, 0.4), 0.98 * 0.98 * 0.4);
        assert_eq!(b.given_back(0.98, 0.5), 0.98 * 0.98 * 0.5);
    }

    #[test]
    fn the_backing_gives_back_less_the_harder_it_is_met() {
        let b = Backing {
            bottom_energy: 0.5,
            damping: 0.3,
        };
        let share = |w: f64| b.given_back(1.0, w) / w;
        assert!(share(0.6) < 1.0);
        assert!(share(2.0) < share(0.6));
        // Undamped, the backing is elastic: nothing is lost.
        let elastic = Backing { damping: 0.0, ..b };
        assert_eq!(elastic.given_back(1.0, 2.0), 2.0);
        // Damped to a stop, it gives nothing back: only the rubber's share returns.
        let dead = Backing { damping: 1e6, ..b };
        assert_eq!(dead.given_back(1.0, 2.0), 0.5);
    }
}
