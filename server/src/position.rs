//! A position as the page holds it: the scene (the scene file's keys, every ball listed), the
//! table to draw, and, for a frame of snooker, the `[frame]` table and what the rules say of
//! it (the balls on, the colours that may be nominated, where the cue ball in hand goes). The
//! layouts the page offers: the break-off and an open table as frames, and the scene files of
//! `scenes/`, built in.

use crate::error::ApiError;
use crate::input::{self, CheckedScene};
use crate::limits::Limits;
use crate::table::{TableView, view};
use serde::Serialize;
use serde_json::Value;
use snooker_rules::Frame;
use snooker_rules::file::FrameFile;

/// The `[frame]` table of a frame (formats.md, "Frame"), as the page sends it back.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FrameTable {
    /// The ball on.
    pub on: &'static str,
    /// The nominated colour, if any.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub nominated: Option<&'static str>,
    /// Points of the two players.
    pub scores: [u32; 2],
    /// The player at the table.
    pub to_play: u8,
    /// The cue ball in hand.
    pub ball_in_hand: bool,
    /// Who broke off.
    pub first_player: u8,
    /// A free ball awarded.
    pub free_ball: bool,
}

/// What the rules say of a frame, for the page to show and to offer.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RulesView {
    /// Ids of the balls on.
    pub balls_on: Vec<String>,
    /// Colours that may be nominated.
    pub nominations: Vec<&'static str>,
    /// Where the cue ball in hand goes if the player does not place it (the valid place in
    /// the D nearest the middle of its straight side), when it is in hand and not placed.
    pub in_hand_place: Option<[f64; 2]>,
}

/// A position: what the page draws and edits.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Position {
    /// The scene, with the scene file's keys, every ball listed (no `frame`).
    pub scene: Value,
    /// The table.
    pub table: TableView,
    /// The frame's `[frame]` table, for a frame of snooker.
    pub frame: Option<FrameTable>,
    /// What the rules say of the frame.
    pub rules: Option<RulesView>,
}

/// The `[frame]` table of `frame`.
pub fn frame_table(frame: &Frame) -> FrameTable {
    let s = frame.state();
    FrameTable {
        on: s.on.name(),
        nominated: s.nominated.map(|c| c.name()),
        scores: s.scores,
        to_play: s.to_play,
        ball_in_hand: s.ball_in_hand,
        first_player: s.first_player,
        free_ball: s.free_ball,
    }
}

/// What the rules say of `frame`.
pub fn rules_view(frame: &Frame) -> RulesView {
    let balls = frame.balls();
    let d = frame.dims();
    let in_hand_place = if frame.state().ball_in_hand && frame.cue_index().is_none() {
        frame.nearest_placement([d.baulk_line - 0.5 * d.d_radius, 0.5 * d.width])
    } else {
        None
    };
    RulesView {
        balls_on: frame
            .balls_on()
            .into_iter()
            .map(|i| balls[i].id.clone())
            .collect(),
        nominations: frame
            .legal_nominations()
            .into_iter()
            .map(|c| c.name())
            .collect(),
        in_hand_place,
    }
}

/// The position of a scene.
pub fn of_scene(checked: &CheckedScene) -> Result<Position, ApiError> {
    Ok(Position {
        scene: input::scene_value(&checked.file)?,
        table: view(&checked.scene.setup.table, &checked.scene.setup.params),
        frame: None,
        rules: None,
    })
}

/// The position of a frame, with no strike (the page sets its own).
pub fn of_frame(frame: &Frame) -> Result<Position, ApiError> {
    of_frame_with(frame, None)
}

/// The position of a frame, with `strike` as its scene's `cue` (the strike offered) if given.
fn of_frame_with(
    frame: &Frame,
    strike: Option<&snooker_engine::Cue>,
) -> Result<Position, ApiError> {
    let mut scene = input::frame_value(frame, strike)?;
    if let Some(map) = scene.as_object_mut() {
        map.remove("frame");
    }
    Ok(Position {
        scene,
        table: view(frame.table(), frame.params()),
        frame: Some(frame_table(frame)),
        rules: Some(rules_view(frame)),
    })
}

/// The position of a frame file read: the frame before its strike, and its strike, if it has
/// one, as the strike offered (as a scene file's is).
pub fn of_frame_file(file: &FrameFile) -> Result<Position, ApiError> {
    of_frame_with(&file.frame, file.strike.as_ref())
}

/// A layout the page offers.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct LayoutInfo {
    /// Its name.
    pub name: &'static str,
    /// `frame` (a frame of snooker) or `scene`.
    pub kind: &'static str,
    /// What it is.
    pub about: &'static str,
}

/// The scene files built in: name, text, what it shows.
const SCENES: [(&str, &str, &str); 16] = [
    (
        "cut-30",
        include_str!("../../scenes/cut-30.toml"),
        "a 30-degree cut",
    ),
    (
        "stun",
        include_str!("../../scenes/stun.toml"),
        "a centre-ball strike into a straight red",
    ),
    (
        "screw",
        include_str!("../../scenes/screw.toml"),
        "a low strike into a straight red",
    ),
    (
        "follow",
        include_str!("../../scenes/follow.toml"),
        "a high strike into a straight red",
    ),
    (
        "one-cushion",
        include_str!("../../scenes/one-cushion.toml"),
        "the cue ball off one cushion",
    ),
    (
        "three-cushion",
        include_str!("../../scenes/three-cushion.toml"),
        "the cue ball off three cushions",
    ),
    (
        "chapter7-example",
        include_str!("../../scenes/chapter7-example.toml"),
        "the thesis's planning example (section 7.3.2)",
    ),
    (
        "two-cushion",
        include_str!("../../scenes/two-cushion.toml"),
        "the cue ball off two cushions",
    ),
    (
        "cushion-rebound",
        include_str!("../../scenes/cushion-rebound.toml"),
        "a ball rolling straight into the top cushion (section 5.1.2)",
    ),
    (
        "table-i-1",
        include_str!("../../scenes/table-i-1.toml"),
        "thesis Table I, collision 1, on the open cloth (appendix III)",
    ),
    (
        "table-i-2",
        include_str!("../../scenes/table-i-2.toml"),
        "thesis Table I, collision 2, on the open cloth (appendix III)",
    ),
    (
        "table-i-3",
        include_str!("../../scenes/table-i-3.toml"),
        "thesis Table I, collision 3, on the open cloth (appendix III)",
    ),
    (
        "table-i-4",
        include_str!("../../scenes/table-i-4.toml"),
        "thesis Table I, collision 4, on the open cloth (appendix III)",
    ),
    (
        "table-i-5",
        include_str!("../../scenes/table-i-5.toml"),
        "thesis Table I, collision 5, on the open cloth (appendix III)",
    ),
    (
        "jump",
        include_str!("../../scenes/jump.toml"),
        "a jump shot over a red, on a bed that gives back half the fall (e_bed = 0.5)",
    ),
    (
        "break-off-shot",
        snooker_scene::DEFAULT_SCENE,
        "the built-in break-off shot of snooker simulate",
    ),
];

/// Every layout offered.
pub fn layouts() -> Vec<LayoutInfo> {
    let mut out = vec![
        LayoutInfo {
            name: "break-off",
            kind: "frame",
            about: "a frame from its start: the rack, the colours on their spots, the cue ball in hand",
        },
        LayoutInfo {
            name: "open-table",
            kind: "frame",
            about: "a frame of reds scattered at random (seeded), the colours on their spots",
        },
    ];
    out.extend(SCENES.iter().map(|(name, _, about)| LayoutInfo {
        name,
        kind: "scene",
        about,
    }));
    out
}

/// The layout `name` (`reds`, default 15, and `seed`, default 1, for the open table; the
/// other layouts take neither, and naming one is refused rather than ignored).
pub fn layout(
    name: &str,
    reds: Option<usize>,
    seed: Option<u64>,
    limits: &Limits,
) -> Result<Position, ApiError> {
    if name != "open-table" {
        let given = [("reds", reds.is_some()), ("seed", seed.is_some())];
        if let Some((key, _)) = given.iter().find(|(_, g)| *g) {
            return Err(ApiError::bad(
                crate::body::REQUEST,
                key,
                format!("only the open-table layout takes {key}, not \"{name}\""),
            ));
        }
    }
    match name {
        "break-off" => of_frame(&Frame::break_off()),
        "open-table" => {
            let reds = reds.unwrap_or(15);
            if reds > 15 {
                return Err(ApiError::bad(
                    crate::body::REQUEST,
                    "reds",
                    format!("at most 15 reds, got {reds}"),
                ));
            }
            of_frame(&Frame::open_table(reds, seed.unwrap_or(1)))
        }
        _ => match SCENES.iter().find(|(n, _, _)| *n == name) {
            Some((n, text, _)) => of_scene(&input::scene_toml(text, &format!("{n}.toml"), limits)?),
            None => Err(ApiError::not_found(format!("no layout \"{name}\""))),
        },
    }
}
