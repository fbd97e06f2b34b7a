//! Slopes and events of one ball against an immovable body (a cushion or a jaw) while none of
//! its contacts is at zero slip: every step of most cushion impacts. The laws are those of
//! [`Contact::rhs_slipping`] and [`Contact::events_slipping`] with body 1 fixed, written for
//! the reduced state (the ball's velocity and spin, and the work) with the mode resolved once
//! per phase; the same operations in the same order, so bitwise the same values (tested).

use super::{Contact, Friction, K, Mode, slip_direction, slip_event};
use crate::ball::Vec3;
use crate::impact::dopri::Events;

/// Length of the reduced state: velocity, spin (units of V), work.
pub(super) const DIM: usize = 7;

/// One phase's laws for a ball against a fixed body.
#[derive(Clone, Copy, Debug)]
pub(super) struct AgainstFixed {
    n: Vec3,
    arm: Vec3,
    mu: f64,
    mu_cloth: f64,
    inv_mass: f64,
    inv_inertia: f64,
    on_cloth: bool,
    primary: Friction,
    cloth: Friction,
    zero: f64,
    compressing: bool,
    w_target: f64,
}

impl AgainstFixed {
    /// The laws of `c` under `mode`, if they apply: body 1 fixed and off the cloth, and no
    /// contact at zero slip.
    pub(super) fn new(c: &Contact, mode: &Mode) -> Option<AgainstFixed> {
        let [ball, other] = c.bodies;
        let fixed = other.inv_mass == 0.0 && other.inv_inertia == 0.0 && !other.on_cloth;
        let applies = fixed
            && !mode.friction.contains(&Friction::AtZero)
            && mode.friction[2] == Friction::Off;
        applies.then_some(AgainstFixed {
            n: c.normal,
            arm: c.arm[0],
            mu: c.mu,
            mu_cloth: c.mu_cloth,
            inv_mass: ball.inv_mass,
            inv_inertia: ball.inv_inertia,
            on_cloth: ball.on_cloth,
            primary: mode.friction[0],
            cloth: mode.friction[1],
            zero: mode.zero,
            compressing: mode.compressing,
            w_target: mode.w_target,
        })
    }

    /// Velocity of the contact point at the nose, and its normal part (positive approaching).
    #[inline(always)]
    fn contact_velocity(&self, v: Vec3, w: Vec3) -> (Vec3, f64) {
        let u = v + w.cross(&self.arm);
        (u, u.dot(&self.n))
    }

    /// Friction at the nose, per unit normal impulse, given the slip there.
    #[inline(always)]
    fn primary_friction(&self, slip: Vec3) -> Vec3 {
        match self.primary {
            Friction::Slip(r) => -self.mu * slip_direction(slip, r, self.zero),
            Friction::Starting(r) => -self.mu * r,
            _ => Vec3::zeros(),
        }
    }

    /// Vertical force on the ball besides the cloth's, per unit normal impulse.
    #[inline(always)]
    fn vertical_force(&self, primary: Vec3) -> f64 {
        primary.z - self.n.z
    }

    /// The slips at the nose and at the cloth (and none under the fixed body) of the reduced
    /// state `z`, as [`Contact::local`] forms them.
    #[inline(always)]
    pub(super) fn slips(&self, z: &[f64; DIM]) -> [Vec3; 3] {
        let v = Vec3::new(z[0], z[1], z[2]);
        let w = Vec3::new(z[3], z[4], z[5]);
        let (u, vn) = self.contact_velocity(v, w);
        [
            u - vn * self.n,
            Vec3::new(v.x - w.y, v.y + w.x, 0.0),
            Vec3::zeros(),
        ]
    }

    /// The slopes of the reduced state `z`.
    #[inline(always)]
    pub(super) fn slopes(&self, z: &[f64; DIM]) -> [f64; DIM] {
        let v = Vec3::new(z[0], z[1], z[2]);
        let w = Vec3::new(z[3], z[4], z[5]);
        let (u, vn) = self.contact_velocity(v, w);
        let primary = self.primary_friction(u - vn * self.n);
        let fz = self.vertical_force(primary);
        let reaction = if self.on_cloth && v.z <= 0.0 {
            (-fz).max(0.0)
        } else {
            0.0
        };
        let c = match self.cloth {
            Friction::Slip(r) => {
                let slip = Vec3::new(v.x - w.y, v.y + w.x, 0.0);
                -self.mu_cloth * reaction * slip_direction(slip, r, self.zero)
            }
            Friction::Starting(r) => -self.mu_cloth * reaction * r,
            _ => Vec3::zeros(),
        };
        let mut force = (primary - self.n) + c;
        force.z += reaction;
        let torque = self.arm.cross(&primary) + Vec3::new(c.y, -c.x, 0.0);
        let dv = self.inv_mass * force;
        let dw = self.inv_inertia * torque;
        [dv.x, dv.y, dv.z, dw.x, dw.y, dw.z, vn]
    }

    /// The event function of the support: the ball's vertical speed while it is up, the
    /// vertical force on it while it is down.
    #[inline(always)]
    fn support_event(&self, vz: f64, slip: Vec3) -> f64 {
        if vz > 0.0 {
            vz
        } else {
            self.vertical_force(self.primary_friction(slip))
        }
    }

    /// The event functions at the reduced state `z`, as [`Contact::events`] orders them.
    #[inline(always)]
    pub(super) fn events(&self, z: &[f64; DIM]) -> [f64; K] {
        let v = Vec3::new(z[0], z[1], z[2]);
        let w = Vec3::new(z[3], z[4], z[5]);
        let (u, vn) = self.contact_velocity(v, w);
        let mut g = [0.0; K];
        if self.compressing {
            g[0] = vn;
        } else {
            g[1] = z[DIM - 1] - self.w_target;
        }
        let slip = u - vn * self.n;
        g[2] = slip_event(self.primary, slip, self.zero);
        g[3] = slip_event(self.cloth, Vec3::new(v.x - w.y, v.y + w.x, 0.0), self.zero);
        if self.on_cloth {
            g[5] = self.support_event(v.z, slip);
        }
        g
    }

    /// Event `e` alone at the reduced state `z` (the same value as in [`Self::events`]),
    /// computing only what it needs.
    #[inline(always)]
    fn event(&self, z: &[f64; DIM], e: usize) -> f64 {
        let v = Vec3::new(z[0], z[1], z[2]);
        let w = Vec3::new(z[3], z[4], z[5]);
        let slip = || {
            let (u, vn) = self.contact_velocity(v, w);
            u - vn * self.n
        };
        match e {
            0 if self.compressing => self.contact_velocity(v, w).1,
            1 if !self.compressing => z[DIM - 1] - self.w_target,
            2 => slip_event(self.primary, slip(), self.zero),
            3 => slip_event(self.cloth, Vec3::new(v.x - w.y, v.y + w.x, 0.0), self.zero),
            5 if self.on_cloth => self.support_event(v.z, slip()),
            _ => 0.0,
        }
    }
}

impl Events<DIM, K> for AgainstFixed {
    fn all(&self, z: &[f64; DIM]) -> [f64; K] {
        self.events(z)
    }

    fn one(&self, z: &[f64; DIM], e: usize) -> f64 {
        self.event(z, e)
    }
}
