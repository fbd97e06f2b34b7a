//! The cross-check stretch by stretch: rapier re-seeded from our engine's state after every
//! impact at which the two engines' impact models differ by design, each stretch between two
//! such impacts compared on its own.
//!
//! With friction, our impacts (thesis §6.1, §6.2: energetic restitution, friction integrated
//! over the normal impulse) and rapier's (Newton's restitution, Coulomb friction once per step)
//! may differ by up to about the friction impulse, a good part of the approach speed. Carried
//! forward, such a difference swamps every later figure (a metre of final position), and a
//! rebound a few degrees apart may send the ball to another cushion: a whole-shot comparison
//! can then neither see an error in a motion law after the first impact nor tell a different
//! sequence from an error. Re-seeding separates the two: each impact's own difference (the
//! change of velocity and spin across it) is measured against its by-design bound
//! ([`crate::tolerance::change_bound`]), and between impacts the motion laws, the detection of
//! the next event, its time and the state just before it are checked from a common state with
//! the derived tolerances, accumulated from zero at the start of each stretch.

use crate::compare::{Comparison, End, Scope, compare};
use crate::digest::{ImpactDigest, Parties, ShotDigest};
use crate::rapier_run::{Rapier, Until};
use crate::tolerance::{Budget, allowances_from};
use serde::Serialize;
use snooker_engine::{BallState, Shot};

/// True when the two engines' models of an impact of `parties` differ by design: every
/// ball-ball and cushion impact when the impacts have `friction`, and every landing (our
/// engine neglects its friction percussion, thesis §6.1.6; rapier's cloth does not).
pub fn differs_by_design(friction: bool, parties: &Parties) -> bool {
    match parties {
        Parties::Landing(_) => true,
        Parties::Balls(..) | Parties::Cushion(..) | Parties::Jaw(..) => friction,
        Parties::Pocket(..) | Parties::OffTable(..) => false,
    }
}

/// One stretch of a run compared on its own.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Stretch {
    /// When it starts, s (rapier is given our engine's state there).
    pub from: f64,
    /// The impact after which it starts ("start" for the first), as a label.
    pub after: String,
    /// The comparison: its impacts (the last one ends the stretch), slide-to-roll
    /// transitions and, for the last stretch, the final positions.
    pub comparison: Comparison,
    /// rapier's steps.
    pub steps: usize,
    /// False when rapier's run ran out of time before the stretch's end.
    pub rapier_finished: bool,
}

impl Stretch {
    /// True when rapier finished and the comparison passed.
    pub fn pass(&self) -> bool {
        self.rapier_finished && self.comparison.pass()
    }
}

/// Where our engine's digest is cut into stretches: the start, then after each impact at which
/// the models differ by design, up to the last compared impact `limit` (a chaotic scene).
/// Returns (index of the impact that starts the stretch, if any; index of the one that ends
/// it, if any).
pub fn cuts(
    ours: &ShotDigest,
    friction: bool,
    limit: Option<usize>,
) -> Vec<(Option<usize>, Option<usize>)> {
    let n = limit.unwrap_or(ours.impacts.len()).min(ours.impacts.len());
    let mut ends: Vec<usize> = (0..n)
        .filter(|&k| differs_by_design(friction, &ours.impacts[k].parties))
        .collect();
    if limit.is_some() && n > 0 && ends.last() != Some(&(n - 1)) {
        ends.push(n - 1);
    }
    let mut out = Vec::new();
    let mut from = None;
    for &k in &ends {
        out.push((from, Some(k)));
        from = Some(k);
    }
    if limit.is_none() {
        out.push((from, None));
    }
    out
}

/// Everything a stretch-by-stretch comparison needs.
pub struct Stretches<'a> {
    /// Our engine's shot (its states at the cuts re-seed rapier).
    pub shot: &'a Shot,
    /// Its digest, normalised.
    pub ours: &'a ShotDigest,
    /// Our engine's starting states.
    pub start: Vec<BallState>,
    /// True when the impacts have friction.
    pub friction: bool,
    /// What of the scene is compared (a chaotic scene: up to the first impact on the pack).
    pub scope: &'a Scope,
    /// Window and speed of [`ShotDigest::normalised`] for rapier's digests.
    pub normalise: (f64, f64),
    /// Time rapier is given beyond our stretch's end, s.
    pub extra_time: f64,
}

/// Runs every stretch of `s` in `rapier` (each from our engine's state at its start) and
/// compares it with the tolerances of `budget` (whose sink is set to the deepest rapier
/// reached over all stretches).
pub fn check(s: &Stretches<'_>, rapier: &mut Rapier<'_>, budget: &Budget) -> Vec<Stretch> {
    let (friction, slow) = (s.friction, s.normalise.1);
    // A contact closing slower is a resting contact (as in the digests), not an impact.
    let ends_stretch =
        move |i: &ImpactDigest| i.approach >= slow && differs_by_design(friction, &i.parties);
    let mut runs = Vec::new();
    for (from_k, to_k) in cuts(s.ours, s.friction, s.scope.impacts) {
        let (from, start) = match from_k {
            None => (0.0, s.start.clone()),
            Some(k) => {
                let t = s.ours.impacts[k].end;
                let balls = s.shot.balls_at(t);
                (t, balls.iter().map(|b| b.state).collect())
            }
        };
        let to = to_k.map_or(f64::INFINITY, |k| s.ours.impacts[k].t);
        let max_time = to.min(s.ours.duration) + s.extra_time;
        let run = rapier.run(from, &start, Until::Impact(&ends_stretch), max_time);
        runs.push((from_k, to_k, from, start, run));
    }
    let budget = Budget {
        sink: runs.iter().map(|r| r.4.sink).fold(budget.sink, f64::max),
        ..*budget
    };
    runs.into_iter()
        .map(|(from_k, to_k, from, start, run)| {
            let to = to_k.map_or(f64::INFINITY, |k| s.ours.impacts[k].t);
            let first = from_k.map_or(0, |k| k + 1);
            let last = to_k.map_or(s.ours.impacts.len(), |k| k + 1);
            let ours = s.ours.stretch(first..last, from, to, &start);
            let theirs = run.digest.normalised(s.normalise.0, s.normalise.1);
            let tol = allowances_from(&ours, &budget, from);
            let chaotic_end = s.scope.impacts.is_some_and(|n| to_k == Some(n - 1));
            let scope = Scope {
                impacts: None,
                skip_after: if chaotic_end {
                    s.scope.skip_after.clone()
                } else {
                    Vec::new()
                },
                end: if to_k.is_some() {
                    End::Impact
                } else {
                    End::Rest
                },
            };
            Stretch {
                from,
                after: from_k.map_or_else(
                    || "start".to_string(),
                    |k| s.ours.impacts[k].parties.label(&s.ours.ids),
                ),
                comparison: compare(&ours, &theirs, &tol, &budget, &scope),
                steps: run.steps,
                rapier_finished: run.finished,
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::digest::Velocities;

    fn digest(parties: Vec<Parties>) -> ShotDigest {
        ShotDigest {
            ids: vec!["cue".into(), "red".into()],
            start: vec![Velocities::default(); 2],
            impacts: parties
                .into_iter()
                .enumerate()
                .map(|(k, parties)| ImpactDigest {
                    t: k as f64,
                    parties,
                    before: vec![Velocities::default(); 2],
                    after: vec![Velocities::default(); 2],
                    end: k as f64,
                    approach: 1.0,
                })
                .collect(),
            rolls: vec![],
            finals: vec![],
            duration: 10.0,
        }
    }

    #[test]
    fn cuts_follow_the_impacts_that_differ_by_design() {
        let d = digest(vec![
            Parties::Balls(0, 1),
            Parties::Landing(0),
            Parties::Cushion(1, "top".into()),
            Parties::Pocket(1, "top-left".into()),
        ]);
        // With friction: after the ball pair, the landing and the cushion; the pot is inside
        // the last stretch.
        assert_eq!(
            cuts(&d, true, None),
            vec![
                (None, Some(0)),
                (Some(0), Some(1)),
                (Some(1), Some(2)),
                (Some(2), None)
            ]
        );
        // Frictionless: only the landing differs by design.
        assert_eq!(
            cuts(&d, false, None),
            vec![(None, Some(1)), (Some(1), None)]
        );
        // A chaotic scene ends with the last compared impact.
        assert_eq!(cuts(&d, false, Some(1)), vec![(None, Some(0))]);
    }
}
