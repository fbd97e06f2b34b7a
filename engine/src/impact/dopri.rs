//! The Dormand-Prince 5(4) Runge-Kutta pair (Dormand and Prince 1980; Hairer, Norsett and
//! Wanner, *Solving ODEs I*, §II.5) on fixed-size arrays, for autonomous systems
//! dy/dx = f(y), with step-size control and location of sign changes of event functions.
//!
//! Written here rather than taken from a crate: an impact is integrated in microseconds, so
//! the stepper must not allocate, and events must be located on the integrator's own steps
//! (re-stepping from the last accepted point), which the ODE crates do not offer.

const C: [[f64; 6]; 6] = [
    [1.0 / 5.0, 0.0, 0.0, 0.0, 0.0, 0.0],
    [3.0 / 40.0, 9.0 / 40.0, 0.0, 0.0, 0.0, 0.0],
    [44.0 / 45.0, -56.0 / 15.0, 32.0 / 9.0, 0.0, 0.0, 0.0],
    [
        19372.0 / 6561.0,
        -25360.0 / 2187.0,
        64448.0 / 6561.0,
        -212.0 / 729.0,
        0.0,
        0.0,
    ],
    [
        9017.0 / 3168.0,
        -355.0 / 33.0,
        46732.0 / 5247.0,
        49.0 / 176.0,
        -5103.0 / 18656.0,
        0.0,
    ],
    [
        35.0 / 384.0,
        0.0,
        500.0 / 1113.0,
        125.0 / 192.0,
        -2187.0 / 6784.0,
        11.0 / 84.0,
    ],
];
/// Fifth-order weights minus the embedded fourth-order ones (the error estimate).
const E: [f64; 7] = [
    71.0 / 57600.0,
    0.0,
    -71.0 / 16695.0,
    71.0 / 1920.0,
    -17253.0 / 339200.0,
    22.0 / 525.0,
    -1.0 / 40.0,
];

/// Shampine's (1986) coefficients of the continuous extension of order 4.
const D: [f64; 7] = [
    -12715105075.0 / 11282082432.0,
    0.0,
    87487479700.0 / 32700410799.0,
    -10690763975.0 / 1880347072.0,
    701980252875.0 / 199316789632.0,
    -1453857185.0 / 822651844.0,
    69997945.0 / 29380423.0,
];

#[cfg(test)]
/// One step of size `h` from `y` whose slope is `k1`: the fifth-order solution, the error
/// estimate of the embedded fourth-order one, and the seven stage slopes (the last is the
/// slope at the new point).
pub fn step<const N: usize, F: Fn(&[f64; N]) -> [f64; N]>(
    f: &F,
    y: &[f64; N],
    k1: &[f64; N],
    h: f64,
) -> ([f64; N], [f64; N], [[f64; N]; 7]) {
    let mut k = [[0.0; N]; 7];
    k[0] = *k1;
    let mut y1 = [0.0; N];
    stages(f, y, h, &mut k, &mut y1);
    let mut err = [0.0; N];
    for (i, e) in err.iter_mut().enumerate() {
        *e = h * (0..7).map(|j| E[j] * k[j][i]).sum::<f64>();
    }
    (y1, err, k)
}

/// Fills stages 2-7 of a step of size `h` from `y` (stage 1, the slope at `y`, given in
/// `k[0]`) and the fifth-order solution `y1`, in place: the stepper copies nothing larger
/// than a state.
fn stages<const N: usize, F: Fn(&[f64; N]) -> [f64; N]>(
    f: &F,
    y: &[f64; N],
    h: f64,
    k: &mut [[f64; N]; 7],
    y1: &mut [f64; N],
) {
    // Each stage spelt out, so that its sum over the previous stages has a constant length
    // (unrolled by the compiler).
    k[1] = f(&combine::<N, 1>(y, h, &C[0], k));
    k[2] = f(&combine::<N, 2>(y, h, &C[1], k));
    k[3] = f(&combine::<N, 3>(y, h, &C[2], k));
    k[4] = f(&combine::<N, 4>(y, h, &C[3], k));
    k[5] = f(&combine::<N, 5>(y, h, &C[4], k));
    // The seventh stage is evaluated at the fifth-order solution itself (FSAL).
    *y1 = combine::<N, 6>(y, h, &C[5], k);
    k[6] = f(y1);
}

/// y + h sum_j a_j k_j over the first `S` stages. The newest stage is added last, to a sum
/// of the others formed while it was being evaluated, so that only one product and one sum
/// stand between a stage and the next evaluation (each step is a chain of evaluations).
fn combine<const N: usize, const S: usize>(
    y: &[f64; N],
    h: f64,
    a: &[f64; 6],
    k: &[[f64; N]; 7],
) -> [f64; N] {
    let ha: [f64; S] = std::array::from_fn(|j| h * a[j]);
    let mut out = [0.0; N];
    for i in 0..N {
        let mut acc = y[i];
        for j in 0..S - 1 {
            acc += ha[j] * k[j][i];
        }
        out[i] = acc + ha[S - 1] * k[S - 1][i];
    }
    out
}

/// The error estimate of the step of size `h` with stages `k`.
fn step_error<const N: usize>(k: &[[f64; N]; 7], h: f64) -> [f64; N] {
    let mut err = [0.0; N];
    for (i, e) in err.iter_mut().enumerate() {
        let mut acc = 0.0;
        for j in 0..7 {
            acc += E[j] * k[j][i];
        }
        *e = h * acc;
    }
    err
}

/// The continuous extension of one step in Horner form, its coefficients formed once so that
/// each evaluation (root finding needs several) costs a few operations per component.
struct Dense<const N: usize> {
    y0: [f64; N],
    rc: [[f64; N]; 4],
}

impl<const N: usize> Dense<N> {
    fn new(y0: &[f64; N], y1: &[f64; N], k: &[[f64; N]; 7], h: f64) -> Dense<N> {
        let mut rc = [[0.0; N]; 4];
        for i in 0..N {
            let rc2 = y1[i] - y0[i];
            let rc3 = h * k[0][i] - rc2;
            rc[0][i] = rc2;
            rc[1][i] = rc3;
            rc[2][i] = rc2 - h * k[6][i] - rc3;
            let mut d = 0.0;
            for j in 0..7 {
                d += D[j] * k[j][i];
            }
            rc[3][i] = h * d;
        }
        Dense { y0: *y0, rc }
    }

    fn at(&self, theta: f64) -> [f64; N] {
        let mut out = [0.0; N];
        let u = 1.0 - theta;
        for i in 0..N {
            let r = &self.rc;
            out[i] =
                self.y0[i] + theta * (r[0][i] + u * (r[1][i] + theta * (r[2][i] + u * r[3][i])));
        }
        out
    }
}

#[cfg(test)]
/// The state at fraction `theta` of a step from `y0` to `y1` of size `h` with stages `k`
/// (the continuous extension, accurate to the order of the embedded method).
pub fn dense<const N: usize>(
    y0: &[f64; N],
    y1: &[f64; N],
    k: &[[f64; N]; 7],
    h: f64,
    theta: f64,
) -> [f64; N] {
    Dense::new(y0, y1, k, h).at(theta)
}

/// Sum over the components of the squared error of a step from `y0` to `y1`, each scaled by
/// `tol (1 + |y|)` (absolute and relative tolerance `tol`, the larger |y| of the two ends).
pub fn mixed_sum<const N: usize>(y0: &[f64; N], y1: &[f64; N], err: &[f64; N], tol: f64) -> f64 {
    let mut sum = 0.0;
    for i in 0..N {
        let r = err[i] / (tol * (1.0 + y0[i].abs().max(y1[i].abs())));
        sum += r * r;
    }
    sum
}

/// How a step's error is measured: the step is accepted when the measure is at most 1.
pub trait ErrorMeasure<const N: usize> {
    /// The size of the error estimate `err` of the step from `y0` to `y1`.
    fn measure(&self, y0: &[f64; N], y1: &[f64; N], err: &[f64; N]) -> f64;
}

#[cfg(test)]
/// The usual measure: the RMS, over `dim` components (more than the state's when it stands
/// for a larger system whose other components are constant), of the error scaled by
/// `tol (1 + |y|)`.
#[derive(Clone, Copy, Debug)]
pub struct Mixed {
    /// Absolute and relative tolerance.
    pub tol: f64,
    /// Number of components the mean is taken over.
    pub dim: usize,
}

#[cfg(test)]
impl<const N: usize> ErrorMeasure<N> for Mixed {
    fn measure(&self, y0: &[f64; N], y1: &[f64; N], err: &[f64; N]) -> f64 {
        (mixed_sum(y0, y1, err, self.tol) / self.dim as f64).sqrt()
    }
}

/// Event functions of a state: a change of sign of one ends a phase of integration.
pub trait Events<const N: usize, const K: usize> {
    /// All of them at `y`.
    fn all(&self, y: &[f64; N]) -> [f64; K];

    /// Event `e` alone at `y` (what a root search evaluates, several times), the same value
    /// as `all(y)[e]`.
    fn one(&self, y: &[f64; N], e: usize) -> f64 {
        self.all(y)[e]
    }
}

impl<const N: usize, const K: usize, F: Fn(&[f64; N]) -> [f64; K]> Events<N, K> for F {
    fn all(&self, y: &[f64; N]) -> [f64; K] {
        self(y)
    }
}

/// Why a phase of integration stopped.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Stop {
    /// Event function `k` changed sign; the state is at its root.
    Event(usize),
    /// The integration failed (step size underflow or too many steps).
    Failed,
}

/// Result of [`integrate`]: where it stopped, the state there, and the step size to reuse.
#[derive(Clone, Copy, Debug)]
pub struct Phase<const N: usize> {
    /// Independent variable at the stop.
    pub x: f64,
    /// State at the stop.
    pub y: [f64; N],
    /// Why it stopped.
    pub stop: Stop,
    /// Suggested next step size.
    pub h: f64,
    /// Accepted steps taken.
    pub steps: usize,
}

/// Integrates dy/dx = f(y) from (x0, y0) until one of the event functions `g` changes sign
/// (a function that is exactly zero at the start is armed only once it is non-zero), then
/// locates that root to `root_tol` on the step's continuous extension (Illinois method), so
/// the stop state is as accurate as the integrator at no extra slope evaluation. Steps are
/// accepted when their error, as `measure` sizes it, is at most 1.
/// `on_step` sees every accepted point (for traces).
/// Gives up (with [`Stop::Failed`] and the state reached) after `max_steps` steps.
#[allow(clippy::too_many_arguments)]
pub fn integrate<const N: usize, const K: usize, F, G, M, S>(
    f: &F,
    g: &G,
    x0: f64,
    y0: [f64; N],
    h0: f64,
    measure: &M,
    root_tol: f64,
    max_steps: usize,
    mut on_step: S,
) -> Phase<N>
where
    F: Fn(&[f64; N]) -> [f64; N],
    G: Events<N, K>,
    M: ErrorMeasure<N>,
    S: FnMut(f64, &[f64; N]),
{
    let (mut x, mut y, mut h) = (x0, y0, h0);
    let mut g0 = g.all(&y);
    // Stage slopes, reused from step to step: k[0] is the slope at y (first same as last).
    let mut k = [[0.0; N]; 7];
    k[0] = f(&y);
    let mut y1 = [0.0; N];
    // The 64th root of the error measure of the last accepted step, for the PI controller.
    let root_floor = root64(1e-4);
    let mut q_old = root_floor;
    for steps in 0..max_steps {
        stages(f, &y, h, &mut k, &mut y1);
        let en = measure.measure(&y, &y1, &step_error(&k, h));
        if en.is_nan() || en > 1.0 {
            // Rejected (or NaN): shrink and retry.
            h *= if en.is_finite() {
                (0.9 * (-0.2 * en.ln()).exp()).clamp(0.1, 0.9)
            } else {
                0.1
            };
            if h.abs() < 1e-300 {
                break;
            }
            continue;
        }
        let g1 = g.all(&y1);
        // The earliest event whose sign changed within this step.
        let mut best: Option<(f64, usize, [f64; N])> = None;
        let mut ext: Option<Dense<N>> = None;
        for e in 0..K {
            let armed = g0[e] != 0.0;
            if armed && (g1[e] == 0.0 || (g1[e] > 0.0) != (g0[e] > 0.0)) {
                let (he, ye) = if g1[e] == 0.0 {
                    (h, y1)
                } else {
                    let d = ext.get_or_insert_with(|| Dense::new(&y, &y1, &k, h));
                    let at = |t: f64| g.one(&d.at(t), e);
                    let t = illinois(&at, 0.0, 1.0, g0[e], g1[e], root_tol, 200);
                    (t * h, d.at(t))
                };
                if best.is_none_or(|b| he < b.0) {
                    best = Some((he, e, ye));
                }
            }
        }
        // PI control (Gustafsson 1991; Hairer, Norsett and Wanner §II.4):
        // h_new = h 0.9 en^-alpha en_old^beta, with alpha = 11/64 and beta = 3/64 (DOPRI5's
        // 0.17 and 0.04, rounded to 64ths so that the powers are six square roots and a few
        // products rather than logarithms and exponentials).
        let q = root64(en.max(1e-10));
        let (q2, q_old2) = (q * q, q_old * q_old);
        let q11 = q2 * q2 * q2 * q2 * q2 * q;
        let grow = (0.9 * q_old2 * q_old / q11).clamp(0.2, 10.0);
        if let Some((he, e, ye)) = best {
            on_step(x + he, &ye);
            return Phase {
                x: x + he,
                y: ye,
                stop: Stop::Event(e),
                h: (h * grow).max(he),
                steps: steps + 1,
            };
        }
        q_old = q.max(root_floor);
        x += h;
        y = y1;
        on_step(x, &y);
        // A function that was exactly zero becomes armed once it leaves zero.
        g0 = g1;
        // First same as last: the final stage is the slope at the new point.
        k[0] = k[6];
        h *= grow;
    }
    Phase {
        x,
        y,
        stop: Stop::Failed,
        h,
        steps: max_steps,
    }
}

/// x^(1/64), by six square roots.
fn root64(x: f64) -> f64 {
    x.sqrt().sqrt().sqrt().sqrt().sqrt().sqrt()
}

/// Root of `f` in [a, b] (values `fa`, `fb` of opposite signs) by the Illinois method, to
/// |f| <= tol or `iters` iterations.
fn illinois<F: Fn(f64) -> f64>(
    f: &F,
    mut a: f64,
    mut b: f64,
    mut fa: f64,
    mut fb: f64,
    tol: f64,
    iters: usize,
) -> f64 {
    let mut side = 0i8;
    let mut m = 0.5 * (a + b);
    for _ in 0..iters {
        m = (a * fb - b * fa) / (fb - fa);
        if !(m > a && m < b) {
            m = 0.5 * (a + b);
        }
        let fm = f(m);
        if fm.abs() <= tol || (b - a).abs() < 1e-15 {
            return m;
        }
        if (fm > 0.0) == (fa > 0.0) {
            a = m;
            fa = fm;
            if side == -1 {
                fb *= 0.5;
            }
            side = -1;
        } else {
            b = m;
            fb = fm;
            if side == 1 {
                fa *= 0.5;
            }
            side = 1;
        }
    }
    m
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn integrates_the_exponential_to_tolerance() {
        let f = |y: &[f64; 1]| [y[0]];
        let g = |y: &[f64; 1]| [y[0] - 10f64.exp()];
        let tol = Mixed { tol: 1e-12, dim: 1 };
        let ph = integrate(&f, &g, 0.0, [1.0], 0.1, &tol, 1e-12, 10_000, |_, _| {});
        assert_eq!(ph.stop, Stop::Event(0));
        assert!((ph.x - 10.0).abs() < 1e-9, "{}", ph.x);
    }

    #[test]
    fn the_continuous_extension_is_fourth_order() {
        // Local error of the interpolant at mid-step falls as h^5 on y' = y.
        let f = |y: &[f64; 1]| [y[0]];
        let err = |h: f64| {
            let (y1, _, k) = step(&f, &[1.0], &[1.0], h);
            (dense(&[1.0], &y1, &k, h, 0.5)[0] - (0.5 * h).exp()).abs()
        };
        let ratio = err(0.1) / err(0.05);
        assert!(ratio > 25.0, "error ratio {ratio}: order below 4");
    }

    #[test]
    fn locates_a_root_of_a_linear_event_exactly() {
        // Constant slope: one step is exact, the root is found to rounding.
        let f = |_: &[f64; 2]| [1.0, -2.0];
        let g = |y: &[f64; 2]| [y[1]];
        let ph = integrate(
            &f,
            &g,
            0.0,
            [0.0, 3.0],
            10.0,
            &Mixed { tol: 1e-10, dim: 2 },
            1e-14,
            10_000,
            |_, _| {},
        );
        assert!((ph.x - 1.5).abs() < 1e-14);
        assert!(ph.y[1].abs() < 1e-14);
    }
}
