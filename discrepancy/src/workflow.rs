//! The workflow: fit the data's unknown initial quantities under the current model, refit the
//! effects the model already has, try every catalogue effect the model lacks, name the best
//! one only if the data demand it, add it, and repeat until nothing significant is left; then
//! say whether what remains is noise or something the catalogue cannot explain.
//!
//! Effects the model already has are refitted before any new one is named (issue 25): an
//! effect on with a wrong value (a ball friction the data want larger) is a refit, not a new
//! law that mimics it. A refit is taken when it qualifies as below, whatever the new effects
//! would score; only when no refit qualifies may a new effect be named.
//!
//! The names are a claim that the data are explained: they stand only if the named effects
//! bring the residual down to the stated noise. When a significant residual remains (a law
//! outside the catalogue's forms, say), the nearest catalogue laws are reported as tentative
//! steps, nothing is named, and the residual is reported as unexplained where it sits.
//!
//! A step (refit or new effect) is taken only if the residual is significant (chi2 more than
//! [`Options::significance`] standard deviations above its expectation: otherwise there is
//! nothing to explain, and an effect that still lowers the BIC is fitting the noise) and all
//! of these hold:
//! - its fit lowers the Bayesian information criterion (chi2 + k ln n, known noise; Schwarz
//!   1978) by at least [`Options::threshold`] (10: "very strong" evidence, Kass & Raftery 1995);
//! - it explains at least [`Options::min_share`] of the excess chi2 (chi2 above its expected
//!   value): an effect that only nibbles at a large residual is mimicking something else;
//! - no other effect comes within [`Options::distinct`] of it: when two effects explain the
//!   data equally well the data cannot tell them apart, and the workflow says so instead of
//!   guessing.

use crate::catalogue::Effect;
use crate::data::Measurement;
use crate::error::DiscrepancyError;
use crate::fit::{FitResult, Fitted, fit};
use crate::locate::{Location, locate};
use crate::residuals::{Gap, position_gap, starting_values};
use rayon::prelude::*;
use serde::Serialize;

/// Decision thresholds.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Options {
    /// Smallest drop in BIC for an effect to be named.
    pub threshold: f64,
    /// Smallest lead in BIC over the runner-up effect.
    pub distinct: f64,
    /// Smallest share of the excess chi2 an effect must explain.
    pub min_share: f64,
    /// Largest number of effects named.
    pub max_steps: usize,
    /// The effects tried (default: the whole catalogue).
    pub candidates: Vec<Effect>,
    /// Number of standard deviations of chi2 above its expected value beyond which a
    /// residual counts as significant (chi2 has standard deviation sqrt(2 dof)).
    pub significance: f64,
}

impl Default for Options {
    fn default() -> Self {
        Options {
            threshold: 10.0,
            distinct: 2.0,
            min_share: 0.2,
            max_steps: 6,
            candidates: Effect::ALL.to_vec(),
            significance: 4.0,
        }
    }
}

/// How one candidate fared in one step.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct CandidateEffect {
    /// The effect.
    pub effect: Effect,
    /// Its fitted values and uncertainties (None when it could not be fitted).
    pub fitted: Option<Fitted>,
    /// BIC change against the current model (negative: better).
    pub delta_bic: f64,
    /// Share of the current excess chi2 it explains.
    pub share: f64,
    /// What the workflow made of it.
    pub verdict: EffectVerdict,
    /// True for an effect the model already had, refitted; false for a new one.
    pub refit: bool,
}

/// What the workflow made of a candidate effect in one step.
#[derive(Clone, Debug, PartialEq)]
pub enum EffectVerdict {
    /// It passed every test but another candidate was better (reported as "").
    Qualified,
    /// It was named.
    Named,
    /// Its drop in BIC is below the threshold.
    NotSignificant,
    /// It lowers the BIC enough but explains too small a share of the excess chi2.
    ExplainsTooLittle,
    /// It explains the data as well as the best one: the data cannot tell them apart.
    Indistinguishable,
    /// The residual is already consistent with the stated noise: nothing is left for the
    /// effect to explain, however much it would lower the BIC.
    NotNeeded,
    /// A fitted value sits at the edge of its admissible range: the fit wants a value the
    /// law does not allow (or the effect off), so it is not the law the data follow.
    AtLimit,
    /// It has no admissible value in this model.
    NotApplicable,
    /// Its fit failed.
    Failed(DiscrepancyError),
}

impl EffectVerdict {
    /// The verdict of a candidate that could not be fitted.
    fn of_error(e: DiscrepancyError) -> EffectVerdict {
        match e {
            DiscrepancyError::NotApplicable => EffectVerdict::NotApplicable,
            e => EffectVerdict::Failed(e),
        }
    }
}

impl std::fmt::Display for EffectVerdict {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            EffectVerdict::Qualified => Ok(()),
            EffectVerdict::Named => f.write_str("named"),
            EffectVerdict::NotSignificant => f.write_str("not significant"),
            EffectVerdict::ExplainsTooLittle => f.write_str("explains too little"),
            EffectVerdict::Indistinguishable => f.write_str("indistinguishable"),
            EffectVerdict::AtLimit => f.write_str("at the edge of its range"),
            EffectVerdict::NotNeeded => f.write_str("not needed: the residual is noise"),
            EffectVerdict::NotApplicable => write!(f, "{}", DiscrepancyError::NotApplicable),
            EffectVerdict::Failed(e) => write!(f, "failed: {e}"),
        }
    }
}

/// Reports give the verdict as its text.
impl Serialize for EffectVerdict {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.collect_str(self)
    }
}

/// One named effect.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Step {
    /// The effect named, with every named effect's values as refitted at this step.
    pub fitted: Vec<Fitted>,
    /// The effect this step added (or refitted).
    pub effect: Effect,
    /// True when the step refitted an effect the starting model already had.
    pub refit: bool,
    /// Position gap after the step.
    pub gap: Gap,
    /// Gap of the observables after the step (their own units).
    pub observable_gap: Gap,
    /// chi2 after the step.
    pub chi2: f64,
    /// BIC change of the step.
    pub delta_bic: f64,
    /// Every candidate tried at this step.
    pub candidates: Vec<CandidateEffect>,
}

/// A fit's summary for reports.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct State {
    /// Position gap.
    pub gap: Gap,
    /// chi2.
    pub chi2: f64,
    /// Residuals.
    pub n: usize,
    /// Fitted numbers.
    pub k: usize,
    /// chi2 per degree of freedom.
    pub reduced_chi2: f64,
    /// Gap of the observables: RMS and largest |simulated - measured|, in their own units (an
    /// observable whose moment never comes counts as simulated 0).
    pub observable_gap: Gap,
    /// Mean |simulated - measured| / |measured| over the observables (0 without).
    pub mean_relative_error: f64,
    /// Where the residuals are.
    pub location: Location,
}

/// What the workflow found.
#[derive(Clone, Debug)]
pub struct Findings {
    /// The starting model with only the initial quantities fitted.
    pub baseline: FitResult,
    /// Its summary.
    pub baseline_state: State,
    /// Named effects, in order (empty when the residual stays significant: see `tentative`).
    pub steps: Vec<Step>,
    /// The steps taken towards a residual that stayed significant: the nearest catalogue
    /// laws, not named.
    pub tentative: Vec<Step>,
    /// The candidates of the last, unsuccessful step (why nothing more was named).
    pub last_candidates: Vec<CandidateEffect>,
    /// The final fit.
    pub last: FitResult,
    /// Its summary.
    pub final_state: State,
    /// True when a significant residual remains.
    pub unexplained: bool,
    /// Where it is, or why nothing was named for it.
    pub unexplained_where: Option<String>,
    /// Effects the data could not tell apart, if the workflow stopped on them.
    pub ambiguous: Vec<Effect>,
}

impl Findings {
    /// The effects named or refitted, in order.
    pub fn named(&self) -> Vec<Effect> {
        self.steps.iter().map(|s| s.effect).collect()
    }
}

fn observable_gap(m: &Measurement, sims: &[snooker_engine::Shot]) -> Gap {
    let d: Vec<f64> = crate::locate::observable_rows(m, sims)
        .iter()
        .map(|o| o.difference.abs())
        .collect();
    if d.is_empty() {
        return Gap::default();
    }
    Gap {
        rms: (d.iter().map(|v| v * v).sum::<f64>() / d.len() as f64).sqrt(),
        max: d.iter().copied().fold(0.0, f64::max),
        samples: d.len(),
    }
}

/// Mean |simulated - measured| / |measured| over the observables of `m` under the fit `r`
/// (0 without observables).
pub fn mean_relative_error(m: &Measurement, r: &FitResult) -> f64 {
    let rows = crate::locate::observable_rows(m, &r.sims);
    let errs: Vec<f64> = rows
        .iter()
        .filter(|o| o.measured != 0.0)
        .map(|o| o.difference.abs() / o.measured.abs())
        .collect();
    if errs.is_empty() {
        0.0
    } else {
        errs.iter().sum::<f64>() / errs.len() as f64
    }
}

fn state(m: &Measurement, r: &FitResult) -> State {
    State {
        gap: position_gap(m, &r.sims),
        chi2: r.chi2,
        n: r.n,
        k: r.k,
        reduced_chi2: r.reduced_chi2(),
        observable_gap: observable_gap(m, &r.sims),
        mean_relative_error: mean_relative_error(m, r),
        location: locate(m, &r.sims),
    }
}

/// True when a fitted value lies at an end of its admissible range (within a millionth of
/// the range).
fn at_limit(f: &Fitted) -> bool {
    f.params.iter().zip(&f.values).any(|(p, v)| {
        let edge = 1e-6 * (p.high - p.low);
        *v <= p.low + edge || *v >= p.high - edge
    })
}

/// chi2 above what noise alone would give, and its threshold of significance.
fn excess(r: &FitResult, opts: &Options) -> (f64, f64) {
    let dof = r.n.saturating_sub(r.k).max(1) as f64;
    (r.chi2 - dof, opts.significance * (2.0 * dof).sqrt())
}

/// Fits `effect` on top of the named effects, from each of its starting points (a refit:
/// from its current values); the best.
fn try_effect(
    m: &Measurement,
    named: &[(Effect, Vec<f64>)],
    current: &FitResult,
    effect: Effect,
    refit: bool,
) -> Result<FitResult, DiscrepancyError> {
    if effect.params(&current.model).is_empty() {
        return Err(DiscrepancyError::NotApplicable);
    }
    let starts = if refit {
        vec![effect.values(&current.model)]
    } else {
        effect.starts(&current.model)
    };
    let mut best: Option<FitResult> = None;
    let mut last_err = None;
    // The initial quantities from the current fit, and afresh from the data: the current ones
    // may have bent to make up for the very effect being tried.
    let fresh: Vec<_> = m.shots.iter().map(starting_values).collect();
    for start in starts {
        for nuisances in [&current.nuisances, &fresh] {
            let mut list = named.to_vec();
            list.push((effect, start.clone()));
            match fit(m, &m.model, &list, nuisances) {
                Ok(r) if best.as_ref().is_none_or(|b| r.chi2 < b.chi2) => best = Some(r),
                Ok(_) => {}
                Err(e) => last_err = Some(e),
            }
        }
    }
    // Every effect has a start (tested): without one it could not be fitted at all.
    best.ok_or_else(|| last_err.unwrap_or(DiscrepancyError::NotApplicable))
}

/// Runs the workflow on `m` from its model.
pub fn run(m: &Measurement, opts: &Options) -> Result<Findings, DiscrepancyError> {
    m.validate()?;
    let start: Vec<_> = m.shots.iter().map(starting_values).collect();
    let baseline = fit(m, &m.model, &[], &start)?;
    let baseline_state = state(m, &baseline);
    let mut current = baseline.clone();
    let mut named: Vec<(Effect, Vec<f64>)> = Vec::new();
    let mut steps = Vec::new();
    let mut last_candidates = Vec::new();
    let mut ambiguous = Vec::new();
    let mut stop_reason = None;
    while steps.len() < opts.max_steps {
        let is_named = |e: &Effect| named.iter().any(|(n, _)| n == e);
        // New effects (off in the model), then the starting model's own effects to refit.
        let tried: Vec<(Effect, bool)> = opts
            .candidates
            .iter()
            .filter(|e| !e.is_on(&current.model) && !is_named(e))
            .map(|&e| (e, false))
            .chain(
                opts.candidates
                    .iter()
                    .filter(|e| e.is_on(&m.model) && !is_named(e))
                    .map(|&e| (e, true)),
            )
            .collect();
        if tried.is_empty() {
            break;
        }
        let fits: Vec<(Effect, bool, Result<FitResult, DiscrepancyError>)> = tried
            .par_iter()
            .map(|&(e, refit)| (e, refit, try_effect(m, &named, &current, e, refit)))
            .collect();
        let (excess_now, limit) = excess(&current, opts);
        let mut cands: Vec<(CandidateEffect, Option<FitResult>)> = fits
            .into_iter()
            .map(|(effect, refit, r)| match r {
                Ok(r) => {
                    let delta_bic = r.bic() - current.bic();
                    // With no excess left there is nothing to explain.
                    let share = if excess_now > 0.0 {
                        (current.chi2 - r.chi2) / excess_now
                    } else {
                        0.0
                    };
                    let fitted = r.effects.last().cloned();
                    (
                        CandidateEffect {
                            effect,
                            fitted,
                            delta_bic,
                            share,
                            verdict: EffectVerdict::Qualified,
                            refit,
                        },
                        Some(r),
                    )
                }
                Err(e) => (
                    CandidateEffect {
                        effect,
                        fitted: None,
                        delta_bic: f64::INFINITY,
                        share: 0.0,
                        verdict: EffectVerdict::of_error(e),
                        refit,
                    },
                    None,
                ),
            })
            .collect();
        cands.sort_by(|a, b| {
            a.0.delta_bic
                .total_cmp(&b.0.delta_bic)
                .then(a.0.refit.cmp(&b.0.refit))
                .then(a.0.effect.cmp(&b.0.effect))
        });
        for (c, _) in cands
            .iter_mut()
            .filter(|(c, _)| c.verdict == EffectVerdict::Qualified)
        {
            c.verdict = if c.delta_bic > -opts.threshold {
                EffectVerdict::NotSignificant
            } else if c.share < opts.min_share {
                EffectVerdict::ExplainsTooLittle
            } else if c.fitted.as_ref().is_some_and(at_limit) {
                EffectVerdict::AtLimit
            } else if excess_now <= limit {
                EffectVerdict::NotNeeded
            } else {
                EffectVerdict::Qualified
            };
        }
        // Parsimony: a qualified refit scoring within `distinct` of the best new law comes
        // first (the data cannot tell them apart, and the refit adds no law).
        if let Some((best, _)) = cands.first()
            && !best.refit
            && best.verdict == EffectVerdict::Qualified
        {
            let best_bic = best.delta_bic;
            if let Some(j) = cands.iter().position(|(c, _)| {
                c.refit
                    && c.verdict == EffectVerdict::Qualified
                    && c.delta_bic - best_bic < opts.distinct
            }) {
                let promoted = cands.remove(j);
                cands.insert(0, promoted);
            }
        }
        // A refit in front competes with the other refits only.
        let refit_first = cands.first().is_some_and(|(c, _)| c.refit);
        if cands
            .first()
            .is_none_or(|(c, _)| c.verdict != EffectVerdict::Qualified)
        {
            if let Some((c, _)) = cands.first()
                && c.verdict == EffectVerdict::ExplainsTooLittle
            {
                stop_reason = Some(format!(
                    "the best candidate, {}, would lower the BIC by {:.0} but explains only \
                     {:.0}% of the excess chi2",
                    c.effect.id(),
                    -c.delta_bic,
                    100.0 * c.share
                ));
            }
            last_candidates = cands.into_iter().map(|(c, _)| c).collect();
            break;
        }
        let i = 0;
        let lead = cands
            .iter()
            .enumerate()
            .filter(|(j, (c, _))| *j != i && c.fitted.is_some() && (!refit_first || c.refit))
            .map(|(_, (c, _))| c.delta_bic - cands[i].0.delta_bic)
            .fold(f64::INFINITY, f64::min);
        if lead < opts.distinct {
            ambiguous = cands
                .iter()
                .filter(|(c, _)| !refit_first || c.refit)
                .filter(|(c, _)| c.delta_bic - cands[i].0.delta_bic < opts.distinct)
                .map(|(c, _)| c.effect)
                .collect();
            for (c, _) in cands.iter_mut() {
                if ambiguous.contains(&c.effect) {
                    c.verdict = EffectVerdict::Indistinguishable;
                }
            }
            stop_reason = Some(format!(
                "{} explain the data equally well (BIC within {}): these data cannot tell them \
                 apart",
                ambiguous
                    .iter()
                    .map(|e| e.id())
                    .collect::<Vec<_>>()
                    .join(" and "),
                opts.distinct
            ));
            last_candidates = cands.into_iter().map(|(c, _)| c).collect();
            break;
        }
        cands[i].0.verdict = EffectVerdict::Named;
        let (cand, Some(r)) = cands.swap_remove(i) else {
            unreachable!("a qualified candidate has a fit");
        };
        let mut candidates: Vec<CandidateEffect> = vec![cand.clone()];
        candidates.extend(cands.into_iter().map(|(c, _)| c));
        candidates.sort_by(|a, b| a.delta_bic.total_cmp(&b.delta_bic));
        named = r
            .effects
            .iter()
            .map(|f| (f.effect, f.values.clone()))
            .collect();
        steps.push(Step {
            fitted: r.effects.clone(),
            effect: cand.effect,
            refit: cand.refit,
            gap: position_gap(m, &r.sims),
            observable_gap: observable_gap(m, &r.sims),
            chi2: r.chi2,
            delta_bic: cand.delta_bic,
            candidates,
        });
        current = r;
    }
    let (left, limit) = excess(&current, opts);
    let unexplained = left > limit || !ambiguous.is_empty();
    // Names stand only if they explain the data down to the noise: otherwise the steps are
    // the nearest laws to something outside the catalogue, and none of them is a finding.
    let mut tentative = Vec::new();
    let mut nearest = None;
    if unexplained && !steps.is_empty() {
        let path = steps
            .iter()
            .map(|s: &Step| s.effect.id())
            .collect::<Vec<_>>()
            .join(", then ");
        nearest = Some(format!(
            "the nearest catalogue laws ({path}) leave chi2/dof {:.2}, not the noise, so \
             none is named",
            current.reduced_chi2()
        ));
        tentative = std::mem::take(&mut steps);
        current = baseline.clone();
    }
    let final_state = state(m, &current);
    let unexplained_where = unexplained.then(|| {
        let place = final_state
            .location
            .worst
            .clone()
            .or_else(|| worst_observable(&final_state.location))
            .unwrap_or_default();
        let why = match (stop_reason, nearest) {
            (Some(r), Some(n)) => format!("{r}; {n}"),
            (Some(r), None) => r,
            (None, Some(n)) => format!("no catalogue effect explains it: {n}"),
            (None, None) => "no catalogue effect explains it".into(),
        };
        format!("{why}; largest residual: {place}")
    });
    Ok(Findings {
        baseline,
        baseline_state,
        steps,
        tentative,
        last_candidates,
        last: current,
        final_state,
        unexplained,
        unexplained_where,
        ambiguous,
    })
}

fn worst_observable(loc: &Location) -> Option<String> {
    loc.observables
        .iter()
        .max_by(|a, b| {
            let r = |o: &crate::locate::ObservableRow| o.difference.abs() / o.sigma;
            r(a).total_cmp(&r(b))
        })
        .map(|o| {
            format!(
                "{} of {} {} in shot {}: measured {:.4}, simulated {}",
                o.quantity,
                o.ball,
                o.when,
                o.shot,
                o.measured,
                o.simulated
                    .map_or("never reached".to_string(), |v| format!("{v:.4}"))
            )
        })
}
