//! The switches that end a phase (thesis §6.1.4, §6.2.4: compression ends, restitution ends,
//! a slip stops or turns, a ball presses on or lifts off the cloth), named, and their event
//! functions: each changes sign at its switch, and the integrator locates the root on its
//! continuous extension ([`crate::impact::dopri`]).

use super::laws::{Held, NONE_HELD};
use super::mode::{CLOTH, Friction, Mode, PRIMARY};
use super::pair::Pair;
use super::phase::PhaseLaws;
use super::problem::Impact;
use crate::ball::Vec3;
use crate::impact::dopri::Events;

/// A switch that ends a phase.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Event {
    /// The normal relative velocity reached zero: compression is over (thesis eq. 6.12).
    Compressed,
    /// The work of the normal impulse reached its target: the impact is over (Stronge's
    /// energetic restitution, thesis eq. 6.38).
    Restituted,
    /// Frictional contact `k` ([`PRIMARY`], or [`CLOTH`] under a body): its slip stopped,
    /// turned through 90 degrees, or, creeping out of zero, became established.
    Slip(usize),
    /// Body `i`'s support changed: the cloth starts or stops pressing on it, or, lifted, it
    /// came back down.
    Support(usize),
}

/// Number of event functions: compression, restitution, three slips, two supports.
pub(super) const K: usize = 7;

impl Event {
    /// The event's place among the event functions.
    pub const fn index(self) -> usize {
        match self {
            Event::Compressed => 0,
            Event::Restituted => 1,
            Event::Slip(k) => 2 + k,
            Event::Support(i) => 5 + i,
        }
    }

    /// The event at place `e` among the event functions (`e < K`).
    pub const fn at(e: usize) -> Event {
        match e {
            0 => Event::Compressed,
            1 => Event::Restituted,
            2..=4 => Event::Slip(e - 2),
            _ => Event::Support(e - 5),
        }
    }
}

/// The event function of frictional contact `k` under `mode` whose slip is `s`: it changes
/// sign when the slip turns through 90 degrees from the phase's direction, and drops to exactly
/// zero when the slip comes down to zero (a slip growing out of zero arms it without a sign
/// change), and one relaxing onto its steady direction also when it lies along it; a slip
/// creeping out of zero crosses zero when it is established. One followed quasi-statically
/// crosses zero where it is established, where it comes down to zero (its part along its
/// direction at the phase's start changes sign: a step may cross the zero band), or where its
/// rate along its steady direction (`rate`, from the Coulomb solve) changes sign.
#[inline(always)]
pub(super) fn slip_event(mode: &Mode, k: usize, s: Vec3, rate: impl FnOnce() -> f64) -> f64 {
    let n = s.norm();
    match mode.friction[k] {
        Friction::Off => 0.0,
        Friction::Slip(r) => {
            if n <= 2.0 * mode.zero {
                0.0
            } else if let Some(u) = mode.aligning[k] {
                s.dot(&r).min((s - s.dot(&u) * u).norm() - 2.0 * mode.zero)
            } else {
                s.dot(&r)
            }
        }
        Friction::AtZero | Friction::Starting(_) => n - mode.established[k],
        Friction::QuasiStatic(r, sign) => {
            if n > 2.0 * mode.zero {
                // No steady direction any more (NaN): the phase ends too. A rate within the
                // events' resolution of zero has not turned: the phase began at that rate's
                // own root (its sign taken from the trend), and rounding about the root must
                // neither end it at once nor disarm the other terms.
                let turned = -sign * rate();
                let turned = if turned.is_nan() {
                    1.0
                } else if turned.abs() <= RESOLUTION {
                    -RESOLUTION
                } else {
                    turned
                };
                (n - mode.established[k]).max(-s.dot(&r)).max(turned)
            } else {
                0.0
            }
        }
    }
}

/// The events' own resolution ([`super::phase`]'s root tolerance: an event is located where
/// its function is within this of zero), in units of V, of the normal impulse per unit dP, or
/// of V per unit impulse for a slip's rate. A support's event function within it is zero: a
/// ball on the cloth whose other vertical forces cancel (both balls on the cloth, friction
/// horizontal) feels a vertical force of rounding size, 1e-18 to 1e-15, whose sign is noise:
/// it neither presses nor lifts (thesis §6.1.2), and must not switch the phase.
pub(super) const RESOLUTION: f64 = 1e-12;

/// The event function of body `i`'s support: its vertical speed while it is up (it comes
/// back down), the other vertical forces on it while it is down (they change sign where the
/// cloth starts or stops holding it); `fz` gives those forces, computed only if needed. Zero
/// within [`RESOLUTION`]: an event function that starts at zero is armed only once
/// it leaves it, so noise about a switch never ends a phase.
#[inline(always)]
fn support_event(vz: f64, fz: impl FnOnce() -> f64) -> f64 {
    let g = if vz > 0.0 { vz } else { fz() };
    if g.abs() > RESOLUTION { g } else { 0.0 }
}

impl<const M: usize, P: Pair<M>, const AT_ZERO: bool> PhaseLaws<'_, M, P, AT_ZERO> {
    /// The Coulomb solve at `y` ([`Impact::at_zero`]): the frictions of the contacts at zero
    /// slip or followed quasi-statically, and the rates of the latter's slips.
    #[inline(always)]
    fn solved(&self, y: &[f64; M]) -> (Held, [f64; 3]) {
        let c = self.contact;
        let (held, creeping) = c.at_zero::<M, P>(y, &c.local::<M, P>(y), self.mode);
        (held, creeping.map(|cr| cr.map_or(f64::NAN, |cr| cr.rate)))
    }

    /// The primary contact's friction at `y` (slip `slip`): a slip's law, or the Coulomb
    /// solve's (`held`, solved here if not given) when the contact is at zero slip or
    /// followed quasi-statically.
    #[inline(always)]
    fn primary_at(&self, y: &[f64; M], slip: Vec3, held: Option<&Held>) -> Vec3 {
        let (c, mode) = (self.contact, self.mode);
        if AT_ZERO
            && matches!(
                mode.friction[PRIMARY],
                Friction::AtZero | Friction::QuasiStatic(..)
            )
        {
            let held = held.copied().unwrap_or_else(|| self.solved(y).0);
            c.primary_friction(slip, mode, &held)
        } else {
            c.primary_friction(slip, mode, &NONE_HELD)
        }
    }

    /// Event `e`'s function at `y`, computing only what it needs.
    #[inline(always)]
    fn event(&self, y: &[f64; M], e: Event) -> f64 {
        let (c, mode) = (self.contact, self.mode);
        let motion = || c.primary_motion::<M, P>(y);
        let slip = || {
            let (u, vn) = motion();
            u - vn * c.normal
        };
        match e {
            Event::Compressed if mode.compressing => motion().1,
            Event::Restituted if !mode.compressing => y[P::WORK] - mode.w_target,
            Event::Slip(PRIMARY) => slip_event(mode, PRIMARY, slip(), || self.solved(y).1[PRIMARY]),
            Event::Slip(k) => {
                slip_event(mode, k, Impact::cloth_slip::<M, P>(y, k - CLOTH[0]), || {
                    self.solved(y).1[k]
                })
            }
            Event::Support(i) if c.bodies[i].on_cloth => support_event(P::vel(y, i).z, || {
                c.vertical_forces(self.primary_at(y, slip(), None))[i]
            }),
            _ => 0.0,
        }
    }
}

impl<const M: usize, P: Pair<M>, const AT_ZERO: bool> Events<M, K>
    for PhaseLaws<'_, M, P, AT_ZERO>
{
    #[inline(always)]
    fn all(&self, y: &[f64; M]) -> [f64; K] {
        let (c, mode) = (self.contact, self.mode);
        let (u, vn) = c.primary_motion::<M, P>(y);
        let mut g = [0.0; K];
        if mode.compressing {
            g[Event::Compressed.index()] = vn;
        } else {
            g[Event::Restituted.index()] = y[P::WORK] - mode.w_target;
        }
        // The Coulomb solve, once, if a slip followed quasi-statically needs its rate.
        let quasi_static = AT_ZERO
            && mode
                .friction
                .iter()
                .any(|law| matches!(law, Friction::QuasiStatic(..)));
        let solved = quasi_static.then(|| self.solved(y));
        let rate = |k: usize| solved.map_or(f64::NAN, |(_, r)| r[k]);
        let slip = u - vn * c.normal;
        g[Event::Slip(PRIMARY).index()] = slip_event(mode, PRIMARY, slip, || rate(PRIMARY));
        for (i, &k) in CLOTH.iter().enumerate() {
            if !matches!(mode.friction[k], Friction::Off) {
                let s = Impact::cloth_slip::<M, P>(y, i);
                g[Event::Slip(k).index()] = slip_event(mode, k, s, || rate(k));
            }
        }
        // The vertical forces on the bodies, formed once if a support needs them.
        let mut fz: Option<[f64; 2]> = None;
        for i in 0..2 {
            if c.bodies[i].on_cloth {
                g[Event::Support(i).index()] = support_event(P::vel(y, i).z, || {
                    fz.get_or_insert_with(|| {
                        let held = solved.as_ref().map(|(h, _)| h);
                        c.vertical_forces(self.primary_at(y, slip, held))
                    })[i]
                });
            }
        }
        g
    }

    #[inline(always)]
    fn one(&self, y: &[f64; M], e: usize) -> f64 {
        self.event(y, Event::at(e))
    }
}
