//! Rerun recordings of a shot (`snooker simulate SCENE --record OUT.rrd`).
//!
//! Everything is in the table frame (m, z up) on the timeline [`TIMELINE`] (seconds). Ball
//! data are sampled from the exact trajectory on a fixed-rate grid plus every event instant,
//! taken twice (just before and just after), so nothing is interpolated across an event.
//! All time-varying data go out in columns (`send_columns`), one chunk per entity and
//! component set. Entity paths and scales are documented in `docs/recording.md`.

mod blueprint;
pub mod frame;
pub mod sample;
mod table;

use rerun::external::re_log_types::{EntityPath, EntityPathPart};
use rerun::log::ChunkBatcherConfig;
use rerun::{
    Arrows3D, Color, Ellipsoids3D, FillMode, LineStrips3D, Points3D, RecordingStream,
    RecordingStreamBuilder, Scalars, SeriesLines, StateChange, StateConfiguration, TextLog,
    TimeColumn, Transform3D, ViewCoordinates,
};
use sample::{Schedule, Side};
use snooker_engine::shown::Shown;
use snooker_engine::sim::{Track, orientation};
use snooker_engine::{BallState, EventKind, Motion, Params, Shot, Vec3};
use snooker_scene::Scene;
use std::collections::VecDeque;

/// The recording's timeline: simulated time, s.
pub const TIMELINE: &str = "sim_time";
/// Default sample rate, Hz.
pub const DEFAULT_RATE: f64 = 240.0;
/// Highest sample rate accepted, Hz.
pub const MAX_RATE: f64 = 10_000.0;
/// Most ball samples (instants times balls) a recording may hold: a guard against a rate or a
/// shot length that would exhaust memory.
pub const MAX_BALL_SAMPLES: usize = 20_000_000;
/// Velocity arrows: length per unit speed, s (1 m/s draws 0.1 m).
pub const VELOCITY_SCALE: f64 = 0.1;
/// Spin arrows: length per unit of surface speed |w| R, s (a ball rolling at 1 m/s draws a
/// spin arrow as long as its velocity arrow).
pub const SPIN_SCALE: f64 = 0.1;
/// Length of a ball's fading trail, s.
pub const TRAIL_SECONDS: f64 = 1.0;
/// How long an event marker stays in the 3D view after its event, s.
pub const MARKER_SECONDS: f64 = 0.5;
/// Spacing of the trail's points, s (event instants are always included).
const TRAIL_SPACING: f64 = 1.0 / 60.0;
/// Opacity of the trail's parts, newest first.
const TRAIL_ALPHA: [u8; 4] = [230, 160, 90, 40];

/// How to record.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RecordOptions {
    /// Sample rate of the fixed grid, Hz.
    pub rate: f64,
    /// Where on the timeline the viewer opens.
    pub open_at: OpenAt,
}

/// Where on the timeline the viewer opens a recording.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum OpenAt {
    /// Paused at the start (a shot, to be played).
    #[default]
    Start,
    /// At the end (a break or a frame: the table and the score it ended with).
    End,
}

impl Default for RecordOptions {
    fn default() -> Self {
        RecordOptions {
            rate: DEFAULT_RATE,
            open_at: OpenAt::Start,
        }
    }
}

impl RecordOptions {
    /// Checks the options: a sample rate in (0, [`MAX_RATE`]] Hz.
    pub fn validate(&self) -> Result<(), RecordError> {
        if self.rate > 0.0 && self.rate <= MAX_RATE {
            Ok(())
        } else {
            Err(RecordError::Rate(self.rate))
        }
    }
}

/// Why a recording could not be made.
#[derive(Debug, thiserror::Error)]
pub enum RecordError {
    /// The sample rate is not a finite number in (0, [`MAX_RATE`]].
    #[error("the sample rate must be a number of Hz in (0, {MAX_RATE}], got {}", Shown(*.0))]
    Rate(f64),
    /// The recording would be too large.
    #[error(
        "the recording would hold about {0} ball samples (limit {MAX_BALL_SAMPLES}); lower --record-rate"
    )]
    TooLarge(usize),
    /// The Rerun SDK refused the data.
    #[error("rerun: {0}")]
    Rerun(String),
}

pub(crate) fn rerun_err(e: impl std::fmt::Display) -> RecordError {
    RecordError::Rerun(e.to_string())
}

/// The colour of each motion phase: velocity arrows and the motion timeline.
pub fn motion_color(m: Motion) -> [u8; 3] {
    match m {
        Motion::Sliding => [255, 140, 0],
        Motion::Rolling => [60, 170, 255],
        Motion::Spinning => [200, 80, 220],
        Motion::Airborne => [0, 230, 230],
        Motion::Stationary => [150, 150, 150],
        Motion::Pocketed => [60, 60, 60],
        Motion::OffTable => [110, 60, 30],
    }
}

const MOTIONS: [Motion; 7] = [
    Motion::Sliding,
    Motion::Rolling,
    Motion::Spinning,
    Motion::Airborne,
    Motion::Stationary,
    Motion::Pocketed,
    Motion::OffTable,
];

/// Entity path `root/part` with `part` escaped (ball ids are free text).
fn path(root: &[&str], part: &str) -> EntityPath {
    let mut parts: Vec<EntityPathPart> = root.iter().map(|&r| EntityPathPart::new(r)).collect();
    parts.push(EntityPathPart::new(part));
    EntityPath::new(parts)
}

fn f32x3(v: Vec3) -> [f32; 3] {
    [v.x as f32, v.y as f32, v.z as f32]
}

fn rgb(c: [u8; 3]) -> Color {
    Color::from_rgb(c[0], c[1], c[2])
}

/// Points shown over a recording on their own entity: a ball's measured centroids, or where
/// another model put it (the discrepancy workflow's overlays).
#[derive(Clone, Debug, PartialEq)]
pub struct Overlay {
    /// Entity path as its parts, e.g. `["measured", "cue"]` (free text: escaped as needed).
    pub entity: Vec<String>,
    /// (time s, position m), in time order.
    pub points: Vec<(f64, Vec3)>,
    /// Colour.
    pub color: [u8; 3],
    /// Radius of the points, m.
    pub radius: f64,
}

/// A recording's builder, its chunks cut by size only: rerun's default batcher also flushes
/// every 200 ms of wall clock, so a loaded machine cut the same shot into other chunks (a
/// fresh clone's test of equal recordings failed under load); the same shot must give the
/// same recording.
pub(crate) fn builder() -> RecordingStreamBuilder {
    RecordingStreamBuilder::new("snooker").batcher_config(ChunkBatcherConfig {
        flush_tick: std::time::Duration::MAX,
        ..ChunkBatcherConfig::DEFAULT
    })
}

/// Records `shot` (simulated from `scene`) and returns the `.rrd` file's bytes: the recording
/// and the default blueprint that frames the table.
pub fn encode(scene: &Scene, shot: &Shot, opts: &RecordOptions) -> Result<Vec<u8>, RecordError> {
    encode_with_overlays(scene, shot, opts, &[])
}

/// As [`encode`], with `overlays` logged on top.
pub fn encode_with_overlays(
    scene: &Scene,
    shot: &Shot,
    opts: &RecordOptions,
    overlays: &[Overlay],
) -> Result<Vec<u8>, RecordError> {
    encode_with(scene, shot, opts, overlays, |_| Ok(()))
}

/// As [`encode_with_overlays`], then `extra` logs what the caller adds (a frame's scoreboard)
/// to the same recording.
pub fn encode_with(
    scene: &Scene,
    shot: &Shot,
    opts: &RecordOptions,
    overlays: &[Overlay],
    extra: impl FnOnce(&RecordingStream) -> Result<(), RecordError>,
) -> Result<Vec<u8>, RecordError> {
    encode_with_cuts(scene, shot, &[], opts, overlays, extra)
}

/// As [`encode_with`], with every time of `cuts` sampled twice, just before and just after:
/// the instants where balls change with no event (the start of each stroke of a sequence).
pub fn encode_with_cuts(
    scene: &Scene,
    shot: &Shot,
    cuts: &[f64],
    opts: &RecordOptions,
    overlays: &[Overlay],
    extra: impl FnOnce(&RecordingStream) -> Result<(), RecordError>,
) -> Result<Vec<u8>, RecordError> {
    opts.validate()?;
    // Checked before anything is allocated: the grid, the end, two instants per event resolved
    // (a lift-off shares its impact's) and per cut.
    let instants = (shot.duration * opts.rate).floor()
        + 2.0
        + 2.0 * (shot.resolved_events() + cuts.len()) as f64;
    let samples = instants * shot.tracks.len() as f64;
    if samples > MAX_BALL_SAMPLES as f64 {
        return Err(RecordError::TooLarge(samples as usize));
    }
    let schedule = Schedule::with_cuts(shot, opts.rate, cuts);
    let states: Vec<Vec<BallState>> = (0..shot.tracks.len())
        .map(|b| schedule.states(shot, b))
        .collect();

    let (rec, storage) = builder()
        .recording_name(scene.name.clone())
        // A recording the user asked for is made whatever the RERUN environment variable says.
        .enabled(true)
        .memory()
        .map_err(rerun_err)?;
    let extent = table::extent(&scene.setup.table, &states);
    blueprint::send(&rec, extent, opts.open_at)?;
    rec.log_static("/", &ViewCoordinates::RIGHT_HAND_Z_UP())
        .map_err(rerun_err)?;
    table::log(&rec, &scene.setup.table, &shot.params, extent)?;
    for (b, track) in shot.tracks.iter().enumerate() {
        let ball = Ball {
            rec: &rec,
            schedule: &schedule,
            track,
            states: &states[b],
            params: &shot.params,
            rate: opts.rate,
        };
        ball.log()?;
    }
    log_events(&rec, shot)?;
    for o in overlays {
        log_overlay(&rec, o)?;
    }
    extra(&rec)?;
    storage.drain_as_bytes().map_err(rerun_err)
}

/// One overlay: its style once, the whole path as a static line (`<entity>/path`) so it can
/// be compared at any time, then one point per time.
fn log_overlay(rec: &RecordingStream, o: &Overlay) -> Result<(), RecordError> {
    let entity = EntityPath::new(o.entity.iter().map(EntityPathPart::new).collect());
    rec.log_static(
        entity.join(&EntityPath::from("path")),
        &LineStrips3D::new([o.points.iter().map(|p| f32x3(p.1)).collect::<Vec<_>>()])
            .with_colors([rgb(o.color)])
            .with_radii([rerun::Radius::new_ui_points(1.0)]),
    )
    .map_err(rerun_err)?;
    rec.log_static(
        entity.clone(),
        &Points3D::update_fields()
            .with_colors([rgb(o.color)])
            .with_radii([rerun::Radius::new_scene_units(o.radius as f32)]),
    )
    .map_err(rerun_err)?;
    let times = TimeColumn::new_duration_secs(TIMELINE, o.points.iter().map(|p| p.0));
    let columns = Points3D::update_fields()
        .with_positions(o.points.iter().map(|p| f32x3(p.1)))
        .columns_of_unit_batches()
        .map_err(rerun_err)?;
    rec.send_columns(entity, [times], columns)
        .map_err(rerun_err)
}

/// One ball's recording.
struct Ball<'a> {
    rec: &'a RecordingStream,
    schedule: &'a Schedule,
    track: &'a Track,
    states: &'a [BallState],
    params: &'a Params,
    rate: f64,
}

impl Ball<'_> {
    /// Sends one entity's columns against `times`.
    fn send(
        &self,
        entity: EntityPath,
        times: TimeColumn,
        columns: rerun::SerializationResult<
            impl IntoIterator<Item = rerun::SerializedComponentColumn>,
        >,
    ) -> Result<(), RecordError> {
        self.rec
            .send_columns(entity, [times], columns.map_err(rerun_err)?)
            .map_err(rerun_err)
    }

    /// Times of the instants at `rows`.
    fn times_at(&self, rows: &[usize]) -> TimeColumn {
        TimeColumn::new_duration_secs(TIMELINE, rows.iter().map(|&i| self.schedule.instants[i].t))
    }

    /// Logs everything about the ball.
    fn log(&self) -> Result<(), RecordError> {
        let id = self.track.id.as_str();
        let r = self.params.ball_radius;
        let colour = rgb(crate::palette::ball(self.track.kind));
        let in_play: Vec<bool> = self.states.iter().map(|s| s.motion.in_play()).collect();
        let rows = self.rows();
        let all = || self.times_at(&rows);

        // Position (the ball's frame) and orientation (its body frame) wherever the state
        // changes.
        self.send(
            path(&["balls"], id),
            all(),
            Transform3D::update_fields()
                .with_many_translation(rows.iter().map(|&i| f32x3(self.states[i].pos)))
                .columns_of_unit_batches(),
        )?;
        let times: Vec<f64> = rows.iter().map(|&i| self.schedule.instants[i].t).collect();
        let q = orientation::orientations(self.track, self.params, &times);
        self.send(
            path(&["balls", id], "body"),
            all(),
            Transform3D::update_fields()
                .with_many_quaternion(q.iter().map(|q| {
                    let c = q.coords;
                    rerun::Quaternion::from_xyzw([c.x as f32, c.y as f32, c.z as f32, c.w as f32])
                }))
                .columns_of_unit_batches(),
        )?;

        // The sphere and its marker: shown while the ball is in play (rows where that changes).
        let changes: Vec<usize> = (0..in_play.len())
            .filter(|&i| i == 0 || in_play[i] != in_play[i - 1])
            .collect();
        let shown: Vec<usize> = changes.iter().map(|&i| usize::from(in_play[i])).collect();
        let body = path(&["balls", id], "body");
        self.rec
            .log_static(
                body.clone(),
                &Ellipsoids3D::update_fields()
                    .with_colors([colour])
                    .with_fill_mode(FillMode::Solid),
            )
            .map_err(rerun_err)?;
        self.send(
            body,
            self.times_at(&changes),
            Ellipsoids3D::update_fields()
                .with_half_sizes(
                    shown
                        .iter()
                        .flat_map(|&n| std::iter::repeat_n([r as f32; 3], n)),
                )
                .columns(shown.clone()),
        )?;
        let marker = path(&["balls", id, "body"], "marker");
        let rings = marker_rings(r * 1.004);
        // Light rings on the dark balls (black, green), dark ones on the others.
        let ring_colour = if crate::palette::ball(self.track.kind)
            .iter()
            .map(|&c| c as u32)
            .sum::<u32>()
            < 200
        {
            Color::from_rgb(230, 230, 230)
        } else {
            Color::from_rgb(20, 20, 20)
        };
        self.rec
            .log_static(
                marker.clone(),
                &LineStrips3D::update_fields()
                    .with_colors([ring_colour])
                    .with_radii([rerun::Radius::new_scene_units(0.0007)]),
            )
            .map_err(rerun_err)?;
        let ring_counts: Vec<usize> = shown.iter().map(|&n| n * rings.len()).collect();
        self.send(
            marker,
            self.times_at(&changes),
            LineStrips3D::update_fields()
                .with_strips(
                    shown
                        .iter()
                        .flat_map(|&n| std::iter::repeat_n(rings.iter().cloned(), n).flatten()),
                )
                .columns(ring_counts),
        )?;

        self.log_arrows(id, r, &rows)?;
        self.log_trail(id)?;
        self.log_plots(id, r, &rows)?;
        self.log_motion(id)
    }

    /// The instants worth a row: the first and the last, and both ends of every run of
    /// instants with the same state (a ball at rest, pocketed or waiting off the table for
    /// its stroke has one state for seconds; the viewer shows the latest row, and a plot's
    /// line between the ends of a run is the run itself). A whole visit's recording was
    /// mostly such repeated rows.
    fn rows(&self) -> Vec<usize> {
        let s = self.states;
        let n = s.len();
        (0..n)
            .filter(|&i| i == 0 || i + 1 == n || s[i] != s[i - 1] || s[i] != s[i + 1])
            .collect()
    }

    /// The vectors `f` gives at the instants the ball is in play and `f` is not zero (with the
    /// motion phase there), and per instant how many of them there are (0 or 1).
    fn shown(
        &self,
        rows: &[usize],
        f: impl Fn(&BallState) -> Vec3,
    ) -> (Vec<(Vec3, Motion)>, Vec<usize>) {
        let mut shown = Vec::new();
        let mut counts = Vec::with_capacity(rows.len());
        for s in rows.iter().map(|&i| &self.states[i]) {
            let v = f(s);
            let show = s.motion.in_play() && v != Vec3::zeros();
            if show {
                shown.push((v, s.motion));
            }
            counts.push(usize::from(show));
        }
        (shown, counts)
    }

    /// Velocity (coloured by motion phase) and spin arrows from the centre; none for a ball at
    /// rest or pocketed.
    fn log_arrows(&self, id: &str, r: f64, rows: &[usize]) -> Result<(), RecordError> {
        let (vel, counts) = self.shown(rows, |s| s.vel);
        self.send(
            path(&["balls", id], "velocity"),
            self.times_at(rows),
            Arrows3D::update_fields()
                .with_vectors(vel.iter().map(|&(v, _)| f32x3(v * VELOCITY_SCALE)))
                .with_colors(vel.iter().map(|&(_, m)| rgb(motion_color(m))))
                .columns(counts),
        )?;
        let (spin, counts) = self.shown(rows, |s| s.spin);
        self.rec
            .log_static(
                path(&["balls", id], "spin"),
                &Arrows3D::update_fields().with_colors([Color::from_rgb(250, 250, 120)]),
            )
            .map_err(rerun_err)?;
        self.send(
            path(&["balls", id], "spin"),
            self.times_at(rows),
            Arrows3D::update_fields()
                .with_vectors(spin.iter().map(|&(w, _)| f32x3(w * (r * SPIN_SCALE))))
                .columns(counts),
        )
    }

    /// The fading trail: the path over the last [`TRAIL_SECONDS`] in four parts of falling
    /// opacity, in the table frame. Rows only where the trail is not empty (and one to clear it).
    ///
    /// The path between events is a straight line (rolling) or a parabola (sliding, flight),
    /// so a trail needs only the event instants, points every [`TRAIL_SPACING`] while the ball
    /// slides or flies, and the exact positions where the parts meet and where the trail ends.
    fn log_trail(&self, id: &str) -> Result<(), RecordError> {
        let inst = &self.schedule.instants;
        let every = (self.rate * TRAIL_SPACING).round().max(1.0) as u64;
        let anchor: Vec<bool> = inst
            .iter()
            .zip(self.states)
            .map(|(x, s)| match x.side {
                Side::Grid => {
                    matches!(s.motion, Motion::Sliding | Motion::Airborne)
                        && ((x.t * self.rate).round() as u64).is_multiple_of(every)
                }
                Side::Before(_) => false,
                Side::After(_) => true,
            })
            .collect();
        let [r, g, b] = crate::palette::ball(self.track.kind);
        let parts = TRAIL_ALPHA.len();
        let part = TRAIL_SECONDS / parts as f64;
        let mut rows = Vec::new();
        let mut counts = Vec::new();
        let mut strips: Vec<Vec<[f32; 3]>> = Vec::new();
        let mut colours = Vec::new();
        let mut last_moving = f64::NEG_INFINITY;
        let mut was_empty = true;
        let mut pts: Vec<(f64, Vec3)> = Vec::new();
        // Anchors before the current instant and younger than the trail, oldest first.
        let mut window: VecDeque<usize> = VecDeque::new();
        for (i, x) in inst.iter().enumerate() {
            let s = &self.states[i];
            if s.motion.is_moving() {
                last_moving = x.t;
            }
            if i > 0 && anchor[i - 1] {
                window.push_back(i - 1);
            }
            while window
                .front()
                .is_some_and(|&j| x.t - inst[j].t >= TRAIL_SECONDS)
            {
                window.pop_front();
            }
            pts.clear();
            if x.t - last_moving <= TRAIL_SECONDS && s.motion.in_play() {
                pts.push((0.0, s.pos));
                pts.extend(
                    window
                        .iter()
                        .map(|&j| (x.t - inst[j].t, self.states[j].pos))
                        .filter(|&(age, _)| age > 0.0),
                );
                for k in 1..=parts {
                    // Never before the start of the shot.
                    let age = (k as f64 * part).min(x.t);
                    pts.push((age, self.track.state_at(x.t - age, self.params).pos));
                }
                pts.sort_by(|a, b| a.0.total_cmp(&b.0));
                pts.dedup_by(|a, b| a.0 == b.0);
            }
            let moved = pts.iter().any(|(_, p)| (p - s.pos).norm() > 1e-6);
            if !moved && was_empty {
                continue;
            }
            rows.push(i);
            let before = strips.len();
            if moved {
                // Consecutive parts share their boundary point.
                let bin = |age: f64| ((age / part) as usize).min(parts - 1);
                let mut k = 0;
                while k + 1 < pts.len() {
                    let this = bin(pts[k].0);
                    let mut strip = vec![f32x3(pts[k].1)];
                    while k + 1 < pts.len() {
                        k += 1;
                        strip.push(f32x3(pts[k].1));
                        if bin(pts[k].0) != this {
                            break;
                        }
                    }
                    strips.push(strip);
                    colours.push(Color::from_unmultiplied_rgba(r, g, b, TRAIL_ALPHA[this]));
                }
            }
            counts.push(strips.len() - before);
            was_empty = !moved;
        }
        let entity = path(&["trails"], id);
        self.rec
            .log_static(
                entity.clone(),
                &LineStrips3D::update_fields().with_radii([rerun::Radius::new_scene_units(0.003)]),
            )
            .map_err(rerun_err)?;
        self.send(
            entity,
            self.times_at(&rows),
            LineStrips3D::update_fields()
                .with_strips(strips)
                .with_colors(colours)
                .columns(counts),
        )
    }

    /// Time series: speed |v|, slip speed at the cloth |u|, spin components. Gaps (NaN) after
    /// the ball is pocketed, and for the slip while it is airborne.
    fn log_plots(&self, id: &str, r: f64, rows: &[usize]) -> Result<(), RecordError> {
        let colour = rgb(crate::palette::ball(self.track.kind));
        let states: Vec<&BallState> = rows.iter().map(|&i| &self.states[i]).collect();
        let speed: Vec<f64> = states
            .iter()
            .map(|s| {
                if s.motion.in_play() {
                    s.vel.norm()
                } else {
                    f64::NAN
                }
            })
            .collect();
        let slip: Vec<f64> = states
            .iter()
            .map(|s| match s.motion {
                Motion::Pocketed | Motion::OffTable | Motion::Airborne => f64::NAN,
                _ => s.slip(r).norm(),
            })
            .collect();
        for (kind, values) in [("speed", speed), ("slip", slip)] {
            let entity = path(&["plots", kind], id);
            self.rec
                .log_static(
                    entity.clone(),
                    &SeriesLines::update_fields()
                        .with_colors([colour])
                        .with_names([id]),
                )
                .map_err(rerun_err)?;
            self.send(
                entity,
                self.times_at(rows),
                Scalars::update_fields()
                    .with_scalars(values)
                    .columns_of_unit_batches(),
            )?;
        }
        let entity = path(&["plots", "spin"], id);
        self.rec
            .log_static(
                entity.clone(),
                &SeriesLines::update_fields()
                    .with_colors([
                        Color::from_rgb(230, 80, 80),
                        Color::from_rgb(80, 190, 80),
                        Color::from_rgb(80, 130, 255),
                    ])
                    .with_names([format!("{id} wx"), format!("{id} wy"), format!("{id} wz")]),
            )
            .map_err(rerun_err)?;
        self.send(
            entity,
            self.times_at(rows),
            Scalars::update_fields()
                .with_scalars(states.iter().flat_map(|s| {
                    if s.motion.in_play() {
                        [s.spin.x, s.spin.y, s.spin.z]
                    } else {
                        [f64::NAN; 3]
                    }
                }))
                .columns(std::iter::repeat_n(3, states.len())),
        )
    }

    /// The motion phase as a state timeline: a row wherever it changes.
    fn log_motion(&self, id: &str) -> Result<(), RecordError> {
        let entity = path(&["motion"], id);
        self.rec
            .log_static(
                entity.clone(),
                &StateConfiguration::new()
                    .with_values(MOTIONS.iter().map(|m| m.name()))
                    .with_colors(MOTIONS.iter().map(|&m| rgb(motion_color(m)))),
            )
            .map_err(rerun_err)?;
        let rows: Vec<usize> = (0..self.states.len())
            .filter(|&i| i == 0 || self.states[i].motion != self.states[i - 1].motion)
            .collect();
        self.send(
            entity,
            self.times_at(&rows),
            StateChange::update_fields()
                .with_state(rows.iter().map(|&i| self.states[i].motion.name()))
                .columns_of_unit_batches(),
        )
    }
}

/// Two perpendicular great circles through the body's poles (a cross seen from above at the
/// start), so that rolling and sidespin both show.
fn marker_rings(radius: f64) -> Vec<Vec<[f32; 3]>> {
    let n = 48;
    let circle = |f: &dyn Fn(f64) -> [f32; 3]| {
        (0..=n)
            .map(|k| f(std::f64::consts::TAU * k as f64 / n as f64))
            .collect::<Vec<_>>()
    };
    let r = radius;
    vec![
        circle(&|a| [(r * a.cos()) as f32, 0.0, (r * a.sin()) as f32]),
        circle(&|a| [0.0, (r * a.cos()) as f32, (r * a.sin()) as f32]),
    ]
}

/// The text of an event's log entry.
fn event_text(shot: &Shot, e: &snooker_engine::Event) -> String {
    let ids: Vec<&str> = e
        .balls
        .iter()
        .map(|&b| shot.tracks[b].id.as_str())
        .collect();
    let mut text = format!("{}: {}", e.kind.name(), ids.join(", "));
    if let Some(f) = &e.feature {
        text += &match e.kind {
            EventKind::BallPocket => format!(" in {f}"),
            EventKind::BallOffTable => format!(" over {f}"),
            _ => format!(" on {f}"),
        };
    }
    if let Some(v) = e.normal_speed {
        text += &format!(" (normal speed {v:.3} m/s)");
    }
    text
}

/// Events: a text log entry each, and a marker above the place of each impact, pot or
/// transition shown for [`MARKER_SECONDS`] from its exact time.
fn log_events(rec: &RecordingStream, shot: &Shot) -> Result<(), RecordError> {
    let r = shot.params.ball_radius;
    let events = &shot.events;
    rec.send_columns(
        "events/log",
        [TimeColumn::new_duration_secs(
            TIMELINE,
            events.iter().map(|e| e.t),
        )],
        TextLog::update_fields()
            .with_many_text(events.iter().map(|e| event_text(shot, e)))
            .with_many_level(events.iter().map(|e| match e.kind {
                EventKind::Transition(_) | EventKind::LiftOff => "DEBUG",
                _ => "INFO",
            }))
            .columns_of_unit_batches()
            .map_err(rerun_err)?,
    )
    .map_err(rerun_err)?;

    let marker = |e: &snooker_engine::Event| -> ([f32; 3], Color, f32) {
        let centre = e.after.iter().map(|s| s.pos).sum::<Vec3>() / e.after.len().max(1) as f64;
        let place = Vec3::new(centre.x, centre.y, 2.0 * r + 0.01);
        let (c, size) = match e.kind {
            EventKind::BallBall => ([255, 255, 255], 0.010),
            EventKind::BallCushion => ([255, 220, 0], 0.010),
            EventKind::BallPocket => ([255, 40, 40], 0.014),
            EventKind::BallOffTable => ([255, 120, 0], 0.014),
            EventKind::Transition(_) | EventKind::LiftOff => ([170, 170, 170], 0.005),
        };
        (f32x3(place), rgb(c), size)
    };
    // Rows wherever the set of live markers changes: at each event and at each expiry.
    let mut bounds: Vec<f64> = events
        .iter()
        .flat_map(|e| [e.t, e.t + MARKER_SECONDS])
        .collect();
    // Markers still live at the end of the shot stay to the end; the timeline ends there.
    bounds.retain(|&t| t <= shot.duration);
    bounds.sort_by(f64::total_cmp);
    bounds.dedup();
    let (mut counts, mut pos, mut colours, mut radii) = (vec![], vec![], vec![], vec![]);
    let mut first = 0;
    for &t in &bounds {
        while first < events.len() && events[first].t + MARKER_SECONDS <= t {
            first += 1;
        }
        let live: Vec<_> = events[first..]
            .iter()
            .take_while(|e| e.t <= t)
            .map(marker)
            .collect();
        counts.push(live.len());
        for (p, c, s) in live {
            pos.push(p);
            colours.push(c);
            radii.push(s);
        }
    }
    rec.send_columns(
        "events/markers",
        [TimeColumn::new_duration_secs(TIMELINE, bounds)],
        Points3D::update_fields()
            .with_positions(pos)
            .with_colors(colours)
            .with_radii(radii)
            .columns(counts)
            .map_err(rerun_err)?,
    )
    .map_err(rerun_err)
}
