//! Aiming to pot: the line's geometric heading ([`crate::line`]: for a direct pot the cue
//! ball's centre sent to the point two radii behind the object ball on its line to an aim
//! point in the pocket's mouth), then corrected on the engine's own result, so that throw,
//! squirt, swerve and the cushions' rebounds are all allowed for (thesis §7.1.5: the object
//! ball's heading after its last contact is what pots it).

use crate::line::{Line, ShotKind};
use crate::problem::Problem;
use crate::trial::{Departure, Trial, angle};
use snooker_engine::cue::Cue;
use snooker_engine::{EventKind, Shot, Vec3};

/// Heading error at which the aim is taken as found, rad: the cue ball's end position then
/// moves by micrometres (a pot's window is ~1e-2 rad wide).
const AIM_TOLERANCE: f64 = 1e-7;
/// Most simulations of one aim correction.
const MAX_AIM_TRIALS: usize = 12;
/// Most simulations of one aim correction along a double, plant or kiss (its geometric
/// heading is further from the engine's).
const MAX_LINE_AIM_TRIALS: usize = 20;
/// Samples of the object ball's path searched for where it crosses the aim point's line.
const PATH_SAMPLES: usize = 256;
/// Share of the mouth's half-width (less a ball's radius) the aim point may move across it.
const MOUTH_REACH: f64 = 0.8;

/// The strike variables other than the heading, and where in the pocket's mouth to aim.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Stroke {
    /// Cue speed, m/s.
    pub speed: f64,
    /// Side offset, m.
    pub side: f64,
    /// Height offset, m.
    pub height: f64,
    /// Elevation, rad.
    pub elevation: f64,
    /// Aim point across the mouth, -1..1 (0: its middle).
    pub mouth: f64,
}

impl Stroke {
    /// The strike with heading `aim`.
    pub fn with_aim(&self, aim: f64) -> Cue {
        Cue {
            speed: self.speed,
            aim,
            offset: [self.side, self.height],
            elevation: self.elevation,
        }
    }
}

impl Problem {
    /// The point of the pocket's mouth a fraction `u` (-1..1) of the way across it.
    pub fn aim_point(&self, u: f64) -> Vec3 {
        let pocket = &self.setup.table.pockets[self.pocket];
        let r = self.setup.params.ball_radius;
        let inward = (pocket.centre - pocket.mouth).xy();
        let across = if inward.norm() > 0.0 {
            Vec3::new(-inward.y, inward.x, 0.0).normalize()
        } else {
            Vec3::zeros()
        };
        let half = (0.5 * pocket.mouth_width - r).max(0.0);
        pocket.mouth + MOUTH_REACH * u.clamp(-1.0, 1.0) * half * across
    }

    /// How far the object ball's path after `dep` misses `at`, as an angle seen from where
    /// it departed (rad; the sign of [`angle`]): the point where the path crosses the line
    /// through `at` across the way from the departure to it, found on the exact track by
    /// bisection. The path is followed only until the ball's next contact (a jaw, a cushion,
    /// a ball) or its fall: beyond, it is continued along the velocity it had (a jaw's
    /// rebound would make the measure jump just where the pot is); a ball that stops short
    /// is measured where it stops.
    fn path_error(&self, shot: &snooker_engine::Shot, dep: &Departure, at: Vec3) -> f64 {
        let p = &shot.params;
        let o = self.object;
        let track = &shot.tracks[o];
        let way = (at - dep.pos).xy();
        let len = way.norm();
        if len == 0.0 {
            return 0.0;
        }
        let u = Vec3::new(way.x / len, way.y / len, 0.0);
        let ahead = |t: f64| (track.state_at(t, p).pos - at).xy().dot(&u.xy());
        let end = shot
            .events
            .iter()
            .find(|e| {
                e.t > dep.t
                    && e.balls.contains(&o)
                    && matches!(
                        e.kind,
                        EventKind::BallBall | EventKind::BallCushion | EventKind::BallPocket
                    )
            })
            .map_or(shot.duration, |e| e.t);
        let mut crossing = None;
        let mut t0 = dep.t;
        for k in 1..=PATH_SAMPLES {
            let t1 = dep.t + (end - dep.t) * k as f64 / PATH_SAMPLES as f64;
            if ahead(t1) >= 0.0 {
                let (mut lo, mut hi) = (t0, t1);
                for _ in 0..48 {
                    let mid = 0.5 * (lo + hi);
                    if ahead(mid) >= 0.0 {
                        hi = mid;
                    } else {
                        lo = mid;
                    }
                }
                crossing = Some(hi);
                break;
            }
            t0 = t1;
        }
        let q = match crossing {
            Some(t) => track.state_at(t, p).pos,
            None => {
                // Continued along its velocity at the contact (or where it stopped).
                let s = track.state_at(end, p);
                let towards = s.vel.xy().dot(&u.xy());
                if towards > 1e-9 {
                    s.pos + (-(s.pos - at).xy().dot(&u.xy()) / towards) * s.vel
                } else {
                    s.pos
                }
            }
        };
        angle(q - dep.pos, at - dep.pos)
    }

    /// The heading that sends the object ball along `line` at the stroke's aim point, found
    /// from the line's geometric heading ([`Problem::line_aim`]) on the engine's result: the
    /// secant method, safeguarded once the root is bracketed (regula falsi, Illinois) and its
    /// steps bounded before; the trial of the best heading found (None if the line's
    /// geometry is closed or no heading could be struck at all).
    pub fn aimed(&self, stroke: &Stroke, line: &Line) -> Option<Trial> {
        self.aimed_shot(stroke, line).map(|(t, _)| t)
    }

    /// [`Problem::aimed`], with the shot of the trial returned.
    pub fn aimed_shot(&self, stroke: &Stroke, line: &Line) -> Option<(Trial, Shot)> {
        let at = self.aim_point(stroke.mouth);
        let (first, cut) = self.line_aim(line, at)?;
        let r = self.setup.params.ball_radius;
        let balls = &self.setup.balls;
        let struck = match line.kind {
            ShotKind::Plant => line.ball.unwrap_or(self.object),
            _ => self.object,
        };
        let d = (balls[struck].state.pos - balls[self.cue].state.pos)
            .xy()
            .norm();
        // A heading change moving the contact by a hundredth of a radius: the second point.
        let step = 0.01 * r * cut.cos().abs().max(0.1) / d.max(r);
        // Largest move of one secant step before the root is bracketed: the heading range
        // over which the cue ball's contact moves by a radius.
        let max_move = 100.0 * step;
        let trials = match line.kind {
            ShotKind::Direct => MAX_AIM_TRIALS,
            _ => MAX_LINE_AIM_TRIALS,
        };
        let mut best: Option<(f64, Trial, Shot)> = None;
        let mut prev: Option<(f64, f64)> = None;
        // Headings on either side of the root, with their errors, once found.
        let mut bracket: Option<((f64, f64), (f64, f64))> = None;
        let mut aim = first;
        for _ in 0..trials {
            let cue = stroke.with_aim(aim);
            let Some(shot) = self.run(&cue) else {
                break;
            };
            let t = self.judge(&cue, line, &shot);
            let Some(dep) = t.departure else {
                // Off the line: back towards the last heading that kept to it.
                match prev {
                    Some((a, _)) => aim = 0.5 * (aim + a),
                    None => break,
                }
                continue;
            };
            let e = match line.kind {
                // The object ball leaves a ball it was at rest against nearly without spin:
                // its heading then is its path.
                ShotKind::Direct | ShotKind::Plant => angle(dep.vel, at - dep.pos),
                // Off a cushion or a kiss it carries spin, and its path bends: where it
                // crosses the line through the aim point across its way is what pots it.
                ShotKind::Double | ShotKind::Kiss => self.path_error(&shot, &dep, at),
            };
            let better = best.as_ref().is_none_or(|(be, _, _)| e.abs() < be.abs());
            let done = e.abs() < AIM_TOLERANCE;
            if better {
                best = Some((e, t, shot));
            }
            if done {
                break;
            }
            bracket = match (bracket, prev) {
                (Some((lo, hi)), _) => Some(if e.signum() == lo.1.signum() {
                    // Illinois: the end kept twice has its error halved.
                    ((aim, e), (hi.0, 0.5 * hi.1))
                } else {
                    ((aim, e), lo)
                }),
                (None, Some((a0, e0))) if e0.signum() != e.signum() => Some(((aim, e), (a0, e0))),
                (None, _) => None,
            };
            let next = match (bracket, prev) {
                (Some(((a1, e1), (a0, e0))), _) => a1 - e1 * (a1 - a0) / (e1 - e0),
                (None, Some((a0, e0))) if e != e0 => {
                    let move_ = -e * (aim - a0) / (e - e0);
                    aim + move_.clamp(-max_move, max_move)
                }
                _ => aim + step,
            };
            if (next - aim).abs() < 1e-12 {
                break;
            }
            prev = Some((aim, e));
            aim = next;
        }
        best.map(|(_, t, shot)| (t, shot))
    }
}
