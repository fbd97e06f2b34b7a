//! Where simulation and measurement disagree: residuals broken down by ball, by motion phase,
//! by the event they follow and by event kind, split along and across the direction of travel,
//! their trends with time, speed, spin and heading, and the measured speed-time curves of
//! thesis chapter 5 (deceleration per phase) against the simulated ones.

use crate::data::{Measurement, Observable};
use crate::residuals::observed_state;
use serde::Serialize;
use snooker_engine::{BallState, EventKind, Motion, Shot};

/// One sample compared: where the simulated ball was against where it was seen.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Point {
    /// Shot index.
    pub shot: usize,
    /// Ball id.
    pub ball: String,
    /// Time, s.
    pub t: f64,
    /// Simulated minus measured position, m.
    pub d: [f64; 2],
    /// Component of `d` along the simulated direction of travel (positive: simulated ahead), m.
    pub along: f64,
    /// Component of `d` to the left of the direction of travel, m.
    pub across: f64,
    /// Simulated speed, m/s.
    pub speed: f64,
    /// Simulated heading of travel, rad.
    pub heading: f64,
    /// Simulated sidespin, rad/s.
    pub spin_z: f64,
    /// Simulated motion phase.
    pub phase: Motion,
    /// The last event the ball took part in ("start" before any), e.g. "ball_cushion #2".
    pub since: String,
}

/// Residual statistics of a group of samples.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Group {
    /// What the group holds ("ball cue", "phase rolling", ...).
    pub key: String,
    /// Samples.
    pub n: usize,
    /// RMS distance, m.
    pub rms: f64,
    /// Largest distance, m.
    pub max: f64,
    /// Mean along-track component, m (positive: the simulation runs ahead).
    pub mean_along: f64,
    /// Mean across-track component, m (positive: the simulation is to the left).
    pub mean_across: f64,
}

/// A linear trend of a residual component with a variable, over moving samples.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Trend {
    /// Residual component ("along" or "across").
    pub component: &'static str,
    /// Variable ("time", "speed", "sidespin", "cos_heading", "sin_heading").
    pub variable: &'static str,
    /// Pearson correlation.
    pub correlation: f64,
    /// Least-squares slope, m per unit of the variable.
    pub slope: f64,
}

/// Measured and simulated deceleration over one phase of one ball (thesis §5.1.1: the slope of
/// the speed-time plot).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct PhaseDeceleration {
    /// Shot index.
    pub shot: usize,
    /// Ball id.
    pub ball: String,
    /// Phase.
    pub phase: Motion,
    /// Start and end of the stretch, s.
    pub t: [f64; 2],
    /// Speed estimates used.
    pub n: usize,
    /// Measured deceleration, m/s^2.
    pub measured: f64,
    /// Simulated deceleration over the same samples, m/s^2.
    pub simulated: f64,
}

/// One observable compared.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct ObservableRow {
    /// Shot name.
    pub shot: String,
    /// Ball id.
    pub ball: String,
    /// Quantity name.
    pub quantity: &'static str,
    /// Moment ("after:ball_cushion#1").
    pub when: String,
    /// Measured value.
    pub measured: f64,
    /// Simulated value (None: the moment never came).
    pub simulated: Option<f64>,
    /// 1-sigma uncertainty.
    pub sigma: f64,
    /// Simulated less measured ([`crate::data::Quantity::difference`]: a heading's is the
    /// turn between them, within a half turn), the simulated value taken as 0 where the moment
    /// never came, as the fit's residuals take it.
    pub difference: f64,
    /// Normal approach speed of the event the moment refers to, m/s.
    pub event_speed: Option<f64>,
}

/// The whole breakdown.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Location {
    /// By ball, phase, preceding event and event kind, largest RMS first.
    pub groups: Vec<Group>,
    /// Trends with |correlation| >= 0.3, strongest first.
    pub trends: Vec<Trend>,
    /// Speed-time analysis per phase.
    pub decelerations: Vec<PhaseDeceleration>,
    /// Observables, one row each.
    pub observables: Vec<ObservableRow>,
    /// The group (ball and preceding event) with the largest RMS, with its time range: where
    /// the disagreement is.
    pub worst: Option<String>,
}

/// The last direction of travel of a ball at or before `t` (its heading), if it ever moved.
fn last_heading(sim: &Shot, ball: usize, t: f64) -> Option<f64> {
    let track = &sim.tracks[ball];
    let s = track.state_at(t, &sim.params);
    if s.vel.xy().norm() > 1e-9 {
        return Some(s.vel.y.atan2(s.vel.x));
    }
    track
        .segments
        .iter()
        .rev()
        .filter(|seg| seg.t <= t)
        .find_map(|seg| {
            let v = seg.state.vel.xy();
            (v.norm() > 1e-9).then(|| v.y.atan2(v.x))
        })
}

/// The last event involving `ball` at or before `t`, as "kind #n" (n counts that kind for
/// that ball); a `lift_off` is not one (a hop is after the impact that made it).
fn since(sim: &Shot, ball: usize, t: f64) -> String {
    let mut counts = std::collections::HashMap::new();
    let mut last = "start".to_string();
    for e in sim
        .events
        .iter()
        .filter(|e| e.t <= t && e.balls.contains(&ball) && e.kind != EventKind::LiftOff)
    {
        let n = counts.entry(e.kind).or_insert(0usize);
        *n += 1;
        last = format!("{} #{}", e.kind.name(), n);
    }
    last
}

/// Every sample of `m` compared with its simulated shot.
pub fn points(m: &Measurement, sims: &[Shot]) -> Vec<Point> {
    let mut out = Vec::new();
    for (k, (shot, sim)) in m.shots.iter().zip(sims).enumerate() {
        for s in &shot.samples {
            let st: BallState = sim.tracks[s.ball].state_at(s.t, &sim.params);
            let d = [st.pos.x - s.pos[0], st.pos.y - s.pos[1]];
            let heading = last_heading(sim, s.ball, s.t).unwrap_or(0.0);
            let (c, sn) = (heading.cos(), heading.sin());
            out.push(Point {
                shot: k,
                ball: sim.tracks[s.ball].id.clone(),
                t: s.t,
                d,
                along: d[0] * c + d[1] * sn,
                across: -d[0] * sn + d[1] * c,
                speed: st.vel.xy().norm(),
                heading,
                spin_z: st.spin.z,
                phase: st.motion,
                since: since(sim, s.ball, s.t),
            });
        }
    }
    out
}

fn group(key: String, pts: &[&Point]) -> Group {
    let n = pts.len().max(1) as f64;
    let dist = |p: &Point| p.d[0].hypot(p.d[1]);
    Group {
        key,
        n: pts.len(),
        rms: (pts.iter().map(|p| dist(p).powi(2)).sum::<f64>() / n).sqrt(),
        max: pts.iter().map(|p| dist(p)).fold(0.0, f64::max),
        mean_along: pts.iter().map(|p| p.along).sum::<f64>() / n,
        mean_across: pts.iter().map(|p| p.across).sum::<f64>() / n,
    }
}

/// Groups of `pts` by a key, in order of first appearance.
fn groups_by(pts: &[Point], label: &str, key: impl Fn(&Point) -> String) -> Vec<Group> {
    let mut keys: Vec<String> = Vec::new();
    for p in pts {
        let k = key(p);
        if !keys.contains(&k) {
            keys.push(k);
        }
    }
    keys.into_iter()
        .map(|k| {
            let members: Vec<&Point> = pts.iter().filter(|p| key(p) == k).collect();
            group(format!("{label} {k}"), &members)
        })
        .collect()
}

/// Pearson correlation and least-squares slope of y on x.
fn regression(x: &[f64], y: &[f64]) -> Option<(f64, f64)> {
    let n = x.len() as f64;
    if x.len() < 10 {
        return None;
    }
    let (mx, my) = (x.iter().sum::<f64>() / n, y.iter().sum::<f64>() / n);
    let sxx: f64 = x.iter().map(|v| (v - mx).powi(2)).sum();
    let syy: f64 = y.iter().map(|v| (v - my).powi(2)).sum();
    let sxy: f64 = x.iter().zip(y).map(|(a, b)| (a - mx) * (b - my)).sum();
    if sxx <= 0.0 || syy <= 0.0 {
        return None;
    }
    Some((sxy / (sxx * syy).sqrt(), sxy / sxx))
}

/// A named quantity of a compared sample.
type Reading = (&'static str, fn(&Point) -> f64);

fn trends(pts: &[Point]) -> Vec<Trend> {
    let moving: Vec<&Point> = pts.iter().filter(|p| p.speed > 1e-6).collect();
    let variables: [Reading; 5] = [
        ("time", |p| p.t),
        ("speed", |p| p.speed),
        ("sidespin", |p| p.spin_z),
        ("cos_heading", |p| p.heading.cos()),
        ("sin_heading", |p| p.heading.sin()),
    ];
    let components: [Reading; 2] = [("along", |p| p.along), ("across", |p| p.across)];
    let mut out = Vec::new();
    for (component, cf) in components {
        let y: Vec<f64> = moving.iter().map(|p| cf(p)).collect();
        for (variable, vf) in variables {
            let x: Vec<f64> = moving.iter().map(|p| vf(p)).collect();
            if let Some((correlation, slope)) = regression(&x, &y)
                && correlation.abs() >= 0.3
            {
                out.push(Trend {
                    component,
                    variable,
                    correlation,
                    slope,
                });
            }
        }
    }
    out.sort_by(|a, b| b.correlation.abs().total_cmp(&a.correlation.abs()));
    out
}

/// Speed estimates from the measured track: a least-squares line through 7 consecutive samples
/// of the ball (its slope's norm), kept only when the simulated ball has one phase, and no
/// event, across the window.
fn decelerations(m: &Measurement, sims: &[Shot]) -> Vec<PhaseDeceleration> {
    const HALF: usize = 3;
    let mut out = Vec::new();
    for (k, (shot, sim)) in m.shots.iter().zip(sims).enumerate() {
        for ball in 0..shot.setup.balls.len() {
            let samples: Vec<_> = shot.samples.iter().filter(|s| s.ball == ball).collect();
            // (t, measured speed, simulated speed, phase, last event index)
            let mut est: Vec<(f64, f64, f64, Motion, usize)> = Vec::new();
            for w in samples.windows(2 * HALF + 1) {
                let (t0, t1) = (w[0].t, w[2 * HALF].t);
                let events_in = |a: f64, b: f64| {
                    sim.events
                        .iter()
                        .filter(|e| e.balls.contains(&ball) && e.t > a && e.t <= b)
                        .count()
                };
                if events_in(t0, t1) > 0 {
                    continue;
                }
                let ts: Vec<f64> = w.iter().map(|s| s.t).collect();
                let vx = regression(&ts, &w.iter().map(|s| s.pos[0]).collect::<Vec<_>>());
                let vy = regression(&ts, &w.iter().map(|s| s.pos[1]).collect::<Vec<_>>());
                let slope = |r: Option<(f64, f64)>| r.map_or(0.0, |v| v.1);
                let tc = w[HALF].t;
                let st = sim.tracks[ball].state_at(tc, &sim.params);
                if !matches!(st.motion, Motion::Sliding | Motion::Rolling) {
                    continue;
                }
                let epoch = events_in(f64::NEG_INFINITY, tc);
                est.push((
                    tc,
                    slope(vx).hypot(slope(vy)),
                    st.vel.xy().norm(),
                    st.motion,
                    epoch,
                ));
            }
            let mut i = 0;
            while i < est.len() {
                let j = est[i..]
                    .iter()
                    .position(|e| e.3 != est[i].3 || e.4 != est[i].4)
                    .map_or(est.len(), |p| i + p);
                let run = &est[i..j];
                let ts: Vec<f64> = run.iter().map(|e| e.0).collect();
                let meas: Vec<f64> = run.iter().map(|e| e.1).collect();
                let simv: Vec<f64> = run.iter().map(|e| e.2).collect();
                let fit = |ys: &[f64]| -> Option<f64> {
                    let n = ts.len() as f64;
                    if ts.len() < 10 {
                        return None;
                    }
                    let mt = ts.iter().sum::<f64>() / n;
                    let my = ys.iter().sum::<f64>() / n;
                    let sxx: f64 = ts.iter().map(|t| (t - mt).powi(2)).sum();
                    let sxy: f64 = ts.iter().zip(ys).map(|(t, y)| (t - mt) * (y - my)).sum();
                    (sxx > 0.0).then(|| -sxy / sxx)
                };
                if let (Some(measured), Some(simulated)) = (fit(&meas), fit(&simv)) {
                    out.push(PhaseDeceleration {
                        shot: k,
                        ball: sim.tracks[ball].id.clone(),
                        phase: run[0].3,
                        t: [ts[0], ts[ts.len() - 1]],
                        n: ts.len(),
                        measured,
                        simulated,
                    });
                }
                i = j;
            }
        }
    }
    out
}

/// The observables of `m` against the simulated shots.
pub fn observable_rows(m: &Measurement, sims: &[Shot]) -> Vec<ObservableRow> {
    let mut out = Vec::new();
    for (shot, sim) in m.shots.iter().zip(sims) {
        for o in &shot.observables {
            out.push(observable_row(&shot.name, sim, o));
        }
    }
    out
}

fn observable_row(shot: &str, sim: &Shot, o: &Observable) -> ObservableRow {
    let (kind, n) = o.when.event();
    let simulated = observed_state(sim, o).map(|s| o.quantity.of(&s));
    let event_speed = sim
        .events
        .iter()
        .filter(|e| e.kind == kind && e.balls.contains(&o.ball))
        .nth(n.saturating_sub(1))
        .and_then(|e| e.normal_speed);
    ObservableRow {
        shot: shot.to_string(),
        ball: sim.tracks[o.ball].id.clone(),
        quantity: o.quantity.name(),
        when: o.when.to_string(),
        measured: o.value,
        simulated,
        sigma: o.sigma,
        difference: o.quantity.difference(simulated.unwrap_or(0.0), o.value),
        event_speed,
    }
}

/// The breakdown of `m`'s residuals against `sims`.
pub fn locate(m: &Measurement, sims: &[Shot]) -> Location {
    let pts = points(m, sims);
    let multi = m.shots.len() > 1;
    let shot_prefix = |p: &Point| {
        if multi {
            format!("{}: ", m.shots[p.shot].name)
        } else {
            String::new()
        }
    };
    let mut groups = Vec::new();
    groups.extend(groups_by(&pts, "ball", |p| {
        format!("{}{}", shot_prefix(p), p.ball)
    }));
    groups.extend(groups_by(&pts, "phase", |p| p.phase.name().to_string()));
    groups.extend(groups_by(&pts, "after", |p| {
        p.since.split(" #").next().unwrap_or("").to_string()
    }));
    let detail = groups_by(&pts, "ball", |p| {
        format!("{}{} after {}", shot_prefix(p), p.ball, p.since)
    });
    let worst = detail
        .iter()
        .filter(|g| g.n > 0)
        .max_by(|a, b| a.rms.total_cmp(&b.rms))
        .map(|g| {
            let key = g.key.trim_start_matches("ball ");
            let ts: Vec<f64> = pts
                .iter()
                .filter(|p| format!("{}{} after {}", shot_prefix(p), p.ball, p.since) == key)
                .map(|p| p.t)
                .collect();
            let (a, b) = (
                ts.iter().copied().fold(f64::INFINITY, f64::min),
                ts.iter().copied().fold(0.0, f64::max),
            );
            format!(
                "{key}, t = {a:.2}-{b:.2} s: RMS {:.1} mm, mean {:.1} mm along and {:.1} mm \
                 across the direction of travel",
                g.rms * 1e3,
                g.mean_along * 1e3,
                g.mean_across * 1e3
            )
        });
    groups.extend(detail);
    groups.sort_by(|a, b| b.rms.total_cmp(&a.rms));
    Location {
        groups,
        trends: trends(&pts),
        decelerations: decelerations(m, sims),
        observables: observable_rows(m, sims),
        worst,
    }
}
