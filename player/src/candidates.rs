//! The pots open from a frame: every ball on into every pocket (with the nomination that makes
//! it the ball on), each a planner problem on the frame's balls, and every line of each that
//! the planner's geometry leaves open (direct, doubles, plants through a ball on, kisses),
//! ranked by a first estimate of what it is worth.

use crate::chance::Direct;
use crate::value::{Valuer, ball_value};
use snooker_engine::{BallKind, Setup, Vec3};
use snooker_planner::{Bounds, Interval, Line, Problem, Request, ShotKind};
use snooker_rules::{Colour, Frame, On};

/// Elevation of the cue for every stroke, rad (2°: a cue just clear of the cushion rail; far
/// enough from level that the elevation's noise never reaches it: 20 standard deviations of
/// the standard noise).
pub const ELEVATION: f64 = 2.0 * std::f64::consts::PI / 180.0;
/// The first estimate of a line that is not a direct pot, as a share of the ball's worth:
/// below any direct pot worth trying, so that doubles, plants and kisses are planned when the
/// budget allows after the direct pots, or when there is none.
pub const OTHER_LINE_PRIOR: f64 = 0.1;

/// A ball on and a pocket: the planner's problem of potting it, on the frame with the
/// nomination that makes it the ball on.
#[derive(Debug)]
pub struct Target {
    /// Index of the ball (in the frame's balls).
    pub ball: usize,
    /// Index of the pocket (in the table's pockets).
    pub pocket: usize,
    /// The nomination the stroke needs.
    pub nominated: Option<Colour>,
    /// The frame with that nomination.
    pub frame: Frame,
    /// The planner's problem.
    pub problem: Problem,
}

impl Target {
    /// The names of what `line` goes via (the play log's `via`): the ball a plant strikes
    /// first or a kiss glances off, or the cushions a double's object ball meets, in order;
    /// none for a direct pot.
    pub fn via(&self, line: &Line) -> Vec<String> {
        match line.ball {
            Some(b) => vec![self.frame.balls()[b].id.clone()],
            None => line
                .cushions
                .iter()
                .map(|&c| self.frame.table().cushions[c].name.clone())
                .collect(),
        }
    }

    /// The id of the ball the cue ball is sent at first on `line` (the play log's `ball`): a
    /// plant's first ball, else the ball potted.
    pub fn first_ball(&self, line: &Line) -> String {
        match (line.kind, line.ball) {
            (ShotKind::Plant, Some(b)) => self.frame.balls()[b].id.clone(),
            _ => self.frame.balls()[self.ball].id.clone(),
        }
    }
}

/// A line to try: its target and a first estimate of its worth (points).
#[derive(Debug, Clone, PartialEq)]
pub struct LineCandidate {
    /// Index into the targets.
    pub target: usize,
    /// The line.
    pub line: Line,
    /// Estimated worth, points (chance times the ball's worth).
    pub estimate: f64,
    /// The pot's chance in closed form ([`Direct::chance`]; [`OTHER_LINE_PRIOR`] for a line
    /// that is not a direct pot).
    pub chance: f64,
}

/// The nomination a stroke at the ball of `kind` needs in `frame`, if one is needed: the
/// colour itself when a colour is on or when it is played as a free ball. With a free ball
/// and the ball on itself played (a red, or the closing colour), none: the free ball is
/// declined ([`Frame::with_nomination`]), since a nominated free ball must be hit first
/// (WPBSA Section 3 Rule 12(c)(i)).
pub fn nomination(frame: &Frame, kind: BallKind) -> Option<Colour> {
    let s = frame.state();
    let needed = s.on == On::Colour || s.free_ball;
    if !needed {
        return None;
    }
    Colour::of(kind).filter(|c| frame.legal_nominations().contains(c))
}

/// The search's bounds for the player's strokes: the planner's default speeds and offsets,
/// the cue at [`ELEVATION`].
pub fn bounds(frame: &Frame) -> Bounds {
    let mut b = Bounds::default_for(frame.params());
    b.elevation = Interval {
        lo: ELEVATION,
        hi: ELEVATION,
    };
    b
}

/// The planner's problem of potting ball `ball` of `frame` in pocket `pocket`, with plants
/// allowed through the balls in `plant_balls`.
pub fn problem(
    frame: &Frame,
    ball: usize,
    pocket: usize,
    plant_balls: &[String],
) -> Option<Problem> {
    let cue = frame.cue_index()?;
    let balls = frame.balls();
    let at = balls[cue].state.pos;
    let mut req = Request::new(
        &balls[ball].id,
        &frame.table().pockets[pocket].name,
        [at.x, at.y],
        frame.params(),
    );
    req.cue_ball = balls[cue].id.clone();
    req.bounds = bounds(frame);
    req.samples = 1;
    req.alternatives = 0;
    req.plant_balls = Some(plant_balls.to_vec());
    let setup = Setup {
        table: frame.table().clone(),
        params: *frame.params(),
        models: *frame.models(),
        balls: balls.to_vec(),
    };
    Problem::for_setup(setup, *frame.options(), req).ok()
}

/// Every ball on of `frame` (the cue ball placed) into every pocket.
pub fn targets(frame: &Frame) -> Vec<Target> {
    let s = frame.state();
    let balls = frame.balls();
    // A plant's first ball must be on as well: another red with reds on (a free ball is
    // never planted).
    let plant_balls: Vec<String> = if s.on == On::Red && !s.free_ball {
        balls
            .iter()
            .filter(|b| b.kind == BallKind::Red)
            .map(|b| b.id.clone())
            .collect()
    } else {
        Vec::new()
    };
    let mut out = Vec::new();
    for b in frame.balls_on() {
        let nominated = nomination(frame, balls[b].kind);
        let Ok(f) = frame.with_nomination(nominated) else {
            continue;
        };
        if !f.is_on(balls[b].kind) {
            continue;
        }
        let plants: Vec<String> = plant_balls
            .iter()
            .filter(|id| **id != balls[b].id)
            .cloned()
            .collect();
        for pocket in 0..frame.table().pockets.len() {
            if let Some(problem) = problem(&f, b, pocket, &plants) {
                out.push(Target {
                    ball: b,
                    pocket,
                    nominated,
                    frame: f.clone(),
                    problem,
                });
            }
        }
    }
    out
}

/// The open lines of `targets`, best estimate first (ties in the targets' order).
pub fn lines(targets: &[Target], valuer: &Valuer) -> Vec<LineCandidate> {
    let mut out = Vec::new();
    for (k, t) in targets.iter().enumerate() {
        let f = &t.frame;
        let r = f.params().ball_radius;
        let balls = f.balls();
        let value = ball_value(f, balls[t.ball].kind);
        let worth = value + valuer.future(f, value);
        let Some(cue) = f.cue_index() else {
            continue;
        };
        let flat = |v: Vec3| Vec3::new(v.x, v.y, 0.0);
        let pocket = &f.table().pockets[t.pocket];
        for line in t.problem.requested_lines() {
            let chance = match line.kind {
                ShotKind::Direct => Direct::new(
                    flat(balls[cue].state.pos),
                    flat(balls[t.ball].state.pos),
                    pocket,
                    r,
                )
                .map_or(0.0, |d| d.chance(pocket, valuer.sd, r)),
                _ => OTHER_LINE_PRIOR,
            };
            out.push(LineCandidate {
                target: k,
                line,
                estimate: chance * worth,
                chance,
            });
        }
    }
    out.sort_by(|a, b| b.estimate.total_cmp(&a.estimate));
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn with_a_free_ball_the_ball_on_is_played_declining_it_and_a_colour_as_the_free_ball() {
        let text = std::fs::read_to_string(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/../rules/tests/frames/free_ball_red_first.toml"
        ))
        .unwrap()
        .replace("nominated = \"blue\"\n", "");
        // The position without its strike (a strike needs the nomination).
        let (head, rest) = text.split_once("[cue]").unwrap();
        let text = format!("{head}{}", &rest[rest.find("[[balls]]").unwrap()..]);
        let frame = snooker_rules::parse(&text, "free_ball_red_first.toml")
            .unwrap()
            .frame;
        assert!(frame.state().free_ball && frame.state().nominated.is_none());
        // A red is the ball on: no nomination, and the frame played declines the free ball.
        assert_eq!(nomination(&frame, BallKind::Red), None);
        let declined = frame.with_nomination(None).unwrap();
        assert!(!declined.state().free_ball);
        // A colour is nominated as the free ball.
        assert_eq!(nomination(&frame, BallKind::Blue), Some(Colour::Blue));
    }

    #[test]
    fn each_lines_via_and_first_ball_name_what_it_goes_by() {
        let valuer = Valuer::new(&snooker_planner::Noise::STANDARD, &Default::default());
        let cushions: Vec<String> = {
            let f = Frame::open_table(15, 1);
            f.table().cushions.iter().map(|c| c.name.clone()).collect()
        };
        let mut seen = [0; 4];
        for seed in 1..=4 {
            let frame = Frame::open_table(15, seed);
            let targets = targets(&frame);
            for lc in lines(&targets, &valuer) {
                let t = &targets[lc.target];
                let pot = t.frame.balls()[t.ball].id.clone();
                let (via, first) = (t.via(&lc.line), t.first_ball(&lc.line));
                match lc.line.kind {
                    ShotKind::Direct => assert!(via.is_empty() && first == pot),
                    ShotKind::Double => {
                        assert!(!via.is_empty() && first == pot, "{via:?}");
                        assert!(via.iter().all(|c| cushions.contains(c)), "{via:?}");
                    }
                    ShotKind::Plant => assert!(via == [first.clone()] && first != pot),
                    ShotKind::Kiss => assert!(via.len() == 1 && via[0] != pot && first == pot),
                }
                seen[lc.line.kind as usize] += 1;
            }
        }
        // Every kind was met (else the test shows nothing of it).
        assert!(seen.iter().all(|&n| n > 0), "{seen:?}");
    }
}
