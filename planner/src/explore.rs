//! Strokes valued by an objective of the caller's instead of a distance to a fixed target: a
//! player's value of where the balls come to rest (the thesis's "strategy-planning element",
//! §2.1, §7.3.1). Each stroke of a grid is aimed along its line ([`Problem::aimed_shot`]),
//! simulated, and scored; the best can then be refined by Nelder–Mead on the objective.

use crate::aim::Stroke;
use crate::line::Line;
use crate::problem::Problem;
use crate::trial::Trial;
use argmin::core::{CostFunction, Error, Executor, State};
use argmin::solver::neldermead::NelderMead;
use rayon::prelude::*;
use snooker_engine::Shot;

/// What a caller wants of a stroke, as a number to maximise.
pub trait Objective: Sync {
    /// The value of the shot `shot` of the trial `trial` (None: not a stroke to play).
    fn value(&self, problem: &Problem, trial: &Trial, shot: &Shot) -> Option<f64>;
}

/// A stroke aimed along its line, simulated and valued.
#[derive(Debug, Clone)]
pub struct Scored {
    /// The stroke (heading solved).
    pub stroke: Stroke,
    /// The trial: the strike and what it did.
    pub trial: Trial,
    /// The objective's value.
    pub value: f64,
}

/// Every stroke of `strokes` aimed along `line` and valued by `objective`, in the order given
/// (simulated in parallel; the answer does not depend on the thread count). Strokes that
/// cannot be aimed or that the objective refuses are left out.
pub fn explore(
    problem: &Problem,
    line: &Line,
    strokes: &[Stroke],
    objective: &dyn Objective,
) -> Vec<Scored> {
    strokes
        .par_iter()
        .map(|s| {
            let (trial, shot) = problem.aimed_shot(s, line)?;
            let value = objective.value(problem, &trial, &shot)?;
            Some(Scored {
                stroke: *s,
                trial,
                value,
            })
        })
        .collect::<Vec<_>>()
        .into_iter()
        .flatten()
        .collect()
}

/// The stroke's free variables in a box: speed (geometric between the bounds), side, height.
struct Box3<'a> {
    problem: &'a Problem,
    line: &'a Line,
    objective: &'a dyn Objective,
    base: Stroke,
}

impl Box3<'_> {
    fn stroke(&self, x: &[f64]) -> Stroke {
        let b = &self.problem.request.bounds;
        let u = |k: usize| x[k].clamp(0.0, 1.0);
        Stroke {
            speed: b.speed.lo * (b.speed.hi / b.speed.lo).powf(u(0)),
            side: b.side.at(u(1)),
            height: b.height.at(u(2)),
            ..self.base
        }
    }

    fn unit(&self, s: &Stroke) -> Vec<f64> {
        let b = &self.problem.request.bounds;
        let frac = |v: f64, lo: f64, hi: f64| {
            if hi > lo {
                ((v - lo) / (hi - lo)).clamp(0.0, 1.0)
            } else {
                0.5
            }
        };
        vec![
            if b.speed.hi > b.speed.lo {
                ((s.speed / b.speed.lo).ln() / (b.speed.hi / b.speed.lo).ln()).clamp(0.0, 1.0)
            } else {
                0.5
            },
            frac(s.side, b.side.lo, b.side.hi),
            frac(s.height, b.height.lo, b.height.hi),
        ]
    }

    fn score(&self, x: &[f64]) -> Option<Scored> {
        let s = self.stroke(x);
        let (trial, shot) = self.problem.aimed_shot(&s, self.line)?;
        let value = self.objective.value(self.problem, &trial, &shot)?;
        Some(Scored {
            stroke: s,
            trial,
            value,
        })
    }
}

impl CostFunction for Box3<'_> {
    type Param = Vec<f64>;
    type Output = f64;

    fn cost(&self, x: &Vec<f64>) -> Result<f64, Error> {
        let outside: f64 = x.iter().map(|u| (u - u.clamp(0.0, 1.0)).abs()).sum();
        Ok(match self.score(x) {
            Some(s) => -s.value + outside,
            // Worse than any stroke the objective accepts.
            None => 1e6 + outside,
        })
    }
}

/// Nelder–Mead on `-objective` over speed, side and height from `start` (at most `iters`
/// iterations, first simplex `size` of each unit interval); `start` itself if nothing better
/// is found. The route may change on the way, which the objective sees.
pub fn refine(
    problem: &Problem,
    line: &Line,
    start: &Scored,
    objective: &dyn Objective,
    iters: u64,
    size: f64,
) -> Scored {
    let f = Box3 {
        problem,
        line,
        objective,
        base: start.stroke,
    };
    let x0 = f.unit(&start.stroke);
    let mut simplex = vec![x0.clone()];
    for k in 0..x0.len() {
        let mut v = x0.clone();
        v[k] += if v[k] > 0.5 { -size } else { size };
        simplex.push(v);
    }
    let best = NelderMead::new(simplex)
        .with_sd_tolerance(1e-9)
        .and_then(|solver| {
            Executor::new(
                Box3 {
                    problem,
                    line,
                    objective,
                    base: start.stroke,
                },
                solver,
            )
            .configure(|s| s.max_iters(iters))
            .run()
        })
        .ok()
        .and_then(|r| r.state().get_best_param().cloned());
    match best.and_then(|x| f.score(&x)) {
        Some(s) if s.value > start.value => s,
        _ => start.clone(),
    }
}
