//! A recording of a sequence of strokes of a frame of snooker (`snooker referee F1 F2 ...
//! --record OUT.rrd`): the strokes one after another on the one timeline [`super::TIMELINE`],
//! [`PAUSE`] apart, every ball as in a shot's recording (a respotted colour reappears on its
//! spot, the cue ball in hand in the D, when the next stroke starts: each stroke's start is
//! sampled just before and just after, as an event is, `sample::Schedule::with_cuts`), and the
//! frame as it goes: a scoreboard above the near cushion (`frame/scoreboard`: the scores, who is to play and the
//! ball on, updated as each stroke starts and ends) and the referee's calls in the event log
//! (`events/frame`).

use super::{RecordError, RecordOptions, rerun_err};
use rerun::{Color, Points3D, RecordingStream, TextLog};
use snooker_engine::sim::shot::Stats;
use snooker_engine::sim::{Segment, Track};
use snooker_engine::{Ending, Event, Setup, Shot};
use snooker_rules::{Frame, FrameState, Verdict};
use snooker_scene::Scene;

/// Time between the end of one stroke and the start of the next on the timeline, s.
pub const PAUSE: f64 = 1.0;
/// Where the scoreboard hangs: beside the near long cushion, at mid-table, m.
pub const SCOREBOARD: [f32; 3] = [1.7845, -0.1, 0.06];

/// One stroke to record: the frame it was played from, its shot and the verdict.
#[derive(Clone, Copy, Debug)]
pub struct RecordedStroke<'a> {
    /// The frame before the stroke.
    pub frame: &'a Frame,
    /// The simulated shot.
    pub shot: &'a Shot,
    /// The referee's verdict.
    pub verdict: &'a Verdict,
}

/// The strokes as one shot: each ball one track over the whole sequence (its segments shifted
/// to their stroke's start), the events likewise, and when each stroke starts.
pub fn chain(strokes: &[RecordedStroke]) -> (Shot, Vec<f64>) {
    let mut tracks: Vec<Track> = Vec::new();
    let mut events: Vec<Event> = Vec::new();
    let mut starts = Vec::new();
    let mut t0 = 0.0;
    for s in strokes {
        starts.push(t0);
        let index: Vec<usize> = s
            .shot
            .tracks
            .iter()
            .map(|tr| match tracks.iter().position(|t| t.id == tr.id) {
                Some(i) => i,
                None => {
                    let mut segments = Vec::new();
                    if t0 > 0.0 {
                        // Not on the table before this stroke.
                        let mut hidden = tr.segments[0].state;
                        hidden.motion = snooker_engine::Motion::Pocketed;
                        segments.push(Segment {
                            t: 0.0,
                            state: hidden,
                        });
                    }
                    tracks.push(Track {
                        id: tr.id.clone(),
                        kind: tr.kind,
                        segments,
                    });
                    tracks.len() - 1
                }
            })
            .collect();
        for (tr, &i) in s.shot.tracks.iter().zip(&index) {
            tracks[i]
                .segments
                .extend(tr.segments.iter().map(|seg| Segment {
                    t: seg.t + t0,
                    state: seg.state,
                }));
        }
        events.extend(s.shot.events.iter().map(|e| Event {
            t: e.t + t0,
            balls: e.balls.iter().map(|&b| index[b]).collect(),
            ..e.clone()
        }));
        t0 += s.shot.duration + PAUSE;
    }
    let params = strokes.first().map(|s| s.shot.params).unwrap_or_default();
    let shot = Shot {
        params,
        events,
        tracks,
        duration: (t0 - PAUSE).max(0.0),
        ending: Ending::AtRest,
        stats: Stats::default(),
    };
    (shot, starts)
}

/// The scoreboard's text for a state (before a stroke, or the next one after it).
fn board(state: &FrameState) -> String {
    let mut on = state.on.to_string();
    if let Some(n) = state.nominated {
        on = format!("{on} ({n})");
    }
    let mut extra = String::new();
    if state.ball_in_hand {
        extra += ", ball in hand";
    }
    if state.free_ball {
        extra += ", free ball";
    }
    format!(
        "player 0: {}   player 1: {}   | player {} to play, on {on}{extra}",
        state.scores[0], state.scores[1], state.to_play
    )
}

/// What the referee called.
fn call(n: usize, v: &Verdict) -> String {
    let what = match &v.foul {
        None if v.points > 0 => format!("legal, {} point(s)", v.points),
        None => "legal, no score".to_string(),
        Some(f) => format!("foul, {} ({} points)", f.reason, f.points),
    };
    let potted = if v.potted.is_empty() {
        String::new()
    } else {
        format!("; potted {}", v.potted.join(", "))
    };
    // A colour put back, the black after a tie on it included (the re-spotted black game,
    // WPBSA Section 3 Rule 4(c)).
    let respotted = if v.respotted.is_empty() {
        String::new()
    } else {
        let ids: Vec<&str> = v.respotted.iter().map(|(id, _)| id.as_str()).collect();
        format!("; respotted {}", ids.join(", "))
    };
    let end = match v.winner {
        Some(w) if v.frame_over() => format!("; frame over, player {w} wins"),
        _ => String::new(),
    };
    format!(
        "stroke {n}: {what}{potted}{respotted}; scores {}-{}{end}",
        v.scores[0], v.scores[1]
    )
}

/// Records `strokes` (in the order played) and returns the `.rrd` file's bytes.
pub fn encode_strokes(
    strokes: &[RecordedStroke],
    opts: &RecordOptions,
) -> Result<Vec<u8>, RecordError> {
    encode_strokes_with(strokes, opts, |_, _| Ok(()))
}

/// As [`encode_strokes`], then `extra` logs what the caller adds (a player's plans), given
/// the recording and when each stroke starts on the timeline ([`super::TIMELINE`]).
pub fn encode_strokes_with(
    strokes: &[RecordedStroke],
    opts: &RecordOptions,
    extra: impl FnOnce(&RecordingStream, &[f64]) -> Result<(), RecordError>,
) -> Result<Vec<u8>, RecordError> {
    let Some(first) = strokes.first() else {
        return Err(RecordError::Rerun("no stroke to record".into()));
    };
    let (shot, starts) = chain(strokes);
    let balls = shot.balls_at(0.0);
    let scene = Scene {
        name: first.frame.name().to_string(),
        setup: Setup {
            table: first.frame.table().clone(),
            params: *first.frame.params(),
            models: *first.frame.models(),
            balls,
        },
        options: *first.frame.options(),
        strike: None,
    };
    // Each stroke after the first starts with no event: balls struck, respotted or placed.
    let cuts = starts.get(1..).unwrap_or_default();
    super::encode_with_cuts(&scene, &shot, cuts, opts, &[], |rec| {
        log_frame(rec, strokes, &starts)?;
        extra(rec, &starts)?;
        rec.reset_time();
        Ok(())
    })
}

/// The scoreboard and the referee's calls.
fn log_frame(
    rec: &RecordingStream,
    strokes: &[RecordedStroke],
    starts: &[f64],
) -> Result<(), RecordError> {
    let scoreboard = |text: String| {
        Points3D::new([SCOREBOARD])
            .with_labels([text])
            .with_colors([Color::from_rgb(240, 240, 240)])
            .with_radii([rerun::Radius::new_scene_units(0.004)])
            .with_show_labels(true)
    };
    for (n, (s, &t)) in strokes.iter().zip(starts).enumerate() {
        rec.set_duration_secs(super::TIMELINE, t);
        rec.log("frame/scoreboard", &scoreboard(board(s.frame.state())))
            .map_err(rerun_err)?;
        rec.log(
            "events/frame",
            &TextLog::new(format!("stroke {}: {}", n + 1, board(s.frame.state()))),
        )
        .map_err(rerun_err)?;
        rec.set_duration_secs(super::TIMELINE, t + s.shot.duration);
        let after = match (&s.verdict.next, s.verdict.winner) {
            (Some(next), _) => board(next),
            (None, w) => format!(
                "player 0: {}   player 1: {}   | frame over, player {} wins",
                s.verdict.scores[0],
                s.verdict.scores[1],
                w.unwrap_or(0)
            ),
        };
        rec.log("frame/scoreboard", &scoreboard(after))
            .map_err(rerun_err)?;
        rec.log("events/frame", &TextLog::new(call(n + 1, s.verdict)))
            .map_err(rerun_err)?;
    }
    rec.reset_time();
    Ok(())
}
