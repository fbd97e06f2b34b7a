//! Coulomb's law at contacts whose slip is zero (thesis §6.1.2.1, §6.2.2.1, with Coulomb's
//! stick in place of the thesis's "no stick"; see [`super`]): those that can hold do, with the
//! frictions that keep their slips at zero (one small linear solve), and the others creep out
//! of zero at mu N in the one direction their friction leaves growing.

// Small dense linear algebra reads best with explicit indices.
#![allow(clippy::needless_range_loop)]

use super::laws::{Forces, Held, Local, NONE_HELD, Pressed};
use super::mode::{Friction, Mode, PRIMARY};
use super::pair::Pair;
use super::problem::Impact;
use crate::ball::Vec3;

/// Most sets of pressed balls a Coulomb solve tries: there are four (each ball pressed or
/// not), and a solve that lands on another set than it assumed moves to that one.
const SUPPORT_PATTERNS: usize = 4;

/// Solves the small dense system `a x = b` (n <= 6) by Gaussian elimination with partial
/// pivoting; `None` if it is singular.
fn solve_dense(a: &mut [[f64; 6]; 6], b: &mut [f64; 6], n: usize) -> Option<()> {
    for c in 0..n {
        let p = (c..n).max_by(|&i, &j| a[i][c].abs().total_cmp(&a[j][c].abs()))?;
        if a[p][c].abs() < 1e-14 {
            return None;
        }
        a.swap(c, p);
        b.swap(c, p);
        for r in c + 1..n {
            let f = a[r][c] / a[c][c];
            for k in c..n {
                a[r][k] -= f * a[c][k];
            }
            b[r] -= f * b[c];
        }
    }
    for c in (0..n).rev() {
        let s: f64 = (c + 1..n).map(|k| a[c][k] * b[k]).sum();
        b[c] = (b[c] - s) / a[c][c];
    }
    Some(())
}

/// A contact's slip rate (in its tangent basis) as an affine function of its friction F:
/// `at_zero + per_unit F`.
#[derive(Clone, Copy, Debug)]
struct Affine {
    at_zero: [f64; 2],
    per_unit: [[f64; 2]; 2],
}

/// How a contact's slip creeps out of zero, or, followed quasi-statically, changes along its
/// steady direction ([`Impact::creep`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Creep {
    /// The slip's direction.
    pub dir: Vec3,
    /// The rate lambda at which the slip grows along `dir` (fraction of V per unit impulse;
    /// negative if it shrinks, NaN if a shrinking slip has no steady direction).
    pub rate: f64,
    /// The size of the slip's rate without the contact's friction, |d|: the rate at which a
    /// slip of size s slipping freely turns towards `dir` is about |d| / s.
    pub drive: f64,
}

fn unit_or(v: Vec3, fallback: Vec3) -> Vec3 {
    let n = v.norm();
    if n > 0.0 { v / n } else { fallback }
}

impl Impact {
    /// Two unit vectors spanning contact `k`'s tangent plane.
    fn tangents(&self, k: usize) -> [Vec3; 2] {
        if k == PRIMARY {
            let t = unit_or(
                self.normal.cross(&Vec3::z()),
                self.normal.cross(&Vec3::x()).normalize(),
            );
            [t, self.normal.cross(&t)]
        } else {
            [Vec3::x(), Vec3::y()]
        }
    }

    /// Normal force (per unit dP) at contact `k`.
    pub(super) fn normal_force(&self, f: &Forces, k: usize) -> f64 {
        if k == PRIMARY { 1.0 } else { f.reaction[k - 1] }
    }

    /// Rate of change of contact `k`'s slip, given the state's rates `dy`.
    pub(super) fn slip_rate<const M: usize, P: Pair<M>>(&self, dy: &[f64; M], k: usize) -> Vec3 {
        if k == PRIMARY {
            let (du, dn) = self.primary_motion::<M, P>(dy);
            du - dn * self.normal
        } else {
            Self::cloth_slip::<M, P>(dy, k - 1)
        }
    }

    /// Slip rates (in each contact's tangent basis) of the contacts in `which`, when the
    /// contacts at zero slip exert the frictions `held` and the cloth presses on the bodies
    /// `pressed` (so that the rates are affine in the frictions).
    fn rates<const M: usize, P: Pair<M>>(
        &self,
        y: &[f64; M],
        loc: &Local,
        mode: &Mode,
        held: &Held,
        which: &[usize],
        pressed: Pressed,
    ) -> [f64; 6] {
        let forces = self.forces_under::<M, P>(y, loc.slip[PRIMARY], mode, held, pressed);
        let dy = self.derivatives::<M, P>(loc.vn, &forces);
        self.in_tangents(which, |k| self.slip_rate::<M, P>(&dy, k))
    }

    /// The vectors `v(k)` of the contacts in `which`, each in its tangent basis, in order.
    fn in_tangents(&self, which: &[usize], v: impl Fn(usize) -> Vec3) -> [f64; 6] {
        let mut r = [0.0; 6];
        for (j, &k) in which.iter().enumerate() {
            let (d, t) = (v(k), self.tangents(k));
            r[2 * j] = d.dot(&t[0]);
            r[2 * j + 1] = d.dot(&t[1]);
        }
        r
    }

    /// Sets `held[k]` of each contact k in `which` from its tangent components in `x` (as
    /// [`Impact::in_tangents`] orders them).
    fn set_from_tangents(&self, which: &[usize], x: &[f64; 6], held: &mut Held) {
        for (j, &k) in which.iter().enumerate() {
            let t = self.tangents(k);
            held[k] = x[2 * j] * t[0] + x[2 * j + 1] * t[1];
        }
    }

    /// The bodies the cloth presses on when the contacts at zero slip exert `held`: a
    /// primary friction pulling a ball down presses it (thesis §6.1.2).
    fn pressed_under<const M: usize, P: Pair<M>>(
        &self,
        y: &[f64; M],
        loc: &Local,
        mode: &Mode,
        held: &Held,
    ) -> Pressed {
        let fp = self.primary_friction(loc.slip[PRIMARY], mode, held);
        self.pressed_by::<M, P>(y, self.vertical_forces(fp))
    }

    /// Sets in `held` the frictions that keep the slip rates of the contacts in `which` at
    /// zero, the other frictions in `held` fixed. The cloth's reaction is unilateral, so the
    /// rates are affine in these frictions only while the cloth presses on the same balls:
    /// the frictions are solved for with the cloth pressing on `pressed` (one small linear
    /// solve), and again with the balls they press if those differ (the reaction being
    /// continuous, frictions that press the balls they were solved for are the answer).
    /// `pressed` is left as the frictions found press. For a single contact, also returns its
    /// rates at zero friction and their change per unit friction along each tangent under
    /// `pressed` (what [`Impact::creep`] needs, so that it need not probe them again).
    fn hold<const M: usize, P: Pair<M>>(
        &self,
        y: &[f64; M],
        loc: &Local,
        mode: &Mode,
        held: &mut Held,
        which: &[usize],
        pressed: &mut Pressed,
    ) -> Option<Affine> {
        let mut single = None;
        for attempt in 0..SUPPORT_PATTERNS {
            single = self.hold_under::<M, P>(y, loc, mode, held, which, *pressed);
            let now = self.pressed_under::<M, P>(y, loc, mode, held);
            if now == *pressed || attempt + 1 == SUPPORT_PATTERNS {
                break;
            }
            *pressed = now;
        }
        single
    }

    /// [`Impact::hold`] with the cloth pressing on `pressed`.
    fn hold_under<const M: usize, P: Pair<M>>(
        &self,
        y: &[f64; M],
        loc: &Local,
        mode: &Mode,
        held: &mut Held,
        which: &[usize],
        pressed: Pressed,
    ) -> Option<Affine> {
        let n = 2 * which.len();
        for &k in which {
            held[k] = Vec3::zeros();
        }
        let (base, mut a) = self.response::<M, P>(y, loc, mode, held, which, pressed);
        let single = (n == 2).then(|| Affine {
            at_zero: [base[0], base[1]],
            per_unit: [[a[0][0], a[0][1]], [a[1][0], a[1][1]]],
        });
        let mut b = [0.0; 6];
        for row in 0..n {
            b[row] = -base[row];
        }
        if solve_dense(&mut a, &mut b, n).is_some() {
            self.set_from_tangents(which, &b, held);
        }
        single
    }

    /// The slip rates (tangent bases) of the contacts in `which` with their frictions zero,
    /// the others' `held` (which must hold zero at `which`), and their change per unit
    /// friction along each tangent, the cloth pressing on `pressed`: the rates are affine in
    /// these frictions, `base + a F`.
    fn response<const M: usize, P: Pair<M>>(
        &self,
        y: &[f64; M],
        loc: &Local,
        mode: &Mode,
        held: &Held,
        which: &[usize],
        pressed: Pressed,
    ) -> ([f64; 6], [[f64; 6]; 6]) {
        let n = 2 * which.len();
        let base = self.rates::<M, P>(y, loc, mode, held, which, pressed);
        let mut a = [[0.0; 6]; 6];
        for col in 0..n {
            let (j, c) = (col / 2, col % 2);
            let mut probe = *held;
            probe[which[j]] = self.tangents(which[j])[c];
            let r = self.rates::<M, P>(y, loc, mode, &probe, which, pressed);
            for row in 0..n {
                a[row][col] = r[row] - base[row];
            }
        }
        (base, a)
    }

    /// Stops the residual slips of the contacts that hold: a slip within the zero band counts
    /// as zero, and a contact holding it keeps it where it is, so that its friction, pushing
    /// along the residual, could do positive work over the whole impact (an elastic cushion's
    /// stick from the start gained 4.8e-8 of the energy at each impact, fuzz seed 20261214,
    /// scene 145456). Coulomb friction takes such a slip to zero within an impulse of about
    /// s / (mu K) (1e-7 of the impact's), dissipating s^T K^-1 s / 2 (K the contacts'
    /// compliance, Stronge 2000 §2.3): the friction impulse that does so is applied here at
    /// once, with the cloth's reaction that keeps a ball on it there. Returns whether `y`
    /// changed.
    pub(super) fn stop_residual_slips<const M: usize, P: Pair<M>>(
        &self,
        y: &mut [f64; M],
        mode: &Mode,
    ) -> bool {
        if !mode.friction.contains(&Friction::AtZero) {
            return false;
        }
        let loc = self.local::<M, P>(y);
        let creeping = self.at_zero::<M, P>(y, &loc, mode).1;
        let mut which = [0usize; 3];
        let mut n = 0;
        for k in 0..3 {
            let holds = mode.friction[k] == Friction::AtZero && creeping[k].is_none();
            if holds && loc.slip[k] != Vec3::zeros() {
                which[n] = k;
                n += 1;
            }
        }
        if n == 0 {
            return false;
        }
        let which = &which[..n];
        // Only these frictions act, and the cloth keeps a ball on it there (its vertical
        // velocity unchanged): a reaction that does no work, so that J's compliance K is
        // symmetric and the stop dissipates. (A slipping cloth contact's friction, following
        // a reaction that may pull, could push along its slip.)
        let mut only = *mode;
        for (k, law) in only.friction.iter_mut().enumerate() {
            if !which.contains(&k) {
                *law = Friction::Off;
            }
        }
        let pressed = [0, 1].map(|i| self.bodies[i].on_cloth && P::vel(y, i).z <= 0.0);
        let (_, mut a) = self.response::<M, P>(y, &loc, &only, &NONE_HELD, which, pressed);
        // The friction impulse J with a J = -s: the slips' change per unit friction is their
        // change per unit friction impulse.
        let mut b = self.in_tangents(which, |k| -loc.slip[k]);
        if solve_dense(&mut a, &mut b, 2 * n).is_none() {
            return false;
        }
        let mut impulse = NONE_HELD;
        self.set_from_tangents(which, &b, &mut impulse);
        // The state's change is the rates' change with the frictions J against without.
        let rate = |h: &Held| {
            let f = self.forces_under::<M, P>(y, loc.slip[PRIMARY], &only, h, pressed);
            self.derivatives::<M, P>(loc.vn, &f)
        };
        let (with, without) = (rate(&impulse), rate(&NONE_HELD));
        for ((v, w), wo) in y.iter_mut().zip(with).zip(without) {
            *v += w - wo;
        }
        true
    }

    /// How contact `k`, at zero slip and unable to hold, creeps out of zero (the other
    /// frictions in `held` fixed). Its slip rate is affine in its friction F while the cloth
    /// presses on the same balls (`pressed`; `known`, if given, is that affine map): rate =
    /// d + B F. With Coulomb friction F = -c s (c = mu N) a slip growing as lambda s needs
    /// (lambda I + c B) s = d with |s| = 1 and lambda >= 0; |(lambda I + c B)^-1 d| falls with
    /// lambda, so lambda is found in a bracket (by Newton's method, safeguarded by bisection;
    /// lambda = 0, the edge of holding, gives the direction opposite to the holding force, so
    /// friction is continuous there). With `slowing`, a contact that could hold is taken to
    /// be slipping, slowly, down to zero (a slip followed quasi-statically,
    /// [`Friction::QuasiStatic`]): the same equation with lambda < 0 gives the direction in
    /// which its slip shrinks along itself. A creeping primary friction that presses other
    /// balls than `pressed` is found again with those (as in [`Impact::hold`]); `pressed` is
    /// left as it presses. Returns the friction and the creep.
    #[allow(clippy::too_many_arguments)]
    fn creep<const M: usize, P: Pair<M>>(
        &self,
        y: &[f64; M],
        loc: &Local,
        mode: &Mode,
        held: &Held,
        k: usize,
        mut known: Option<Affine>,
        pressed: &mut Pressed,
        slowing: bool,
    ) -> (Vec3, Creep) {
        let mut out = (
            Vec3::zeros(),
            Creep {
                dir: Vec3::zeros(),
                rate: 0.0,
                drive: 0.0,
            },
        );
        for attempt in 0..SUPPORT_PATTERNS {
            out = self.creep_under::<M, P>(y, loc, mode, held, k, known.take(), *pressed, slowing);
            if k != PRIMARY {
                // The cloth's friction does not move the balls vertically.
                break;
            }
            let mut with = *held;
            with[k] = out.0;
            let now = self.pressed_under::<M, P>(y, loc, mode, &with);
            if now == *pressed || attempt + 1 == SUPPORT_PATTERNS {
                break;
            }
            *pressed = now;
        }
        out
    }

    /// [`Impact::creep`] with the cloth pressing on `pressed`.
    #[allow(clippy::too_many_arguments)]
    fn creep_under<const M: usize, P: Pair<M>>(
        &self,
        y: &[f64; M],
        loc: &Local,
        mode: &Mode,
        held: &Held,
        k: usize,
        known: Option<Affine>,
        pressed: Pressed,
        slowing: bool,
    ) -> (Vec3, Creep) {
        let t = self.tangents(k);
        let mut probe = *held;
        probe[k] = Vec3::zeros();
        let cap = self.coefficient(k)
            * self.normal_force(
                &self.forces_with::<M, P>(y, loc.slip[PRIMARY], mode, &probe),
                k,
            );
        let Affine {
            at_zero: d,
            per_unit: b,
        } = known.unwrap_or_else(|| {
            let d6 = self.rates::<M, P>(y, loc, mode, &probe, &[k], pressed);
            let d = [d6[0], d6[1]];
            let mut b = [[0.0; 2]; 2];
            for c in 0..2 {
                probe[k] = t[c];
                let r = self.rates::<M, P>(y, loc, mode, &probe, &[k], pressed);
                b[0][c] = r[0] - d[0];
                b[1][c] = r[1] - d[1];
            }
            Affine {
                at_zero: d,
                per_unit: b,
            }
        });
        // s(lambda) = M^-1 d with M = lambda I + c B, and M^-1 s (for d s / d lambda = -M^-1 s).
        let s_of = |lambda: f64| {
            let (a, bb, c, dd) = (
                lambda + cap * b[0][0],
                cap * b[0][1],
                cap * b[1][0],
                lambda + cap * b[1][1],
            );
            let det = a * dd - bb * c;
            let s = [(dd * d[0] - bb * d[1]) / det, (a * d[1] - c * d[0]) / det];
            let ms = [(dd * s[0] - bb * s[1]) / det, (a * s[1] - c * s[0]) / det];
            (s, ms)
        };
        let norm = |v: [f64; 2]| (v[0] * v[0] + v[1] * v[1]).sqrt();
        // Newton's method on 1/|s| - 1, which rises with lambda (nearly linearly: |s| ~ |d| /
        // lambda for large lambda), from `start`, kept strictly inside the bracket [lo, hi] of
        // the root, halving it whenever a step would not be, and stopping at the width a
        // bisection of the whole bracket would end at: a handful of steps reach rounding.
        let newton = |mut lo: f64, mut hi: f64, start: f64| {
            let width = (hi - lo) * f64::EPSILON;
            let mut lambda = start;
            for _ in 0..100 {
                let (s, ms) = s_of(lambda);
                let ns = norm(s);
                let g = 1.0 / ns - 1.0;
                if g == 0.0 {
                    break;
                } else if g < 0.0 {
                    lo = lambda;
                } else {
                    hi = lambda;
                }
                let slope = (s[0] * ms[0] + s[1] * ms[1]) / (ns * ns * ns);
                let mut next = lambda - g / slope;
                if !(next > lo && next < hi) {
                    next = 0.5 * (lo + hi);
                }
                let done = (next - lambda).abs() <= 1e-15 * next.abs() || hi - lo <= width;
                lambda = next;
                if done {
                    break;
                }
            }
            lambda
        };
        let mut lambda = 0.0;
        if norm(s_of(0.0).0) > 1.0 {
            lambda = newton(
                0.0,
                norm(d) + cap * (b[0][0].abs() + b[1][1].abs()) + 1.0,
                0.0,
            );
        } else if slowing {
            // A slip coming down to zero: lambda < 0, above the largest (real, negative) root
            // of det(lambda I + c B), where |s| is unbounded. Without a root in that bracket
            // (B's eigenvalues complex, or not both positive) the slip has no steady
            // direction: rate NaN.
            let (tr, det) = (
                cap * (b[0][0] + b[1][1]),
                cap * cap * (b[0][0] * b[1][1] - b[0][1] * b[1][0]),
            );
            // (A double root, as the cloth's isotropic B gives, may round to complex ones.)
            let disc = tr * tr - 4.0 * det;
            let pole = 0.5 * (disc.max(0.0).sqrt() - tr);
            lambda = if tr > 0.0 && det > 0.0 && pole < 0.0 {
                newton(pole, 0.0, 0.0)
            } else {
                f64::NAN
            };
            let found = (norm(s_of(lambda).0) - 1.0).abs() <= 1e-6;
            if !found {
                lambda = f64::NAN;
            }
        }
        let s = s_of(if lambda.is_nan() { 0.0 } else { lambda }).0;
        let dir = unit_or(s[0] * t[0] + s[1] * t[1], t[0]);
        let creep = Creep {
            dir,
            rate: lambda,
            drive: norm(d),
        };
        (-cap * dir, creep)
    }

    /// Frictions of the contacts at zero slip, by Coulomb's law taken jointly: those that can
    /// hold do (one linear solve for all of them), the others creep at mu N (one at a time,
    /// each release changing what the rest need); and of the slips followed quasi-statically,
    /// found first. Also returns, per contact, its creep if it creeps (or is followed so).
    #[inline(always)]
    pub(super) fn at_zero<const M: usize, P: Pair<M>>(
        &self,
        y: &[f64; M],
        loc: &Local,
        mode: &Mode,
    ) -> ([Vec3; 3], [Option<Creep>; 3]) {
        let mut held = [Vec3::zeros(); 3];
        let mut creeping: [Option<Creep>; 3] = [None; 3];
        // The balls the cloth presses on without the frictions to be found: where to start.
        let mut pressed = self.pressed_under::<M, P>(y, loc, mode, &held);
        // Slips followed quasi-statically slip at mu N, in their steady directions, whatever
        // the contacts at zero do.
        for k in 0..3 {
            if let Friction::QuasiStatic(..) = mode.friction[k] {
                let (force, creep) =
                    self.creep::<M, P>(y, loc, mode, &held, k, None, &mut pressed, true);
                held[k] = force;
                creeping[k] = Some(creep);
            }
        }
        for _ in 0..3 {
            let mut which_at = [0usize; 3];
            let mut n = 0;
            for k in 0..3 {
                if mode.friction[k] == Friction::AtZero && creeping[k].is_none() {
                    which_at[n] = k;
                    n += 1;
                }
            }
            if n == 0 {
                break;
            }
            // Alone at zero, the contact's rates as `hold` probed them are those `creep` needs
            // (the other frictions are the same).
            let single = self.hold::<M, P>(y, loc, mode, &mut held, &which_at[..n], &mut pressed);
            let f = self.forces_with::<M, P>(y, loc.slip[PRIMARY], mode, &held);
            let excess = |k: usize| held[k].norm() - self.coefficient(k) * self.normal_force(&f, k);
            let worst = which_at[..n]
                .iter()
                .copied()
                .filter(|&k| excess(k) > 0.0)
                .max_by(|&a, &b| excess(a).total_cmp(&excess(b)));
            let Some(k) = worst else { break };
            let (force, creep) =
                self.creep::<M, P>(y, loc, mode, &held, k, single, &mut pressed, false);
            held[k] = force;
            creeping[k] = Some(creep);
        }
        (held, creeping)
    }

    /// All forces under `mode` (contacts at zero slip by [`Impact::at_zero`]).
    pub(super) fn forces<const M: usize, P: Pair<M>>(
        &self,
        y: &[f64; M],
        loc: &Local,
        mode: &Mode,
    ) -> Forces {
        if !mode.any_at_zero() {
            return self.forces_with::<M, P>(y, loc.slip[PRIMARY], mode, &NONE_HELD);
        }
        let (held, _) = self.at_zero::<M, P>(y, loc, mode);
        self.forces_with::<M, P>(y, loc.slip[PRIMARY], mode, &held)
    }
}
