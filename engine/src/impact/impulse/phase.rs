//! One phase of an impact: the laws under a mode fixed for the phase, resolved once (a phase
//! with no contact at zero slip, most of them, reads no Coulomb solve), and their integration
//! to the next switch.

use super::establish::establish;
use super::events::K;
use super::laws::{Held, NONE_HELD};
use super::mode::Mode;
use super::pair::Pair;
use super::problem::Impact;
use crate::ball::Vec3;
use crate::impact::dopri::{self, ErrorMeasure, Events, Stop};
use std::marker::PhantomData;

/// Event functions (velocities in units of V) are located to this.
const ROOT_TOLERANCE: f64 = 1e-12;
/// Steps after which a phase counts as crawling.
pub(super) const CRAWL_STEPS: usize = 5000;

/// The laws of one phase: `contact` under `mode`, on the state of pair `P`. `AT_ZERO` says
/// whether a contact is at zero slip, so that its friction needs the Coulomb solve at every
/// evaluation; without one, the slopes are those of the slips' laws alone.
pub(super) struct PhaseLaws<'a, const M: usize, P: Pair<M>, const AT_ZERO: bool> {
    /// The impact.
    pub contact: &'a Impact,
    /// The phase's mode.
    pub mode: &'a Mode,
    pair: PhantomData<P>,
}

impl<'a, const M: usize, P: Pair<M>, const AT_ZERO: bool> PhaseLaws<'a, M, P, AT_ZERO> {
    /// The laws of `contact` under `mode`; `AT_ZERO` must say whether `mode` has a contact
    /// at zero slip.
    pub fn new(contact: &'a Impact, mode: &'a Mode) -> Self {
        debug_assert_eq!(AT_ZERO, mode.any_at_zero());
        PhaseLaws {
            contact,
            mode,
            pair: PhantomData,
        }
    }

    /// The slopes of the state `y`: its rates per unit normal impulse.
    #[inline(always)]
    pub fn slopes(&self, y: &[f64; M]) -> [f64; M] {
        let (c, mode) = (self.contact, self.mode);
        if AT_ZERO {
            let loc = c.local::<M, P>(y);
            let held: Held = c.at_zero::<M, P>(y, &loc, mode).0;
            let f = c.forces_with::<M, P>(y, loc.slip[0], mode, &held);
            c.derivatives::<M, P>(loc.vn, &f)
        } else {
            let (u, vn) = c.primary_motion::<M, P>(y);
            let f = c.forces_with::<M, P>(y, u - vn * c.normal, mode, &NONE_HELD);
            c.derivatives::<M, P>(vn, &f)
        }
    }
}

/// One phase to integrate: its mode, start, first step, and whether a starting slip may be
/// established by Heun's step ([`establish`]).
struct Run<'a> {
    mode: &'a Mode,
    p: f64,
    h: f64,
    establish: bool,
}

impl Run<'_> {
    /// The phase from state `y` with slopes `f`, events `g`, slips `slips` and step error
    /// `measure`.
    fn go<const M: usize, F, G, S, X>(
        &self,
        y: [f64; M],
        f: &F,
        g: &G,
        slips: &S,
        measure: &X,
        mut on_step: impl FnMut(f64, &[f64; M]),
    ) -> dopri::Phase<M>
    where
        F: Fn(&[f64; M]) -> [f64; M],
        G: Events<M, K>,
        S: Fn(&[f64; M]) -> [Vec3; 3],
        X: ErrorMeasure<M>,
    {
        let shortcut = if self.establish {
            establish(self.mode, &y, f, g, slips, measure)
        } else {
            None
        };
        if let Some((dp, y1, ev)) = shortcut {
            on_step(self.p + dp, &y1);
            return dopri::Phase {
                x: self.p + dp,
                y: y1,
                stop: Stop::Event(ev.index()),
                h: self.h,
                steps: 1,
            };
        }
        dopri::integrate(
            f,
            g,
            self.p,
            y,
            self.h,
            measure,
            ROOT_TOLERANCE,
            CRAWL_STEPS,
            on_step,
        )
    }
}

impl Impact {
    /// Integrates one phase under `mode` from impulse `p`, state `y` (of pair `P`), first step
    /// `h`, to tolerance `tol`, until an event (or a crawl); `on_step` sees every accepted
    /// point. `establish` allows Heun's step for a starting slip.
    #[allow(clippy::too_many_arguments)]
    pub(super) fn integrate_phase<const M: usize, P: Pair<M>>(
        &self,
        mode: &Mode,
        p: f64,
        y: [f64; M],
        h: f64,
        tol: f64,
        establish: bool,
        on_step: impl FnMut(f64, &[f64; M]),
    ) -> dopri::Phase<M> {
        let run = Run {
            mode,
            p,
            h,
            establish,
        };
        let slips = |y: &[f64; M]| self.local::<M, P>(y).slip;
        let measure = self.measure(tol, slips);
        if mode.any_at_zero() {
            let laws = PhaseLaws::<M, P, true>::new(self, mode);
            run.go(y, &|y| laws.slopes(y), &laws, &slips, &measure, on_step)
        } else {
            let laws = PhaseLaws::<M, P, false>::new(self, mode);
            run.go(y, &|y| laws.slopes(y), &laws, &slips, &measure, on_step)
        }
    }
}
