//! The state of an impact, in units of the approach speed V (velocities / V, spins R / V,
//! work / (M V^2)), and the two ways it holds the body pair: both bodies free, or the other
//! body (body 1) fixed at rest, as a cushion is. A fixed body's velocities stay zero, so its
//! state leaves them out and the laws drop its terms: written once, generic over [`Pair`],
//! the compiler specialises them for each.

use crate::ball::Vec3;

/// Length of the whole state: each body's velocity and spin, then the work of the normal
/// impulse, W(P) = integral of v_n dP (thesis eq. 6.12).
pub(super) const N: usize = 13;

/// Offsets of each body's velocity and spin in the whole state.
const VEL: [usize; 2] = [0, 6];
const SPIN: [usize; 2] = [3, 9];
/// Offset of the work in the whole state.
pub(super) const WORK: usize = N - 1;

/// How a state of `M` entries holds the two bodies.
pub(super) trait Pair<const M: usize>: Copy {
    /// Whether body 1 moves (its velocity and spin are in the state).
    const OTHER_FREE: bool;
    /// Offset of the work.
    const WORK: usize = M - 1;

    /// Body `i`'s velocity (zero for a fixed body 1).
    fn vel(y: &[f64; M], i: usize) -> Vec3;

    /// Body `i`'s spin (zero for a fixed body 1).
    fn spin(y: &[f64; M], i: usize) -> Vec3;

    /// Sets body `i`'s velocity and spin (body 0, or a free body 1).
    fn put(y: &mut [f64; M], i: usize, vel: Vec3, spin: Vec3);

    /// The whole state.
    fn whole(y: &[f64; M]) -> [f64; N];

    /// This pair's part of the whole state `y`.
    fn part(y: &[f64; N]) -> [f64; M];
}

/// Both bodies free: the whole state.
#[derive(Clone, Copy, Debug)]
pub(super) struct Free;

/// Body 1 fixed at rest (a cushion), body 0 free: body 0's velocity and spin, and the work.
#[derive(Clone, Copy, Debug)]
pub(super) struct Fixed;

/// Length of the state of a ball against a fixed body.
pub(super) const FIXED_DIM: usize = 7;

#[inline(always)]
fn v3<const M: usize>(y: &[f64; M], i: usize) -> Vec3 {
    Vec3::new(y[i], y[i + 1], y[i + 2])
}

#[inline(always)]
fn set<const M: usize>(y: &mut [f64; M], i: usize, v: Vec3) {
    y[i] = v.x;
    y[i + 1] = v.y;
    y[i + 2] = v.z;
}

impl Pair<N> for Free {
    const OTHER_FREE: bool = true;

    #[inline(always)]
    fn vel(y: &[f64; N], i: usize) -> Vec3 {
        v3(y, VEL[i])
    }

    #[inline(always)]
    fn spin(y: &[f64; N], i: usize) -> Vec3 {
        v3(y, SPIN[i])
    }

    #[inline(always)]
    fn put(y: &mut [f64; N], i: usize, vel: Vec3, spin: Vec3) {
        set(y, VEL[i], vel);
        set(y, SPIN[i], spin);
    }

    #[inline(always)]
    fn whole(y: &[f64; N]) -> [f64; N] {
        *y
    }

    #[inline(always)]
    fn part(y: &[f64; N]) -> [f64; N] {
        *y
    }
}

/// The entries of the whole state that the state of a ball against a fixed body keeps.
const KEPT: [usize; FIXED_DIM] = [0, 1, 2, 3, 4, 5, WORK];

impl Pair<FIXED_DIM> for Fixed {
    const OTHER_FREE: bool = false;

    #[inline(always)]
    fn vel(y: &[f64; FIXED_DIM], i: usize) -> Vec3 {
        if i == 0 { v3(y, 0) } else { Vec3::zeros() }
    }

    #[inline(always)]
    fn spin(y: &[f64; FIXED_DIM], i: usize) -> Vec3 {
        if i == 0 { v3(y, 3) } else { Vec3::zeros() }
    }

    #[inline(always)]
    fn put(y: &mut [f64; FIXED_DIM], i: usize, vel: Vec3, spin: Vec3) {
        debug_assert_eq!(i, 0, "a fixed body has no velocities to set");
        set(y, 0, vel);
        set(y, 3, spin);
    }

    #[inline(always)]
    fn whole(y: &[f64; FIXED_DIM]) -> [f64; N] {
        let mut w = [0.0; N];
        for (j, &i) in KEPT.iter().enumerate() {
            w[i] = y[j];
        }
        w
    }

    #[inline(always)]
    fn part(y: &[f64; N]) -> [f64; FIXED_DIM] {
        KEPT.map(|i| y[i])
    }
}

/// Number of bodies whose velocities are in the state of pair `P`.
#[inline(always)]
pub(super) const fn moving_bodies<const M: usize, P: Pair<M>>() -> usize {
    if P::OTHER_FREE { 2 } else { 1 }
}
