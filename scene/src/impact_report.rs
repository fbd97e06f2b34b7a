//! The report of one impact of the thesis's frictional models (`snooker impact`, and
//! `snooker.impact_ball_ball` / `impact_cushion` in Python): the incoming ball in the terms of
//! the thesis's figures (speed, spins in units of V/R), the state just after the impact and
//! once each ball's slip on the cloth has ended (run by the engine on the open table), its hop,
//! and the normal impulse (thesis §6.1, §6.2; figs. 6.14, 6.15, 6.23).

use serde::{Deserialize, Serialize};
use snooker_engine::impact::ball_ball::mathavan as bb;
use snooker_engine::impact::cushion::mathavan as cush;
use snooker_engine::impact::impulse::{ImpactError, Sample};
use snooker_engine::impact::incoming;
use snooker_engine::motion::{self, airborne};
use snooker_engine::shown::Shown;
use snooker_engine::sim::setup::MAX_SPIN_SPEED;
use snooker_engine::{
    Ball, BallKind, BallState, Models, Motion, Params, Setup, SimError, SimOptions, Table, Vec3,
    simulate,
};

/// Fastest incoming ball accepted, m/s.
pub const MAX_SPEED: f64 = 20.0;
/// Largest spin accepted, units of V/R.
pub const MAX_SPIN: f64 = 10.0;

/// Which impact.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Geometry {
    /// A cue ball moving along +x meets a resting object ball at this cut angle, degrees
    /// (0 = full ball; positive: the object ball to the left).
    BallBall {
        /// Cut angle, degrees.
        cut: f64,
    },
    /// A ball meets the cushion at this angle of incidence from the cushion line, degrees
    /// (90 = perpendicular).
    Cushion {
        /// Angle of incidence, degrees.
        angle: f64,
    },
}

/// An impact to report.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ImpactSpec {
    /// Which impact.
    pub geometry: Geometry,
    /// Speed of the incoming ball, m/s.
    pub speed: f64,
    /// Its topspin, units of V/R (1 = rolling, negative = backspin).
    pub topspin: f64,
    /// Its sidespin, units of V/R (positive = anticlockwise seen from above).
    pub sidespin: f64,
    /// The parameters.
    pub params: Params,
}

/// An impact that cannot be reported.
#[derive(Debug, thiserror::Error)]
pub enum ImpactReportError {
    /// The incoming speed is outside (0, [`MAX_SPEED`]].
    #[error("speed must lie in (0, {MAX_SPEED}] m/s, got {}", Shown(*.0))]
    Speed(f64),
    /// A spin is outside [-[`MAX_SPIN`], [`MAX_SPIN`]].
    #[error("{name} must lie in [-{MAX_SPIN}, {MAX_SPIN}] (units of V/R), got {}", Shown(*.value))]
    Spin {
        /// `topspin` or `sidespin`.
        name: &'static str,
        /// The value given.
        value: f64,
    },
    /// Speed and spins give a surface speed beyond any shot.
    #[error(
        "speed {speed} with these spins gives the ball a surface speed R|w| of {surface} m/s, \
         beyond any shot (at most {MAX_SPIN_SPEED} m/s)"
    )]
    SurfaceSpeed {
        /// The speed given, m/s.
        speed: f64,
        /// The surface speed, m/s.
        surface: f64,
    },
    /// The approach along the contact normal is too slow to resolve (a tiny speed, or a
    /// grazing angle or cut, underflows it towards zero).
    #[error(
        "speed {} m/s approaches along the contact normal at {} m/s, below {} m/s: too slow \
         an approach for an impact (a larger speed, angle or smaller cut)",
        Shown(*.speed),
        Shown(*.normal),
        Shown(MIN_NORMAL_SPEED)
    )]
    NormalSpeed {
        /// The speed given, m/s.
        speed: f64,
        /// Its component along the contact normal, m/s.
        normal: f64,
    },
    /// The cut is outside (-89, 89) degrees.
    #[error("cut must lie in (-89, 89) degrees, got {}", Shown(*.0))]
    Cut(f64),
    /// The angle is outside (0, 90] degrees.
    #[error("angle must lie in (0, 90] degrees, got {}", Shown(*.0))]
    Angle(f64),
    /// The impact solver failed.
    #[error("the impact: {0}")]
    Impact(#[from] ImpactError),
    /// The slip after it could not be run to its end.
    #[error("the slip after the impact: {0}")]
    Slip(#[from] SimError),
}

impl ImpactReportError {
    /// The input at fault (`speed`, `topspin`, `sidespin`, `cut`, `angle`), which the message
    /// begins with; none for a failure of the solver.
    pub fn field(&self) -> Option<&'static str> {
        match self {
            ImpactReportError::Speed(_)
            | ImpactReportError::SurfaceSpeed { .. }
            | ImpactReportError::NormalSpeed { .. } => Some("speed"),
            ImpactReportError::Spin { name, .. } => Some(name),
            ImpactReportError::Cut(_) => Some("cut"),
            ImpactReportError::Angle(_) => Some("angle"),
            ImpactReportError::Impact(_) | ImpactReportError::Slip(_) => None,
        }
    }
}

/// An impact's report: the document, the solver's samples (if asked for) and the axes a plot
/// of the slips uses (horizontal and vertical directions across the contact).
#[derive(Debug, Clone)]
pub struct ImpactReport {
    /// The result document (`snooker impact --json`).
    pub doc: ImpactRecord,
    /// The plot's axes.
    pub axes: (Vec3, Vec3),
}

/// The impact asked for, as the report repeats it.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ImpactInput {
    /// `ball-ball` or `cushion`.
    pub setup: String,
    /// Incoming speed, m/s.
    pub speed: f64,
    /// Cut angle (ball-ball) or angle of incidence from the cushion line, degrees.
    pub angle_deg: f64,
    /// Topspin, units of V/R.
    pub topspin_v_over_r: f64,
    /// Sidespin, units of V/R.
    pub sidespin_v_over_r: f64,
    /// Ball-ball friction.
    pub mu_ball: f64,
    /// Ball-ball restitution.
    pub e_ball: f64,
    /// Cushion friction.
    pub mu_cushion: f64,
    /// Cushion restitution.
    pub e_cushion: f64,
    /// Cloth sliding friction.
    pub mu_slide: f64,
}

/// A ball's motion as the report describes it (directions from the incoming ball's path or
/// the cushion line).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct MotionSummary {
    /// Horizontal speed, m/s.
    pub speed: f64,
    /// Heading, degrees.
    pub direction_deg: f64,
    /// Vertical speed, m/s.
    pub vertical_speed: f64,
    /// Angular velocity, rad/s.
    pub spin: [f64; 3],
    /// Its vertical part, rad/s.
    pub sidespin: f64,
    /// Motion phase.
    pub motion: Motion,
}

/// One ball after the impact.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct BallAfter {
    /// Just after the impact.
    pub after_impact: MotionSummary,
    /// Once its slip on the cloth has ended.
    pub after_slip: MotionSummary,
    /// Peak height of its hop, m (0: none).
    pub hop_height: f64,
    /// Length of the hop, m.
    pub hop_length: f64,
    /// Distance covered until the slip ends, m.
    pub distance_to_end_of_slip: f64,
    /// The rebound's angle from the cushion line, degrees (cushion impacts).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub rebound_angle_deg: Option<f64>,
}

/// The report of one impact (`snooker impact --json`).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ImpactRecord {
    /// What was asked.
    pub input: ImpactInput,
    /// The cue ball (ball-ball).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub cue_ball: Option<BallAfter>,
    /// The object ball (ball-ball).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub object_ball: Option<BallAfter>,
    /// The ball (cushion).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub ball: Option<BallAfter>,
    /// The normal impulse, N s.
    pub impulse: f64,
    /// The approach speed along the cushion's plan normal, m/s (cushion).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub normal_speed: Option<f64>,
    /// A reminder of the units.
    pub units: String,
}

/// One ball's state, as reported.
fn describe(s: &BallState) -> MotionSummary {
    let v = Vec3::new(s.vel.x, s.vel.y, 0.0);
    MotionSummary {
        speed: v.norm(),
        direction_deg: v.y.atan2(v.x).to_degrees(),
        vertical_speed: s.vel.z,
        spin: [s.spin.x, s.spin.y, s.spin.z],
        sidespin: s.spin.z,
        motion: s.motion,
    }
}

/// What happens to a ball after an impact until its slip on the cloth ends, run by the engine
/// on the open table: its hop, if it left the cloth, then its slide. The ball's state once its
/// slip has ended (rolling, spinning or at rest; still sliding if the cloth has no friction),
/// the hop's peak height and length, and the distance covered until then.
fn after_slip(s: BallState, p: &Params) -> Result<(BallState, f64, f64, f64), SimError> {
    let setup = Setup {
        table: Table::open(),
        params: *p,
        models: Models::default(),
        balls: vec![Ball {
            id: "ball".into(),
            kind: BallKind::Other,
            state: s,
        }],
    };
    let opts = SimOptions {
        horizon: Some(SimOptions::default().max_time),
        ..SimOptions::default()
    };
    let shot = simulate(&setup, &opts)?;
    let segments = &shot.tracks[0].segments;
    let first = segments[0].state;
    let (hop_height, hop_length) = if first.motion == Motion::Airborne {
        let landed = segments[1..].first().map_or(first.pos, |g| g.state.pos);
        let length = Vec3::new(landed.x - first.pos.x, landed.y - first.pos.y, 0.0).norm();
        (airborne::peak_height(&first, p), length)
    } else {
        (0.0, 0.0)
    };
    let end = segments
        .iter()
        .find(|g| !matches!(g.state.motion, Motion::Sliding | Motion::Airborne))
        .map_or_else(|| shot.final_states()[0], |g| g.state);
    let dist = Vec3::new(end.pos.x - s.pos.x, end.pos.y - s.pos.y, 0.0).norm();
    Ok((end, hop_height, hop_length, dist))
}

/// The report of one ball after the impact.
fn ball_report(s: BallState, p: &Params) -> Result<BallAfter, SimError> {
    let (rolled, hop_height, hop_length, dist) = after_slip(s, p)?;
    Ok(BallAfter {
        after_impact: describe(&motion::settle(s, p)),
        after_slip: describe(&rolled),
        hop_height,
        hop_length,
        distance_to_end_of_slip: dist,
        rebound_angle_deg: None,
    })
}

/// Checks the incoming ball of `spec`.
fn check(spec: &ImpactSpec) -> Result<(), ImpactReportError> {
    let speed = spec.speed;
    if !(speed.is_finite() && speed > 0.0 && speed <= MAX_SPEED) {
        return Err(ImpactReportError::Speed(speed));
    }
    for (name, value) in [("topspin", spec.topspin), ("sidespin", spec.sidespin)] {
        if !(value.is_finite() && value.abs() <= MAX_SPIN) {
            return Err(ImpactReportError::Spin { name, value });
        }
    }
    let surface = speed * spec.topspin.hypot(spec.sidespin);
    if surface > MAX_SPIN_SPEED {
        return Err(ImpactReportError::SurfaceSpeed { speed, surface });
    }
    match spec.geometry {
        Geometry::BallBall { cut } if !(cut.is_finite() && cut.abs() < 89.0) => {
            Err(ImpactReportError::Cut(cut))
        }
        Geometry::Cushion { angle } if !(angle.is_finite() && angle > 0.0 && angle <= 90.0) => {
            Err(ImpactReportError::Angle(angle))
        }
        Geometry::BallBall { cut } => normal_speed(speed, speed * cut.to_radians().cos()),
        Geometry::Cushion { angle } => normal_speed(speed, speed * angle.to_radians().sin()),
    }
}

/// The slowest approach along the contact normal the report resolves, m/s: a nanometre a
/// second, far below any shot, and far above where the solver's state (in units of the
/// approach speed) would underflow (an approach of 5e-324 m/s was 0, "not approaching").
pub const MIN_NORMAL_SPEED: f64 = 1e-9;

fn normal_speed(speed: f64, normal: f64) -> Result<(), ImpactReportError> {
    if normal < MIN_NORMAL_SPEED {
        return Err(ImpactReportError::NormalSpeed { speed, normal });
    }
    Ok(())
}

/// The report of the impact `spec`; `trace`, if given, receives the solver's samples.
pub fn impact_report(
    spec: &ImpactSpec,
    trace: Option<&mut Vec<Sample>>,
) -> Result<ImpactReport, ImpactReportError> {
    check(spec)?;
    let (p, speed) = (&spec.params, spec.speed);
    let (setup, angle) = match spec.geometry {
        Geometry::BallBall { cut } => ("ball-ball", cut),
        Geometry::Cushion { angle } => ("cushion", angle),
    };
    let mut doc = ImpactRecord {
        input: ImpactInput {
            setup: setup.into(),
            speed,
            angle_deg: angle,
            topspin_v_over_r: spec.topspin,
            sidespin_v_over_r: spec.sidespin,
            mu_ball: p.mu_ball,
            e_ball: p.e_ball,
            mu_cushion: p.mu_cushion,
            e_cushion: p.e_cushion,
            mu_slide: p.mu_slide,
        },
        cue_ball: None,
        object_ball: None,
        ball: None,
        impulse: 0.0,
        normal_speed: None,
        units: "SI; directions in degrees from the incoming ball's path (ball-ball) or the \
                cushion line (cushion)"
            .into(),
    };
    let axes = match spec.geometry {
        Geometry::BallBall { cut } => {
            let (cue, obj) =
                incoming::ball_ball(speed, cut.to_radians(), spec.topspin, spec.sidespin, p);
            let out = bb::solve(&cue, &obj, p, trace)?;
            let after = |s: &BallState, i: usize| BallState {
                vel: out.after.vel[i],
                spin: out.after.spin[i],
                ..*s
            };
            let n = (obj.pos - cue.pos).normalize();
            doc.cue_ball = Some(ball_report(after(&cue, 0), p)?);
            doc.object_ball = Some(ball_report(after(&obj, 1), p)?);
            doc.impulse = out.impulse;
            (n.cross(&Vec3::z()).normalize(), Vec3::z())
        }
        Geometry::Cushion { angle } => {
            let rad = angle.to_radians();
            let ball = incoming::cushion(speed, rad, spec.topspin, spec.sidespin, p);
            let out = cush::solve(&ball, Vec3::y(), p, trace)?;
            let b1 = BallState {
                vel: out.after.vel[0],
                spin: out.after.spin[0],
                ..ball
            };
            let n = cush::contact(&ball, Vec3::y(), p).normal;
            doc.ball = Some(BallAfter {
                rebound_angle_deg: Some(b1.vel.y.atan2(b1.vel.x.abs()).to_degrees()),
                ..ball_report(b1, p)?
            });
            doc.impulse = out.impulse;
            doc.normal_speed = Some(speed * rad.sin());
            (Vec3::x(), n.cross(&Vec3::x()))
        }
    };
    Ok(ImpactReport { doc, axes })
}
