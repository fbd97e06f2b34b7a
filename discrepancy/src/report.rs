//! The workflow's outcome as the JSON report of formats.md (`baseline_gap`, `steps`, `named`,
//! `unexplained`, `final_gap`), extended with uncertainties, the evidence for each decision,
//! every candidate tried and where the residuals are, and as a plain-text summary.

use crate::catalogue::Effect;
use crate::data::Measurement;
use crate::fit::Fitted;
use crate::residuals::Gap;
use crate::workflow::{CandidateEffect, Findings, State, Step};
use serde_json::{Map, Value, json};

fn params_of(f: &Fitted) -> (Value, Value) {
    let mut values = Map::new();
    let mut errors = Map::new();
    for ((p, v), e) in f.params.iter().zip(&f.values).zip(&f.errors) {
        values.insert(p.name.into(), json!(v));
        errors.insert(p.name.into(), json!(e));
    }
    (Value::Object(values), Value::Object(errors))
}

fn candidate(c: &CandidateEffect) -> Value {
    let (params, uncertainties) = c.fitted.as_ref().map_or((json!({}), json!({})), params_of);
    json!({
        "effect": c.effect.id(),
        "delta_bic": if c.delta_bic.is_finite() { json!(c.delta_bic) } else { Value::Null },
        "share_of_excess": c.share,
        "verdict": c.verdict,
        "refit": c.refit,
        "params": params,
        "uncertainties": uncertainties,
    })
}

fn state(s: &State) -> Value {
    json!({
        "gap": s.gap,
        "observable_gap": s.observable_gap,
        "chi2": s.chi2,
        "residuals": s.n,
        "fitted_numbers": s.k,
        "reduced_chi2": s.reduced_chi2,
        "mean_relative_error": s.mean_relative_error,
        "location": s.location,
    })
}

/// The catalogue as documentation: id, description, source and parameters.
pub fn catalogue() -> Value {
    let model = crate::data::Model {
        params: snooker_engine::Params::default(),
        models: snooker_engine::Models::default(),
    };
    Value::Array(
        Effect::ALL
            .iter()
            .map(|e| {
                json!({
                    "id": e.id(),
                    "description": e.description(),
                    "source": e.source(),
                    "params": e.params(&model),
                })
            })
            .collect(),
    )
}

/// One step (named, refitted or tentative) as JSON.
fn step(s: &Step) -> Value {
    let added = s
        .fitted
        .iter()
        .find(|f| f.effect == s.effect)
        .expect("a step's effect is among its fitted effects");
    let (params, uncertainties) = params_of(added);
    json!({
        "effect": s.effect.id(),
        "params": params,
        "gap": s.gap,
        "refit": s.refit,
        "uncertainties": uncertainties,
        "observable_gap": s.observable_gap,
        "description": s.effect.description(),
        "source": s.effect.source(),
        "delta_bic": s.delta_bic,
        "chi2": s.chi2,
        "refitted": s.fitted.iter().map(|f| {
            let (p, u) = params_of(f);
            json!({"effect": f.effect.id(), "params": p, "uncertainties": u})
        }).collect::<Vec<_>>(),
        "candidates": s.candidates.iter().map(candidate).collect::<Vec<_>>(),
    })
}

/// The report of `o` on `m` (formats.md's keys first).
pub fn json(m: &Measurement, o: &Findings) -> Value {
    let steps: Vec<Value> = o.steps.iter().map(step).collect();
    let nuisances: Vec<Value> = m
        .shots
        .iter()
        .zip(&o.last.nuisances)
        .map(|(shot, values)| {
            let ids = shot.ids();
            let mut map = Map::new();
            for (n, v) in shot.nuisances.iter().zip(values) {
                map.insert(n.name(&ids), json!(v));
            }
            json!({"shot": shot.name, "fitted": map})
        })
        .collect();
    json!({
        "baseline_gap": o.baseline_state.gap,
        "steps": steps,
        "named": o.named().iter().map(|e| e.id()).collect::<Vec<_>>(),
        "unexplained": o.unexplained,
        "final_gap": o.final_state.gap,
        "baseline_observable_gap": o.baseline_state.observable_gap,
        "final_observable_gap": o.final_state.observable_gap,
        "unexplained_where": o.unexplained_where,
        "ambiguous": o.ambiguous.iter().map(|e| e.id()).collect::<Vec<_>>(),
        "tentative": o.tentative.iter().map(step).collect::<Vec<_>>(),
        "noise": m.noise,
        "shots": m.shots.iter().map(|s| json!({
            "name": s.name,
            "samples": s.samples.len(),
            "observables": s.observables.len(),
        })).collect::<Vec<_>>(),
        "start_model": {"params": m.model.params, "models": m.model.models},
        "final_model": {"params": o.last.model.params, "models": o.last.model.models},
        "fitted_initial_quantities": nuisances,
        "baseline": state(&o.baseline_state),
        "final": state(&o.final_state),
        "last_candidates": o.last_candidates.iter().map(candidate).collect::<Vec<_>>(),
    })
}

fn format_fitted(f: &Fitted) -> String {
    f.params
        .iter()
        .zip(&f.values)
        .zip(&f.errors)
        .map(|((p, v), e)| format!("{} = {v:.5} ± {e:.2e}{}", p.name, p.unit_suffix()))
        .collect::<Vec<_>>()
        .join(", ")
}

/// The gaps as text: positions in mm (with tracks), observables in their units (with them;
/// `observables` says which: one unit, or several that an RMS mixes).
fn format_gaps(pos: &Gap, obs: &Gap, tracks: bool, observables: Option<&str>) -> String {
    let mut parts = Vec::new();
    if tracks {
        parts.push(format!(
            "gap RMS {:.2} mm, max {:.2} mm",
            pos.rms * 1e3,
            pos.max * 1e3
        ));
    }
    if let Some(units) = observables {
        parts.push(format!(
            "observables off by RMS {:.4}, max {:.4} {units}",
            obs.rms, obs.max
        ));
    }
    parts.join("; ")
}

/// How the observables' gaps are told: "in their units" when they share one; when they mix
/// several (a speed in m/s and a heading in degrees) an RMS across them is no one measure,
/// and the text says so rather than print it as one.
fn observable_units(m: &Measurement) -> Option<String> {
    let mut units: Vec<&str> = Vec::new();
    for o in m.shots.iter().flat_map(|s| &s.observables) {
        let u = o.quantity.unit();
        if !units.contains(&u) {
            units.push(u);
        }
    }
    match units.len() {
        0 => None,
        1 => Some("in their units".into()),
        _ => Some(format!(
            "across mixed units ({}: no single measure; the % average leaves out values \
             measured as 0)",
            units.join(", ")
        )),
    }
}

fn format_state(label: &str, s: &State, tracks: bool, observables: Option<&str>) -> String {
    let mut out = format!(
        "{label}: {}",
        format_gaps(&s.gap, &s.observable_gap, tracks, observables)
    );
    if observables.is_some() {
        out += &format!(" ({:.2}% on average)", 100.0 * s.mean_relative_error);
    }
    out + &format!("; chi2/dof {:.2}\n", s.reduced_chi2)
}

/// A plain-text summary of `o`.
pub fn text(m: &Measurement, o: &Findings) -> String {
    let units = observable_units(m);
    let observables = units.as_deref();
    let tracks = m.shots.iter().any(|s| !s.samples.is_empty());
    let mut out = format_state("start", &o.baseline_state, tracks, observables);
    if let Some(w) = &o.baseline_state.location.worst {
        out += &format!("  largest residual: {w}\n");
    }
    let tentative = o.tentative.iter().map(|s| (s, "tentative, not named: "));
    for (k, (s, label)) in o.steps.iter().map(|s| (s, "")).chain(tentative).enumerate() {
        let f = s
            .fitted
            .iter()
            .find(|f| f.effect == s.effect)
            .expect("a step's effect is among its fitted effects");
        out += &format!(
            "step {}: {label}{} {} (BIC {:.0}): {}\n  {}\n",
            k + 1,
            // A tentative step names nothing: it was tried.
            match (s.refit, label.is_empty()) {
                (true, _) => "refitted",
                (false, true) => "named",
                (false, false) => "tried",
            },
            s.effect.id(),
            s.delta_bic,
            format_fitted(f),
            s.effect.description()
        );
        out += &format!(
            "  {}\n",
            format_gaps(&s.gap, &s.observable_gap, tracks, observables)
        );
    }
    out += &format_state("end", &o.final_state, tracks, observables);
    if o.steps.is_empty() {
        out += "named: nothing\n";
    } else {
        out += &format!(
            "named: {}\n",
            o.named()
                .iter()
                .map(|e| e.id())
                .collect::<Vec<_>>()
                .join(", ")
        );
        for f in &o.last.effects {
            out += &format!("  {}: {}\n", f.effect.id(), format_fitted(f));
        }
    }
    if !o.last_candidates.is_empty() {
        out += "not named:\n";
        for c in &o.last_candidates {
            let bic = if c.delta_bic.is_finite() {
                format!("BIC {:+.0}", c.delta_bic)
            } else {
                "no fit".into()
            };
            out += &format!("  {:<26} {bic:<12} {}\n", c.effect.id(), c.verdict);
        }
    }
    out += &match (&o.unexplained, &o.unexplained_where) {
        (true, Some(w)) => format!("unexplained: {w}\n"),
        (true, None) => "unexplained\n".into(),
        (false, _) => "what remains is consistent with the stated noise\n".into(),
    };
    out
}
