//! The search over the stroke (speed, side, height, elevation, and the aim point across the
//! pocket's mouth; the heading is solved for the pot, `aim.rs`): a grid of starts run in parallel, the best start of each route of the cue
//! ball, then Nelder–Mead (argmin) from each, in parallel. Where a route changes (a cushion
//! met or missed) the cue ball's end jumps; within a route it moves smoothly, which is what
//! Nelder–Mead needs.

use crate::aim::Stroke;
use crate::line::{Line, ShotKind};
use crate::problem::{Bounds, Problem};
use crate::trial::{Route, Trial};
use argmin::core::{CostFunction, Error, Executor, State};
use argmin::solver::neldermead::NelderMead;
use rayon::prelude::*;
use std::collections::BTreeMap;

/// Cost of a stroke that does not pot (plus its distance): worse than any pot on the table.
const NO_POT: f64 = 10.0;
/// Grid of starts: speeds (geometric), height and side fractions of their intervals.
const SPEEDS: usize = 9;
const HEIGHTS: [f64; 5] = [0.05, 0.275, 0.5, 0.725, 0.95];
const SIDES: [f64; 3] = [0.2, 0.5, 0.8];
const ELEVATIONS: [f64; 2] = [0.1, 0.6];
const MOUTHS: [f64; 3] = [0.2, 0.5, 0.8];
/// Most routes refined, and how many at a time (fixed, so that the answer does not depend on
/// the number of threads): refinement stops once the best shot is within the tolerance and
/// the alternatives asked for are found.
const MAX_SEEDS: usize = 12;
const BATCH: usize = 2;
/// Nelder–Mead: most iterations and the first simplex's size (fraction of each interval).
const MAX_ITERS: u64 = 120;
const SIMPLEX: f64 = 0.04;

/// A point of the unit box of the free variables, mapped onto the bounds.
fn stroke(b: &Bounds, free: &[Var], x: &[f64]) -> Stroke {
    let mut s = Stroke {
        speed: b.speed.lo,
        side: b.side.at(0.5),
        height: b.height.at(0.5),
        elevation: b.elevation.lo,
        mouth: 0.0,
    };
    for (v, &u) in free.iter().zip(x) {
        let u = u.clamp(0.0, 1.0);
        match v {
            Var::Speed => s.speed = b.speed.lo * (b.speed.hi / b.speed.lo).powf(u),
            Var::Side => s.side = b.side.at(u),
            Var::Height => s.height = b.height.at(u),
            Var::Elevation => s.elevation = b.elevation.at(u),
            Var::Mouth => s.mouth = 2.0 * u - 1.0,
        }
    }
    s
}

/// A searched variable.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Var {
    Speed,
    Side,
    Height,
    Elevation,
    Mouth,
}

/// The variables whose interval is not a single value.
fn free_vars(b: &Bounds) -> Vec<Var> {
    [
        (Var::Speed, b.speed),
        (Var::Side, b.side),
        (Var::Height, b.height),
        (Var::Elevation, b.elevation),
    ]
    .into_iter()
    .filter(|(_, iv)| !iv.is_fixed())
    .map(|(v, _)| v)
    .chain([Var::Mouth])
    .collect()
}

/// A stroke found, with its trial.
#[derive(Debug, Clone)]
pub struct Found {
    /// The pot's trial (heading solved).
    pub trial: Trial,
    /// Distance of the cue ball's end from the target, m.
    pub distance: f64,
    /// Where it is in the unit box.
    x: Vec<f64>,
}

struct Cost<'a> {
    problem: &'a Problem,
    free: &'a [Var],
    line: &'a Line,
}

impl Cost<'_> {
    fn eval(&self, x: &[f64]) -> Option<Found> {
        let s = stroke(&self.problem.request.bounds, self.free, x);
        let trial = self.problem.aimed(&s, self.line)?;
        let distance = self.problem.distance(&trial);
        Some(Found {
            trial,
            distance,
            x: x.to_vec(),
        })
    }

    fn cost_of(found: &Option<Found>, x: &[f64]) -> f64 {
        let outside: f64 = x.iter().map(|u| (u - u.clamp(0.0, 1.0)).abs()).sum();
        match found {
            Some(f) if f.trial.pots() => f.distance + outside,
            Some(f) => NO_POT + f.distance + outside,
            None => 2.0 * NO_POT + outside,
        }
    }
}

impl CostFunction for Cost<'_> {
    type Param = Vec<f64>;
    type Output = f64;

    fn cost(&self, x: &Vec<f64>) -> Result<f64, Error> {
        Ok(Cost::cost_of(&self.eval(x), x))
    }
}

/// The grid of starts in the unit box.
fn starts(free: &[Var]) -> Vec<Vec<f64>> {
    let mut out: Vec<Vec<f64>> = vec![Vec::new()];
    for v in free {
        let values: Vec<f64> = match v {
            Var::Speed => (0..SPEEDS)
                .map(|i| (i as f64 + 0.5) / SPEEDS as f64)
                .collect(),
            Var::Side => SIDES.to_vec(),
            Var::Height => HEIGHTS.to_vec(),
            Var::Elevation => ELEVATIONS.to_vec(),
            Var::Mouth => MOUTHS.to_vec(),
        };
        out = out
            .iter()
            .flat_map(|p| {
                values.iter().map(move |&u| {
                    let mut q = p.clone();
                    q.push(u);
                    q
                })
            })
            .collect();
    }
    out
}

/// Nelder–Mead from `start` until the cost is under `target`.
fn refine(cost: &Cost<'_>, start: &Found, target: f64, size: f64) -> Found {
    let n = start.x.len();
    if n == 0 {
        return start.clone();
    }
    let mut simplex = vec![start.x.clone()];
    for k in 0..n {
        let mut v = start.x.clone();
        // Step inward so that the simplex starts inside the box.
        v[k] += if v[k] > 0.5 { -size } else { size };
        simplex.push(v);
    }
    let run = NelderMead::new(simplex)
        .with_sd_tolerance(1e-12)
        .and_then(|solver| {
            Executor::new(
                Cost {
                    problem: cost.problem,
                    free: cost.free,
                    line: cost.line,
                },
                solver,
            )
            .configure(|s| s.max_iters(MAX_ITERS).target_cost(target))
            .run()
        });
    let best_x = run
        .ok()
        .and_then(|r| r.state().get_best_param().cloned())
        .unwrap_or_else(|| start.x.clone());
    match cost.eval(&best_x) {
        Some(f) if f.trial.pots() && f.distance < start.distance => f,
        _ => start.clone(),
    }
}

/// The stages of the search: direct pots first; the other kinds only if those do not reach
/// the target (or give too few routes).
const STAGES: [&[ShotKind]; 2] = [
    &[ShotKind::Direct],
    &[ShotKind::Double, ShotKind::Plant, ShotKind::Kiss],
];

/// Potting points a local grid is laid around when the grid's seeds do not reach the target.
const DENSE_CENTRES: usize = 6;

/// Half the grid's spacing along each free variable (the unit box).
fn half_spacing(free: &[Var]) -> Vec<f64> {
    free.iter()
        .map(|v| match v {
            Var::Speed => 0.5 / SPEEDS as f64,
            Var::Side => 0.5 * (SIDES[1] - SIDES[0]),
            Var::Height => 0.5 * (HEIGHTS[1] - HEIGHTS[0]),
            Var::Elevation => 0.5 * (ELEVATIONS[1] - ELEVATIONS[0]),
            Var::Mouth => 0.5 * (MOUTHS[1] - MOUTHS[0]),
        })
        .collect()
}

/// The points of a local grid around `x`: every combination of -h, 0, +h along each variable
/// but `x` itself.
fn local_grid(x: &[f64], h: &[f64]) -> Vec<Vec<f64>> {
    let mut out: Vec<Vec<f64>> = vec![Vec::new()];
    for (&c, &hk) in x.iter().zip(h) {
        out = out
            .iter()
            .flat_map(|p| {
                [-hk, 0.0, hk].into_iter().map(move |d| {
                    let mut q = p.clone();
                    q.push((c + d).clamp(0.0, 1.0));
                    q
                })
            })
            .collect();
    }
    out.retain(|p| p.as_slice() != x);
    out
}

/// True when the search has what it was asked for.
fn done(refined: &[Found], routes: usize, tol: f64) -> bool {
    refined.len() >= routes && refined.iter().any(|f| f.distance <= tol)
}

/// The best potting stroke of each route among `found` (at most [`MAX_SEEDS`], nearest
/// first), refined two at a time until the search is done; the refined strokes are added to
/// `refined`.
fn seed_and_refine(
    problem: &Problem,
    free: &[Var],
    found: &[Found],
    refined: &mut Vec<Found>,
    routes: usize,
) {
    let tol = problem.request.tolerance;
    let target = 0.25 * tol;
    let mut by_route: BTreeMap<Route, Found> = BTreeMap::new();
    for f in found.iter().filter(|f| f.trial.pots()) {
        let slot = by_route
            .entry(f.trial.route.clone())
            .or_insert_with(|| f.clone());
        if f.distance < slot.distance {
            *slot = f.clone();
        }
    }
    let mut seeds: Vec<Found> = by_route.into_values().collect();
    seeds.sort_by(|a, b| a.distance.total_cmp(&b.distance));
    seeds.truncate(MAX_SEEDS);
    for batch in seeds.chunks(BATCH) {
        if done(refined, routes, tol) {
            break;
        }
        let more: Vec<Found> = batch
            .par_iter()
            .map(|s| {
                let cost = Cost {
                    problem,
                    free,
                    line: &s.trial.route.line,
                };
                let f = refine(&cost, s, target, SIMPLEX);
                if f.distance > tol {
                    // Once more from where it got to, with a smaller simplex.
                    refine(&cost, &f, target, 0.25 * SIMPLEX)
                } else {
                    f
                }
            })
            .collect();
        refined.extend(more);
    }
}

/// Evaluates strokes at `points` of the unit box, each on its line, in parallel.
fn evaluate(problem: &Problem, free: &[Var], points: &[(&Line, Vec<f64>)]) -> Vec<Found> {
    points
        .par_iter()
        .map(|(line, x)| {
            Cost {
                problem,
                free,
                line,
            }
            .eval(x)
        })
        .collect::<Vec<Option<Found>>>()
        .into_iter()
        .flatten()
        .collect()
}

/// The best pot found on each route of the cue ball, best first; empty if no stroke pots.
///
/// By stages (direct pots, then the other kinds): a grid of starts on every line of the stage;
/// the best start of each route refined by Nelder–Mead; and if that does not reach the
/// target, a finer local grid around the potting starts nearest it, refined likewise.
pub fn search(problem: &Problem, routes: usize) -> Vec<Found> {
    let free = free_vars(&problem.request.bounds);
    let lines = problem.requested_lines();
    let tol = problem.request.tolerance;
    let grid = starts(&free);
    let h = half_spacing(&free);
    let mut refined: Vec<Found> = Vec::new();
    for stage in STAGES {
        if done(&refined, routes, tol) {
            break;
        }
        let jobs: Vec<(&Line, Vec<f64>)> = lines
            .iter()
            .filter(|l| stage.contains(&l.kind))
            .flat_map(|l| grid.iter().map(move |x| (l, x.clone())))
            .collect();
        let mut potting: Vec<Found> = evaluate(problem, &free, &jobs)
            .into_iter()
            .filter(|f| f.trial.pots())
            .collect();
        seed_and_refine(problem, &free, &potting, &mut refined, routes);
        if done(&refined, routes, tol) {
            break;
        }
        potting.sort_by(|a, b| a.distance.total_cmp(&b.distance));
        let dense: Vec<(&Line, Vec<f64>)> = potting
            .iter()
            .take(DENSE_CENTRES)
            .flat_map(|f| {
                local_grid(&f.x, &h)
                    .into_iter()
                    .map(move |x| (&f.trial.route.line, x))
            })
            .collect();
        let more = evaluate(problem, &free, &dense);
        seed_and_refine(problem, &free, &more, &mut refined, routes);
    }
    refined.sort_by(|a, b| a.distance.total_cmp(&b.distance));
    // A refinement may have crossed onto another seed's route: keep the best of each.
    let mut seen = Vec::new();
    refined.retain(|f| {
        let fresh = !seen.contains(&f.trial.route);
        seen.push(f.trial.route.clone());
        fresh
    });
    refined
}
