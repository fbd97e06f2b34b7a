//! A slip creeping robustly out of zero ([`Friction::Starting`]) counts as established once it
//! reaches `ESTABLISHED_PER_ZERO` zero bands: an impulse so small that the slopes barely change
//! over it. The phase is taken as one step of Heun's method, of the length the slip's rate
//! predicts, rather than a full step of the integrator and a search for the event.

use super::events::{Event, K};
use super::mode::{Friction, Mode};
use crate::ball::Vec3;
use crate::impact::dopri::{ErrorMeasure, Events};

/// The step that establishes the first of the slips starting in `mode`, from state `y` with
/// slopes `f`, events `g`, slips (of a state or of its rate) `slips`: the impulse taken, the
/// state reached and the event (that slip's). `None`, to integrate the phase as any other, if
/// no slip is starting, if the step's error estimate (Euler's, which bounds Heun's) exceeds
/// `measure`'s tolerance, or if another event falls within it.
pub(super) fn establish<const M: usize, F, G, S, X>(
    mode: &Mode,
    y: &[f64; M],
    f: &F,
    g: &G,
    slips: &S,
    measure: &X,
) -> Option<(f64, [f64; M], Event)>
where
    F: Fn(&[f64; M]) -> [f64; M],
    G: Events<M, K>,
    S: Fn(&[f64; M]) -> [Vec3; 3],
    X: ErrorMeasure<M>,
{
    if !mode
        .friction
        .iter()
        .any(|law| matches!(law, Friction::Starting(_)))
    {
        return None;
    }
    let f0 = f(y);
    // The slips are linear in the state: those of the slopes are their rates.
    let (now, rates) = (slips(y), slips(&f0));
    let mut first: Option<(f64, usize)> = None;
    for k in 0..3 {
        if let Friction::Starting(dir) = mode.friction[k] {
            let growth = rates[k].dot(&dir);
            let dp = (mode.established[k] - now[k].dot(&dir)) / growth;
            if !(growth > 0.0 && dp > 0.0 && dp.is_finite()) {
                return None;
            }
            if first.is_none_or(|(d, _)| dp < d) {
                first = Some((dp, k));
            }
        }
    }
    let (dp, k) = first?;
    let mut euler = *y;
    for i in 0..M {
        euler[i] += dp * f0[i];
    }
    let f1 = f(&euler);
    let (mut y1, mut err) = (*y, [0.0; M]);
    for i in 0..M {
        y1[i] += 0.5 * dp * (f0[i] + f1[i]);
        err[i] = 0.5 * dp * (f1[i] - f0[i]);
    }
    // Rejects a NaN measure too.
    let within = measure.measure(y, &y1, &err) <= 1.0;
    if !within {
        return None;
    }
    let (g0, g1) = (g.all(y), g.all(&y1));
    let crossed = |e: usize| g0[e] != 0.0 && (g1[e] == 0.0 || (g1[e] > 0.0) != (g0[e] > 0.0));
    let event = Event::Slip(k);
    if (0..K).any(|e| e != event.index() && crossed(e)) {
        return None;
    }
    Some((dp, y1, event))
}
