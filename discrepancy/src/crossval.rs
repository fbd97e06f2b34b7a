//! Cross-validation: a model fitted on some collisions judged on others (issue 25). The
//! held-out pool (Table I's oblique collisions, say) is split in two halves; each half in
//! turn is fitted (with the shots outside the pool, which always train) and the other half
//! is predicted, so every error on a test half comes from a model that never saw it.

use crate::catalogue::Effect;
use crate::data::{Measurement, Model};
use crate::error::DiscrepancyError;
use crate::fit::{Fitted, fit};
use crate::residuals::starting_values;
use crate::workflow::{Options, mean_relative_error, run};
use serde::Serialize;

/// How a model is made from the training shots.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Fitting {
    /// Nothing fitted: the model as it is.
    Fixed(Model),
    /// The listed effects' parameters fitted, from their starting values in the model.
    Effects(Model, Vec<Effect>),
    /// The whole workflow run from the model: whatever it names and refits.
    Workflow(Model),
}

/// One model's errors on one fold.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Fold {
    /// The pool's shots it was fitted on (the shots outside the pool besides).
    pub train: Vec<String>,
    /// The pool's shots it predicted.
    pub test: Vec<String>,
    /// Mean relative error of the observables on the training half of the pool.
    pub train_error: f64,
    /// Mean relative error of the observables on the test half.
    pub test_error: f64,
    /// What was fitted (and named, for the workflow).
    pub fitted: Vec<Fitted>,
}

/// One model's cross-validation.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct CrossValidated {
    /// The name given to the model.
    pub name: String,
    /// Both folds.
    pub folds: Vec<Fold>,
    /// Mean of the folds' training errors.
    pub train_error: f64,
    /// Mean of the folds' test errors.
    pub test_error: f64,
}

/// The shots of `m` with these indices.
fn subset(m: &Measurement, shots: &[usize]) -> Measurement {
    Measurement {
        shots: shots.iter().map(|&i| m.shots[i].clone()).collect(),
        ..m.clone()
    }
}

/// Mean relative error of `m`'s observables under `model` (the initial quantities, if any,
/// fitted).
fn error_under(m: &Measurement, model: &Model) -> Result<f64, DiscrepancyError> {
    let start: Vec<_> = m.shots.iter().map(starting_values).collect();
    let r = fit(m, model, &[], &start)?;
    Ok(mean_relative_error(m, &r))
}

/// The pool's two halves: its even- and odd-numbered shots.
pub fn halves(pool: &[usize]) -> [Vec<usize>; 2] {
    let pick = |parity| {
        pool.iter()
            .enumerate()
            .filter(|(k, _)| k % 2 == parity)
            .map(|(_, &i)| i)
            .collect()
    };
    [pick(0), pick(1)]
}

/// Cross-validates `fitting` named `name` on `m`, holding out halves of the shots `pool`.
pub fn cross_validate(
    m: &Measurement,
    pool: &[usize],
    name: &str,
    fitting: &Fitting,
) -> Result<CrossValidated, DiscrepancyError> {
    let names = |idx: &[usize]| idx.iter().map(|&i| m.shots[i].name.clone()).collect();
    let always: Vec<usize> = (0..m.shots.len()).filter(|i| !pool.contains(i)).collect();
    let [a, b] = halves(pool);
    let mut folds = Vec::new();
    for (train, test) in [(&a, &b), (&b, &a)] {
        let fitted_on: Vec<usize> = always.iter().chain(train.iter()).copied().collect();
        let mt = subset(m, &fitted_on);
        let (model, fitted) = match fitting {
            Fitting::Fixed(model) => (*model, Vec::new()),
            Fitting::Effects(model, effects) => {
                let list: Vec<(Effect, Vec<f64>)> = effects
                    .iter()
                    .map(|e| {
                        let on = e.apply(model, &e.values(model));
                        (*e, e.values(&on))
                    })
                    .collect();
                let start: Vec<_> = mt.shots.iter().map(starting_values).collect();
                let r = fit(&mt, model, &list, &start)?;
                (r.model, r.effects)
            }
            Fitting::Workflow(model) => {
                let o = run(
                    &Measurement {
                        model: *model,
                        ..mt.clone()
                    },
                    &Options::default(),
                )?;
                (o.last.model, o.last.effects)
            }
        };
        folds.push(Fold {
            train: names(train),
            test: names(test),
            train_error: error_under(&subset(m, train), &model)?,
            test_error: error_under(&subset(m, test), &model)?,
            fitted,
        });
    }
    let mean = |f: fn(&Fold) -> f64| folds.iter().map(f).sum::<f64>() / folds.len() as f64;
    Ok(CrossValidated {
        name: name.into(),
        train_error: mean(|f| f.train_error),
        test_error: mean(|f| f.test_error),
        folds,
    })
}
