//! A frame of snooker between strokes: the table, the physics, the balls at rest and the
//! [`FrameState`]; checked when made, so that every [`Frame`] can be played and judged. What
//! is on and what may be nominated follow from it (WPBSA Section 3 Rule 3 "Mode of Play").

use crate::colour::Colour;
use crate::error::{FrameError, Key, Problem};
use crate::in_hand::{self, TheD};
use crate::state::{FrameState, On};
use snooker_engine::cue::Cue;
use snooker_engine::{
    Ball, BallKind, Models, Params, Setup, SimOptions, SnookerDims, Table, TableKind, Vec3,
};

/// A frame of snooker between strokes.
#[derive(Clone, Debug, PartialEq)]
pub struct Frame {
    name: String,
    table: Table,
    dims: SnookerDims,
    params: Params,
    models: Models,
    options: SimOptions,
    balls: Vec<Ball>,
    state: FrameState,
}

/// What a ball is to the rules.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Role {
    /// The cue ball.
    Cue,
    /// A red.
    Red,
    /// A colour.
    Colour(Colour),
}

impl Role {
    /// The role of a ball of this kind (`None`: not a ball of snooker).
    pub fn of(kind: BallKind) -> Option<Role> {
        match kind {
            BallKind::Cue => Some(Role::Cue),
            BallKind::Red => Some(Role::Red),
            k => Colour::of(k).map(Role::Colour),
        }
    }
}

fn err(key: Key, problem: Problem) -> FrameError {
    FrameError::new(key, problem)
}

impl Frame {
    /// A frame from its parts, checked: the snooker table a frame file describes
    /// (`Table::snooker` of the default dimensions but for the four pocket sizes); only the cue ball, reds and
    /// colours, each colour and the cue ball once, all at rest; the balls as `state.on` says
    /// (reds on: a red and every colour on the table; a closing colour on: no red, that colour
    /// and every higher one, no lower one); a nomination that can be played; a cue ball on the
    /// table, or in hand and (if placed) in the D touching no ball; every ball on the cloth
    /// (its centre a radius above it); the simulation's limits valid ([`SimOptions::validate`]).
    /// Positions in plan are checked by the engine (on the playing area, no overlaps) when a
    /// strike is played. Errors name the key (`balls[i]` by index into `balls`).
    pub fn new(
        name: impl Into<String>,
        table: Table,
        params: Params,
        models: Models,
        options: SimOptions,
        balls: Vec<Ball>,
        state: FrameState,
    ) -> Result<Frame, FrameError> {
        let dims = match (table.kind, table.dims) {
            (TableKind::Snooker, Some(d)) => d,
            _ => return Err(err(Key::Other("table.kind"), Problem::NotSnookerTable)),
        };
        // The table a frame file can describe (its four pocket sizes, formats.md), so that the
        // frame's file (`to_toml`) reads back to the same frame.
        let of_file = SnookerDims {
            corner_mouth: dims.corner_mouth,
            middle_mouth: dims.middle_mouth,
            jaw_radius: dims.jaw_radius,
            fall_depth: dims.fall_depth,
            ..SnookerDims::default()
        };
        if dims != of_file || table != Table::snooker(&dims) {
            return Err(err(Key::Other("table"), Problem::NotTheFilesTable));
        }
        if options.horizon.is_some() {
            return Err(err(Key::Other("sim.horizon"), Problem::Horizon));
        }
        options.validate().map_err(|e| {
            let key = match e.field.as_str() {
                "options.max_events" => "sim.max_events",
                _ => "sim.max_time",
            };
            err(Key::Other(key), Problem::Limits(e.reason))
        })?;
        let frame = Frame {
            name: name.into(),
            table,
            dims,
            params,
            models,
            options,
            balls,
            state,
        };
        frame.check_balls()?;
        frame.check_state()?;
        Ok(frame)
    }

    fn check_balls(&self) -> Result<(), FrameError> {
        let mut cue = None;
        let mut colours = [false; 6];
        for (i, b) in self.balls.iter().enumerate() {
            let role = Role::of(b.kind).ok_or_else(|| {
                err(
                    Key::Ball(i, "id"),
                    Problem::NotSnookerBall { id: b.id.clone() },
                )
            })?;
            match role {
                Role::Cue if cue.is_some() => {
                    return Err(err(
                        Key::Ball(i, "id"),
                        Problem::SecondCueBall { id: b.id.clone() },
                    ));
                }
                Role::Cue => cue = Some(i),
                Role::Colour(c) if colours[c as usize] => {
                    return Err(err(
                        Key::Ball(i, "id"),
                        Problem::ColourTwice {
                            id: b.id.clone(),
                            colour: c,
                        },
                    ));
                }
                Role::Colour(c) => colours[c as usize] = true,
                Role::Red => {}
            }
            // At rest means on the cloth too: a ball above it would start the stroke falling.
            let height = b.state.pos.z - self.params.ball_radius;
            if height.is_nan() || height.abs() > snooker_engine::motion::ON_CLOTH {
                return Err(err(
                    Key::Ball(i, "pos"),
                    Problem::OffTheCloth {
                        id: b.id.clone(),
                        height,
                    },
                ));
            }
            for (field, v) in [("vel", b.state.vel), ("spin", b.state.spin)] {
                if v != Vec3::zeros() {
                    return Err(err(
                        Key::Ball(i, field),
                        Problem::Moving { id: b.id.clone() },
                    ));
                }
            }
        }
        Ok(())
    }

    fn check_state(&self) -> Result<(), FrameError> {
        let s = &self.state;
        for (key, p) in [("to_play", s.to_play), ("first_player", s.first_player)] {
            if p > 1 {
                return Err(err(Key::Frame(key), Problem::NotAPlayer(p.into())));
            }
        }
        if let Some(&high) = s.scores.iter().find(|&&v| v > crate::state::MAX_SCORE) {
            return Err(err(Key::Frame("scores"), Problem::ScoreTooHigh(high)));
        }
        let on_key = Key::Frame("on");
        if !self.has_colour(Colour::Black) {
            return Err(err(Key::Other("balls"), Problem::NoBlack));
        }
        let reds = self.reds_on_table();
        match s.on {
            On::Red | On::Colour => {
                if s.on == On::Red && reds == 0 {
                    return Err(err(on_key, Problem::NoRedOn));
                }
                if let Some(&c) = Colour::ALL.iter().find(|&&c| !self.has_colour(c)) {
                    return Err(err(
                        on_key,
                        Problem::ColourMissing {
                            on: s.on,
                            colour: c,
                        },
                    ));
                }
            }
            On::Closing(c) => {
                if reds > 0 {
                    return Err(err(on_key, Problem::ClosingWithReds { on: s.on }));
                }
                if let Some(lowest) = Colour::ALL.into_iter().find(|&l| self.has_colour(l))
                    && lowest < c
                {
                    return Err(err(on_key, Problem::NotLowest { on: s.on, lowest }));
                }
                if !self.has_colour(c) {
                    return Err(err(on_key, Problem::OnMissing { on: s.on }));
                }
                if let Some(missing) = Colour::ALL
                    .into_iter()
                    .find(|&h| h > c && !self.has_colour(h))
                {
                    return Err(err(
                        on_key,
                        Problem::HigherMissing {
                            on: s.on,
                            colour: missing,
                        },
                    ));
                }
            }
        }
        let nom_key = Key::Frame("nominated");
        if s.free_ball {
            if s.on == On::Colour {
                return Err(err(Key::Frame("free_ball"), Problem::FreeBallOnColour));
            }
            if let (On::Closing(c), Some(n)) = (s.on, s.nominated)
                && c == n
            {
                return Err(err(nom_key, Problem::FreeBallIsOn(c)));
            }
        } else {
            match (s.on, s.nominated) {
                (On::Red, Some(_)) => return Err(err(nom_key, Problem::NothingToNominate)),
                (On::Closing(c), Some(n)) if n != c => {
                    return Err(err(
                        nom_key,
                        Problem::NominatedNotOn {
                            on: s.on,
                            nominated: n,
                        },
                    ));
                }
                _ => {}
            }
        }
        if let Some(n) = s.nominated
            && !self.has_colour(n)
        {
            return Err(err(nom_key, Problem::NominatedMissing { colour: n }));
        }
        match self.cue_index() {
            None if !s.ball_in_hand => Err(err(Key::Frame("ball_in_hand"), Problem::NoCueBall)),
            Some(i) if s.ball_in_hand => {
                let others: Vec<Ball> = self
                    .balls
                    .iter()
                    .enumerate()
                    .filter(|&(j, _)| j != i)
                    .map(|(_, b)| b.clone())
                    .collect();
                match in_hand::placement_problem(
                    &self.the_d(),
                    self.balls[i].state.pos,
                    &others,
                    self.params.ball_radius,
                ) {
                    Some(p) => Err(err(Key::Ball(i, "pos"), p)),
                    None => Ok(()),
                }
            }
            _ => Ok(()),
        }
    }

    /// The frame's name (free text; the scene's).
    pub fn name(&self) -> &str {
        &self.name
    }

    /// The table.
    pub fn table(&self) -> &Table {
        &self.table
    }

    /// The table's dimensions (spots, the D).
    pub fn dims(&self) -> &SnookerDims {
        &self.dims
    }

    /// The physical parameters.
    pub fn params(&self) -> &Params {
        &self.params
    }

    /// The impact models.
    pub fn models(&self) -> &Models {
        &self.models
    }

    /// The simulation limits of a stroke.
    pub fn options(&self) -> &SimOptions {
        &self.options
    }

    /// The balls on the table, at rest (the cue ball absent while in hand and not placed).
    pub fn balls(&self) -> &[Ball] {
        &self.balls
    }

    /// The state: ball on, nomination, scores, turn, ball in hand, free ball.
    pub fn state(&self) -> &FrameState {
        &self.state
    }

    /// The D of this table.
    pub fn the_d(&self) -> TheD {
        TheD::of(&self.dims)
    }

    /// Index of the cue ball among the balls, if it is on the table (or placed).
    pub fn cue_index(&self) -> Option<usize> {
        self.balls.iter().position(|b| b.kind == BallKind::Cue)
    }

    /// The balls the cue ball touches as it lies (centres at most 2R + the engine's
    /// [`snooker_engine::TOUCH_TOL`] apart): the referee's TOUCHING BALL (WPBSA Section 3 Rule
    /// 8(a)). Empty with the cue ball in hand.
    pub fn touching(&self) -> Vec<usize> {
        let Some(cue) = self.cue_index().filter(|_| !self.state.ball_in_hand) else {
            return Vec::new();
        };
        let c = self.balls[cue].state.pos;
        let reach = 2.0 * self.params.ball_radius + snooker_engine::TOUCH_TOL;
        (0..self.balls.len())
            .filter(|&i| {
                let p = self.balls[i].state.pos;
                i != cue && (p.x - c.x).hypot(p.y - c.y) <= reach
            })
            .collect()
    }

    /// True when a ball of this colour is on the table.
    pub fn has_colour(&self, c: Colour) -> bool {
        self.balls.iter().any(|b| b.kind == c.kind())
    }

    /// How many reds are on the table.
    pub fn reds_on_table(&self) -> usize {
        self.balls
            .iter()
            .filter(|b| b.kind == BallKind::Red)
            .count()
    }

    /// The value of the ball on, for fouls: a red 1, the nominated colour (with `on =
    /// "colour"`), the closing colour; a free ball takes the value of the ball on. `None` with
    /// a colour on and nothing nominated.
    pub fn value_on(&self) -> Option<u32> {
        match self.state.on {
            On::Red => Some(1),
            On::Colour => self.state.nominated.map(Colour::value),
            On::Closing(c) => Some(c.value()),
        }
    }

    /// The kind of the ball nominated as a free ball, if a free ball is taken: the ball the
    /// cue ball must meet first (WPBSA Section 3 Rule 12(c)(i)).
    pub fn free_ball_nominated(&self) -> Option<BallKind> {
        let s = &self.state;
        s.nominated.filter(|_| s.free_ball).map(Colour::kind)
    }

    /// True when a ball of this kind is on for the stroke (WPBSA Section 2 Rule 11): a red
    /// with reds on, the nominated colour with a colour on, the closing colour; and with a free
    /// ball the nominated ball too (Section 3 Rule 12).
    pub fn is_on(&self, kind: BallKind) -> bool {
        let s = &self.state;
        let free = s.free_ball && s.nominated.is_some_and(|n| n.kind() == kind);
        free || match s.on {
            On::Red => kind == BallKind::Red,
            On::Colour => s.nominated.is_some_and(|n| n.kind() == kind),
            On::Closing(c) => c.kind() == kind,
        }
    }

    /// The indices of the balls on for the stroke as the frame stands (with a colour or a
    /// free ball on and nothing nominated: every ball that could be nominated).
    pub fn balls_on(&self) -> Vec<usize> {
        let s = &self.state;
        let nominable = self.legal_nominations();
        self.balls
            .iter()
            .enumerate()
            .filter(|(_, b)| {
                let colour = Colour::of(b.kind);
                self.is_on(b.kind)
                    || (s.nominated.is_none()
                        && (s.on == On::Colour || s.free_ball)
                        && colour.is_some_and(|c| nominable.contains(&c)))
            })
            .map(|(i, _)| i)
            .collect()
    }

    /// The colours the player may nominate for the stroke: any colour on the table with
    /// `on = "colour"`; with a free ball any colour on the table other than the ball on
    /// (WPBSA Section 2 Rule 13); nothing otherwise (reds on, or the closing colour).
    pub fn legal_nominations(&self) -> Vec<Colour> {
        let s = &self.state;
        Colour::ALL
            .into_iter()
            .filter(|&c| self.has_colour(c))
            .filter(|&c| match s.on {
                On::Colour => true,
                On::Red => s.free_ball,
                On::Closing(on) => s.free_ball && c != on,
            })
            .collect()
    }

    /// This frame with `nominated` as the nomination for the stroke (checked as
    /// [`Frame::new`] checks it); `None` clears it, and with a free ball declines the free
    /// ball (`free_ball` false: the ball on is played as the ball on).
    pub fn with_nomination(&self, nominated: Option<Colour>) -> Result<Frame, FrameError> {
        let mut f = self.clone();
        f.state.nominated = nominated;
        // Nothing nominated with a free ball declines it: the ball on is played as without
        // one (WPBSA Section 3 Rule 12(b): the player *may* nominate).
        if nominated.is_none() {
            f.state.free_ball = false;
        }
        f.check_state()?;
        Ok(f)
    }

    /// This frame with the cue ball in hand placed at `pos` (plan): refused outside the D or
    /// touching a ball. The frame must have the cue ball in hand.
    pub fn with_cue_ball_at(&self, pos: [f64; 2]) -> Result<Frame, FrameError> {
        if !self.state.ball_in_hand {
            return Err(err(Key::Frame("ball_in_hand"), Problem::NotInHand));
        }
        let mut f = self.clone();
        let r = self.params.ball_radius;
        let at = snooker_engine::BallState::at_rest(pos[0], pos[1], r);
        match f.cue_index() {
            Some(i) => f.balls[i].state = at,
            None => f.balls.push(Ball {
                id: "cue".into(),
                kind: BallKind::Cue,
                state: at,
            }),
        }
        f.check_state()?;
        Ok(f)
    }

    /// The valid place for the cue ball in hand nearest `preferred` (see
    /// [`in_hand::nearest_placement`]).
    pub fn nearest_placement(&self, preferred: [f64; 2]) -> Option<[f64; 2]> {
        let others: Vec<Ball> = self
            .balls
            .iter()
            .filter(|b| b.kind != BallKind::Cue)
            .cloned()
            .collect();
        in_hand::nearest_placement(
            &self.the_d(),
            Vec3::new(preferred[0], preferred[1], 0.0),
            &others,
            self.params.ball_radius,
        )
        .map(|p| [p.x, p.y])
    }

    /// Checks that the frame is ready for a stroke: the cue ball on the table (placed, if in
    /// hand), and the ball nominated where one must be.
    pub fn check_ready(&self) -> Result<usize, FrameError> {
        let s = &self.state;
        let cue = self.cue_index().ok_or_else(|| {
            err(
                Key::Other("balls"),
                if s.ball_in_hand {
                    Problem::NotPlaced
                } else {
                    Problem::NoCueBall
                },
            )
        })?;
        if s.nominated.is_none() && (s.on == On::Colour || s.free_ball) {
            return Err(err(
                Key::Frame("nominated"),
                Problem::NoNomination {
                    on: s.on,
                    free_ball: s.free_ball,
                },
            ));
        }
        Ok(cue)
    }

    /// What the engine simulates for `strike` on the cue ball: the frame's table, physics and
    /// balls, the cue ball struck. Errors: the frame not ready ([`Frame::check_ready`]), a
    /// strike the engine refuses (key `cue.KEY`).
    pub fn setup(&self, strike: &Cue) -> Result<Setup, FrameError> {
        let cue = self.check_ready()?;
        let mut balls = self.balls.clone();
        balls[cue].strike(strike, &self.params).map_err(|e| {
            let key = match e.key {
                "speed" => "cue.speed",
                "aim" => "cue.aim",
                "offset" => "cue.offset",
                "elevation" => "cue.elevation",
                _ => "cue",
            };
            err(Key::Other(key), Problem::Strike(e.reason))
        })?;
        Ok(Setup {
            table: self.table.clone(),
            params: self.params,
            models: self.models,
            balls,
        })
    }

    /// A frame from parts already checked elsewhere (the next frame of a judged stroke).
    pub(crate) fn with_parts(&self, balls: Vec<Ball>, state: FrameState) -> Frame {
        Frame {
            name: self.name.clone(),
            table: self.table.clone(),
            dims: self.dims,
            params: self.params,
            models: self.models,
            options: self.options,
            balls,
            state,
        }
    }
}
