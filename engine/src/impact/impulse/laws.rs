//! The laws of the impact per unit normal impulse dP (thesis §6.1.2, §6.2.2): the velocities
//! at the contacts, the forces (the normal impulse, Coulomb friction at the primary contact,
//! the cloth's unilateral reaction and friction under each ball), and the rates of the state
//! they give. Written once for both body pairs ([`Pair`]).

use super::mode::{CLOTH, Mode, PRIMARY, friction};
use super::pair::{Pair, moving_bodies};
use super::problem::Impact;
use crate::ball::Vec3;

/// Velocities at the contacts in one state.
#[derive(Clone, Copy, Debug)]
pub(super) struct Local {
    /// Normal relative velocity at the primary contact (positive approaching).
    pub vn: f64,
    /// Slips of the three frictional contacts (primary, cloth under body 0, body 1).
    pub slip: [Vec3; 3],
}

/// All forces per unit dP, besides the primary normal impulse.
#[derive(Clone, Copy, Debug)]
pub(super) struct Forces {
    /// Friction on body 0 at the primary contact (body 1 gets the opposite).
    pub primary: Vec3,
    /// Cloth friction on each body.
    pub cloth: [Vec3; 2],
    /// Cloth reaction on each body.
    pub reaction: [f64; 2],
}

/// Frictions of contacts at zero slip, as the Coulomb solve gives them (indexed as
/// [`Mode::friction`]); unread for contacts that are not at zero.
pub(super) type Held = [Vec3; 3];

/// Whether the cloth presses on each body (holds it down, with a reaction).
pub(super) type Pressed = [bool; 2];

/// No contact at zero slip.
pub(super) const NONE_HELD: Held = [Vec3::new(0.0, 0.0, 0.0); 3];

impl Impact {
    /// Velocity of body 0's contact point relative to body 1's, and its normal part
    /// (positive approaching). A fixed body's contact point is at rest.
    #[inline(always)]
    pub(super) fn primary_motion<const M: usize, P: Pair<M>>(&self, y: &[f64; M]) -> (Vec3, f64) {
        let point = |i: usize| P::vel(y, i) + P::spin(y, i).cross(&self.arm[i]);
        let u = if P::OTHER_FREE {
            point(0) - point(1)
        } else {
            point(0)
        };
        (u, u.dot(&self.normal))
    }

    /// Slip of body `i`'s cloth contact point (horizontal): v + w x (-z) in units of R.
    #[inline(always)]
    pub(super) fn cloth_slip<const M: usize, P: Pair<M>>(y: &[f64; M], i: usize) -> Vec3 {
        let (v, w) = (P::vel(y, i), P::spin(y, i));
        Vec3::new(v.x - w.y, v.y + w.x, 0.0)
    }

    /// The velocities at the contacts of state `y`.
    #[inline(always)]
    pub(super) fn local<const M: usize, P: Pair<M>>(&self, y: &[f64; M]) -> Local {
        let (u, vn) = self.primary_motion::<M, P>(y);
        Local {
            vn,
            slip: [
                u - vn * self.normal,
                Self::cloth_slip::<M, P>(y, 0),
                Self::cloth_slip::<M, P>(y, 1),
            ],
        }
    }

    /// Friction coefficient of frictional contact `k`.
    pub(super) fn coefficient(&self, k: usize) -> f64 {
        if k == PRIMARY { self.mu } else { self.mu_cloth }
    }

    /// Vertical component of the non-cloth force on each body (per unit dP), given the
    /// friction `fp` on body 0 at the primary contact.
    #[inline(always)]
    pub(super) fn vertical_forces(&self, fp: Vec3) -> [f64; 2] {
        [fp.z - self.normal.z, self.normal.z - fp.z]
    }

    /// Which bodies the cloth presses on when the other vertical forces on them are `fz`: a
    /// ball that is down on the cloth and pushed down (a unilateral constraint, thesis §6.1.2;
    /// eq. 6.28 for the cushion). One pushed up, or already rising, is free.
    #[inline(always)]
    pub(super) fn pressed_by<const M: usize, P: Pair<M>>(
        &self,
        y: &[f64; M],
        fz: [f64; 2],
    ) -> Pressed {
        [0, 1].map(|i| self.bodies[i].on_cloth && P::vel(y, i).z <= 0.0 && fz[i] < 0.0)
    }

    /// Friction on body 0 at the primary contact under `mode`, its slip being `slip`; `held`
    /// if the contact is at zero slip.
    #[inline(always)]
    pub(super) fn primary_friction(&self, slip: Vec3, mode: &Mode, held: &Held) -> Vec3 {
        friction(
            mode.friction[PRIMARY],
            self.mu,
            || slip,
            mode.zero,
            held[PRIMARY],
        )
    }

    /// The cloth's friction on body `i` at state `y` under `mode`, its reaction being
    /// `reaction`; `held` if the contact is at zero slip.
    #[inline(always)]
    fn cloth_friction<const M: usize, P: Pair<M>>(
        &self,
        y: &[f64; M],
        i: usize,
        reaction: f64,
        mode: &Mode,
        held: &Held,
    ) -> Vec3 {
        let k = CLOTH[i];
        let slip = || Self::cloth_slip::<M, P>(y, i);
        friction(
            mode.friction[k],
            self.mu_cloth * reaction,
            slip,
            mode.zero,
            held[k],
        )
    }

    /// The forces at state `y` under `mode` (the primary contact's slip `slip`), contacts at
    /// zero slip exerting the frictions `held`.
    #[inline(always)]
    pub(super) fn forces_with<const M: usize, P: Pair<M>>(
        &self,
        y: &[f64; M],
        slip: Vec3,
        mode: &Mode,
        held: &Held,
    ) -> Forces {
        let primary = self.primary_friction(slip, mode, held);
        let fz = self.vertical_forces(primary);
        let pressed = self.pressed_by::<M, P>(y, fz);
        self.forces_given::<M, P>(y, primary, fz, pressed, mode, held)
    }

    /// [`Impact::forces_with`] with the cloth pressing on the bodies `pressed`, whatever the
    /// vertical forces: its reaction on each is then affine in the frictions, negative where
    /// the forces would lift the ball (what the Coulomb solve needs, [`super::coulomb`]).
    #[inline(always)]
    pub(super) fn forces_under<const M: usize, P: Pair<M>>(
        &self,
        y: &[f64; M],
        slip: Vec3,
        mode: &Mode,
        held: &Held,
        pressed: Pressed,
    ) -> Forces {
        let primary = self.primary_friction(slip, mode, held);
        let fz = self.vertical_forces(primary);
        self.forces_given::<M, P>(y, primary, fz, pressed, mode, held)
    }

    /// The forces given the primary friction `primary`, the other vertical forces `fz` and
    /// the bodies the cloth presses on: the reaction that cancels `fz` on those, and the
    /// cloth's friction.
    #[inline(always)]
    fn forces_given<const M: usize, P: Pair<M>>(
        &self,
        y: &[f64; M],
        primary: Vec3,
        fz: [f64; 2],
        pressed: Pressed,
        mode: &Mode,
        held: &Held,
    ) -> Forces {
        let reaction = [0, 1].map(|i| if pressed[i] { -fz[i] } else { 0.0 });
        let cloth = [
            self.cloth_friction::<M, P>(y, 0, reaction[0], mode, held),
            self.cloth_friction::<M, P>(y, 1, reaction[1], mode, held),
        ];
        Forces {
            primary,
            cloth,
            reaction,
        }
    }

    /// The state's rates under forces `f`, the normal relative velocity being `vn` (the
    /// work's rate): each moving body's velocity and spin change by its inverse mass and
    /// inertia times the forces and their moments.
    #[inline(always)]
    pub(super) fn derivatives<const M: usize, P: Pair<M>>(&self, vn: f64, f: &Forces) -> [f64; M] {
        let mut dy = [0.0; M];
        let torque_p = [self.arm[0].cross(&f.primary), f.primary.cross(&self.arm[1])];
        let sign = [1.0, -1.0];
        for i in 0..moving_bodies::<M, P>() {
            let b = &self.bodies[i];
            // Body 0 of a pair with body 1 fixed is free (`Fixed`'s precondition).
            if (P::OTHER_FREE || i > 0) && b.is_fixed() {
                continue;
            }
            let c = f.cloth[i];
            let mut force = sign[i] * (f.primary - self.normal) + c;
            force.z += f.reaction[i];
            // The cloth's friction acts at the lowest point: (-z) x c = (c_y, -c_x, 0).
            let torque = torque_p[i] + Vec3::new(c.y, -c.x, 0.0);
            P::put(&mut dy, i, b.inv_mass * force, b.inv_inertia * torque);
        }
        dy[P::WORK] = vn;
        dy
    }
}
