//! Least-squares fits of effect parameters together with the shots' unknown initial
//! quantities: Levenberg-Marquardt with bounds (MPFIT, via `rmpfit`) on the residuals of
//! [`crate::residuals`], finite-difference Jacobians, 1-sigma uncertainties from the
//! covariance.

use crate::catalogue::{Effect, EffectParam};
use crate::data::{Measurement, Model};
use crate::error::DiscrepancyError;
use crate::residuals::{self, NuisanceValues};
use rmpfit::{MPConfig, MPError, MPFitter, MPPar, MPResult, MPSide};
use snooker_engine::Shot;

/// Residual given to every entry when a trial model cannot be simulated (a step the fit then
/// rejects): far worse than any fit worth keeping.
const FAILED: f64 = 1e4;

/// An effect with fitted values and their 1-sigma uncertainties.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct Fitted {
    /// The effect.
    pub effect: Effect,
    /// Its parameters (names, units, ranges).
    pub params: Vec<EffectParam>,
    /// Fitted values, in the order of `params`.
    pub values: Vec<f64>,
    /// 1-sigma uncertainties (scaled up by sqrt(chi2 / dof) when the fit is worse than the
    /// stated noise), in the same order.
    pub errors: Vec<f64>,
}

/// The outcome of one fit.
#[derive(Clone, Debug)]
pub struct FitResult {
    /// The model with every fitted effect at its fitted values.
    pub model: Model,
    /// The effects with their values and uncertainties.
    pub effects: Vec<Fitted>,
    /// The fitted initial quantities, per shot.
    pub nuisances: Vec<NuisanceValues>,
    /// The shots simulated with the result.
    pub sims: Vec<Shot>,
    /// Residuals at the result.
    pub resid: Vec<f64>,
    /// Sum of squared normalised residuals.
    pub chi2: f64,
    /// Number of residuals.
    pub n: usize,
    /// Number of fitted numbers.
    pub k: usize,
}

impl FitResult {
    /// Bayesian information criterion with known noise: chi2 + k ln n (Schwarz 1978).
    pub fn bic(&self) -> f64 {
        self.chi2 + self.k as f64 * (self.n as f64).ln()
    }

    /// chi2 per degree of freedom.
    pub fn reduced_chi2(&self) -> f64 {
        self.chi2 / (self.n.saturating_sub(self.k)).max(1) as f64
    }
}

/// What is being fitted: the layout of the parameter vector.
struct Problem<'a> {
    m: &'a Measurement,
    base: Model,
    effects: Vec<(Effect, Vec<EffectParam>)>,
    /// (shot, nuisance index, component) per nuisance entry of the vector.
    nuisance_slots: Vec<(usize, usize, usize)>,
    template: Vec<NuisanceValues>,
    /// Starting values and scales: a parameter is origin + scale u, MPFIT fits u.
    origin: Vec<f64>,
    scale: Vec<f64>,
    pars: Vec<MPPar>,
    config: MPConfig,
    n: usize,
    /// Samples after this time are left out (a stage of the fit).
    window: f64,
}

impl Problem<'_> {
    fn model(&self, x: &[f64]) -> Model {
        let mut model = self.base;
        let mut k = 0;
        for (e, params) in &self.effects {
            model = e.apply(&model, &x[k..k + params.len()]);
            k += params.len();
        }
        model
    }

    fn nuisances(&self, x: &[f64]) -> Vec<NuisanceValues> {
        let mut v = self.template.clone();
        let first = self.effects.iter().map(|(_, p)| p.len()).sum::<usize>();
        for (slot, &(shot, n, c)) in self.nuisance_slots.iter().enumerate() {
            v[shot][n][c] = x[first + slot];
        }
        v
    }

    /// The parameters at offsets `u`.
    fn theta(&self, u: &[f64]) -> Vec<f64> {
        u.iter()
            .zip(self.origin.iter().zip(&self.scale))
            .map(|(u, (o, s))| o + s * u)
            .collect()
    }

    /// Simulated shots and residuals at offsets `u`.
    fn run(&self, u: &[f64]) -> Result<(Vec<Shot>, Vec<f64>), DiscrepancyError> {
        let x = self.theta(u);
        let model = self.model(&x);
        let sims = residuals::simulate_all(self.m, &model, &self.nuisances(&x), self.window)?;
        let resid = residuals::all_residuals(self.m, &sims, self.window);
        Ok((sims, resid))
    }
}

impl Problem<'_> {
    /// True when chi2 over the current window is within 4 standard deviations of what noise
    /// alone gives (chi2 of N residuals: mean N, standard deviation sqrt(2N)).
    fn fits_within_noise(&self, u: &[f64]) -> bool {
        let Ok((_, r)) = self.run(u) else {
            return false;
        };
        let n = self.m.shots.iter().map(|s| {
            2 * s.samples.iter().filter(|p| p.t <= self.window).count() + s.observables.len()
        });
        let n = n.sum::<usize>() as f64;
        let chi2: f64 = r.iter().map(|v| v * v).sum();
        chi2 <= n + 4.0 * (2.0 * n).sqrt()
    }
}

impl MPFitter for Problem<'_> {
    fn eval(&mut self, params: &[f64], deviates: &mut [f64]) -> MPResult<()> {
        match self.run(params) {
            Ok((_, r)) if r.iter().all(|v| v.is_finite()) => deviates.copy_from_slice(&r),
            _ => deviates.fill(FAILED),
        }
        Ok(())
    }

    fn number_of_points(&self) -> usize {
        self.n
    }

    fn config(&self) -> &MPConfig {
        &self.config
    }

    fn parameters(&self) -> &[MPPar] {
        &self.pars
    }
}

fn par(low: Option<f64>, high: Option<f64>) -> MPPar {
    MPPar {
        limited_low: low.is_some(),
        limit_low: low.unwrap_or(0.0),
        limited_up: high.is_some(),
        limit_up: high.unwrap_or(0.0),
        // A thousandth of the resolvable change: a track through several cushions curves
        // noticeably within a tenth of it (1e-3 m/s in the starting speed turns its gradient
        // round), while the impact solvers' tolerance (5e-10 relative) stays far below.
        step: 1e-3,
        side: MPSide::Auto,
        ..MPPar::new()
    }
}

/// First window of a staged fit, s.
const FIRST_WINDOW: f64 = 0.5;

/// The windows of a staged fit: the first half second of the tracks, then twice as much each
/// stage, then all. A track through several cushions depends on its starting values ever more
/// steeply; fitting its beginning first keeps the fit in the right valley (continuation).
fn stages(m: &Measurement) -> Vec<f64> {
    let end = m.shots.iter().map(|s| s.last_sample()).fold(0.0, f64::max);
    let mut out = Vec::new();
    let mut w = FIRST_WINDOW;
    while w < end {
        out.push(w);
        w *= 1.3;
    }
    out.push(f64::INFINITY);
    out
}

/// Fits `effects` (each from its starting values) together with every shot's nuisances (from
/// `start`), on top of `base`.
///
/// The fit runs on offsets from the starting point in units of each parameter's resolvable
/// change: MPFIT's convergence test on the parameters is relative to their size, which would
/// otherwise be dominated by a large starting value (a speed of 2 m/s) and stop the fit while
/// it still moves in the smaller directions.
pub fn fit(
    m: &Measurement,
    base: &Model,
    effects: &[(Effect, Vec<f64>)],
    start: &[NuisanceValues],
) -> Result<FitResult, DiscrepancyError> {
    // (start, scale, low, high) per fitted number.
    let mut entries: Vec<(f64, f64, Option<f64>, Option<f64>)> = Vec::new();
    let mut layout = Vec::new();
    // Each effect's ranges under the model with the effects before it on (a tilt's range
    // depends on the rolling resistance).
    let mut running = *base;
    for (e, values) in effects {
        let params = e.params(&running);
        if params.len() != values.len() {
            return Err(DiscrepancyError::EffectValues {
                effect: *e,
                given: values.len(),
                expected: params.len(),
            });
        }
        for (p, v) in params.iter().zip(values) {
            entries.push((v.clamp(p.low, p.high), p.scale, Some(p.low), Some(p.high)));
        }
        running = e.apply(&running, values);
        layout.push((*e, params));
    }
    let mut slots = Vec::new();
    for (s, shot) in m.shots.iter().enumerate() {
        for (k, nu) in shot.nuisances.iter().enumerate() {
            for (c, &v) in start[s][k].iter().enumerate().take(nu.len()) {
                slots.push((s, k, c));
                let (low, high) = nu.bounds().unzip();
                let v = v.clamp(low.unwrap_or(v), high.unwrap_or(v));
                entries.push((v, nu.scale(), low, high));
            }
        }
    }
    let origin: Vec<f64> = entries.iter().map(|e| e.0).collect();
    let scale: Vec<f64> = entries.iter().map(|e| e.1).collect();
    let pars = entries
        .iter()
        .map(|&(o, sc, low, high)| {
            par(
                low.map(|l| ((l - o) / sc).min(0.0)),
                high.map(|h| ((h - o) / sc).max(0.0)),
            )
        })
        .collect();
    let n = m.residual_count();
    let k = entries.len();
    let mut problem = Problem {
        m,
        base: *base,
        effects: layout,
        nuisance_slots: slots,
        template: start.to_vec(),
        origin,
        scale,
        pars,
        config: MPConfig {
            ftol: 1e-10,
            xtol: 1e-10,
            max_iter: 200,
            ..MPConfig::new()
        },
        n,
        window: f64::INFINITY,
    };
    let mut u = vec![0.0; k];
    let mut errors = vec![0.0; k];
    if k > 0 {
        for window in stages(m) {
            problem.window = window;
            // A stage whose data the current values already fit to within the noise is
            // skipped: fitting it could only let parameters it cannot pin down wander off.
            if window.is_finite() && problem.fits_within_noise(&u) {
                continue;
            }
            match problem.mpfit(&mut u) {
                Ok(status) => errors = status.xerror,
                Err(MPError::DoF) => {
                    return Err(DiscrepancyError::TooFewResiduals {
                        residuals: n,
                        unknowns: k,
                    });
                }
                Err(e) => return Err(DiscrepancyError::Solver(e.to_string())),
            }
        }
    }
    problem.window = f64::INFINITY;
    let (sims, resid) = problem.run(&u)?;
    let x = problem.theta(&u);
    let chi2: f64 = resid.iter().map(|r| r * r).sum();
    let result_model = problem.model(&x);
    let dof = n.saturating_sub(k).max(1) as f64;
    let inflate = (chi2 / dof).sqrt().max(1.0);
    let mut fitted = Vec::new();
    let mut at = 0;
    for (e, params) in &problem.effects {
        let len = params.len();
        fitted.push(Fitted {
            effect: *e,
            params: params.clone(),
            values: x[at..at + len].to_vec(),
            errors: (at..at + len)
                .map(|i| errors[i] * problem.scale[i] * inflate)
                .collect(),
        });
        at += len;
    }
    Ok(FitResult {
        model: result_model,
        effects: fitted,
        nuisances: problem.nuisances(&x),
        sims,
        resid,
        chi2,
        n,
        k,
    })
}
