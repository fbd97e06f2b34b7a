//! The default viewer layout shipped inside the recording: the 3D table view on top, seen
//! from above the near long side; below it the time series (speed, slip, spin), the motion
//! timeline and the event log.
//!
//! The Rust SDK's blueprint builder cannot set a 3D view's eye, so the blueprint store is
//! written directly, with the entity paths the viewer reads (as the Python SDK writes them).

use super::{RecordError, TIMELINE, rerun_err};
use rerun::external::re_log_types::{BlueprintActivationCommand, StoreId};
use rerun::external::re_sdk_types::blueprint::archetypes::{
    Background, ContainerBlueprint, EyeControls3D, LineGrid3D, PanelBlueprint, PlotLegend,
    TextLogColumns, TimePanelBlueprint, ViewBlueprint, ViewContents, ViewportBlueprint,
};
use rerun::external::re_sdk_types::blueprint::components::{
    BackgroundKind, ContainerKind, Corner2D, Eye3DKind, IncludedContent, PanelState, PlayState,
    QueryExpression, RootContainer, TextLogColumn, ViewClass,
};
use rerun::external::re_sdk_types::blueprint::datatypes::{self, TextLogColumnKind};
use rerun::external::uuid::Uuid;
use rerun::{Color, RecordingStream};
use snooker_engine::Vec3;

/// Elevation of the default eye above the table plane, rad (looking down at 60 degrees).
const ELEVATION: f64 = 1.05;
/// Vertical field of view the eye distance is computed for, rad (the viewer's default, 55 deg).
const FOV_Y: f64 = 0.96;
/// Share of the view's height the framed rectangle fills.
const FILL: f64 = 0.9;
/// The narrowest view (width over height) the framing allows for.
const MIN_ASPECT: f64 = 2.0;

/// Where the eye goes and what it looks at to frame the plan rectangle `lo`..`hi` from above
/// its near long side: its near and far edges fill [`FILL`] of the view's height, symmetrically
/// about the centre of the view, and its length fits a view at least [`MIN_ASPECT`] wide.
fn eye(lo: Vec3, hi: Vec3) -> (Vec3, Vec3) {
    let centre = 0.5 * (lo + hi);
    let back = Vec3::new(0.0, -ELEVATION.cos(), ELEVATION.sin());
    let near = Vec3::new(centre.x, lo.y, 0.0);
    let far = Vec3::new(centre.x, hi.y, 0.0);
    let spread = |d: f64| {
        let e = centre + d * back;
        (near - e).normalize().angle(&(far - e).normalize())
    };
    // The spread falls as the eye backs off: bisect for the distance that gives FILL * FOV_Y.
    let (mut a, mut b) = (1e-3f64, 1e3f64);
    for _ in 0..100 {
        let m = (a * b).sqrt();
        if spread(m) > FILL * FOV_Y {
            a = m
        } else {
            b = m
        }
    }
    let half_width = (MIN_ASPECT * (0.5 * FOV_Y).tan()).atan();
    let d = a.max(0.5 * (hi.x - lo.x) / (FILL * half_width).tan());
    let e = centre + d * back;
    let axis = ((near - e).normalize() + (far - e).normalize()).normalize();
    let target = e + axis * (-e.z / axis.z);
    (e, target)
}

/// Fixed ids, so that the same scene always yields the same layout.
fn id(n: u8) -> Uuid {
    Uuid::from_bytes([
        0x5e, 0x0c, 0x4e, 0x40, 0, 0, 0x40, 0, 0x80, 0, 0, 0, 0, 0, 0, n,
    ])
}

struct View {
    id: Uuid,
    class: &'static str,
    name: &'static str,
    origin: &'static str,
    contents: &'static [&'static str],
}

impl View {
    fn path(&self) -> String {
        format!("view/{}", self.id)
    }

    fn log(&self, bp: &RecordingStream) -> Result<(), RecordError> {
        bp.log(
            format!("{}/ViewContents", self.path()),
            &ViewContents::new(self.contents.iter().map(|q| QueryExpression((*q).into()))),
        )
        .map_err(rerun_err)?;
        bp.log(
            self.path(),
            &ViewBlueprint::new(ViewClass(self.class.into()))
                .with_display_name(self.name)
                .with_space_origin(self.origin),
        )
        .map_err(rerun_err)
    }
}

fn container(
    bp: &RecordingStream,
    id: Uuid,
    kind: ContainerKind,
    children: &[String],
    shares: &[f32],
) -> Result<(), RecordError> {
    let mut c = ContainerBlueprint::new(kind)
        .with_contents(children.iter().map(|p| IncludedContent(p.as_str().into())));
    c = match kind {
        ContainerKind::Vertical => c.with_row_shares(shares.iter().copied()),
        ContainerKind::Horizontal => c.with_col_shares(shares.iter().copied()),
        _ => c,
    };
    bp.log(format!("container/{id}"), &c).map_err(rerun_err)
}

/// Sends the layout to `rec`, with the 3D eye framing the plan rectangle `extent` and the
/// timeline opening at `open_at`, and makes it the recording's default.
pub fn send(
    rec: &RecordingStream,
    extent: Option<(Vec3, Vec3)>,
    open_at: super::OpenAt,
) -> Result<(), RecordError> {
    let (bp, storage) = super::builder()
        .enabled(true)
        .blueprint()
        .memory()
        .map_err(rerun_err)?;
    bp.set_time_sequence("blueprint", 0);

    let table = View {
        id: id(1),
        class: "3D",
        name: "table",
        origin: "/",
        contents: &["+ /**", "- /plots/**", "- /motion/**", "- /events/log"],
    };
    let plots = [
        View {
            id: id(2),
            class: "TimeSeries",
            name: "speed (m/s)",
            origin: "/plots/speed",
            contents: &["+ $origin/**"],
        },
        View {
            id: id(3),
            class: "TimeSeries",
            name: "slip at the cloth (m/s)",
            origin: "/plots/slip",
            contents: &["+ $origin/**"],
        },
        View {
            id: id(4),
            class: "TimeSeries",
            name: "spin (rad/s)",
            origin: "/plots/spin",
            contents: &["+ $origin/**"],
        },
    ];
    let motion = View {
        id: id(5),
        class: "StateTimeline",
        name: "motion",
        origin: "/motion",
        contents: &["+ $origin/**"],
    };
    let events = View {
        id: id(6),
        class: "TextLog",
        name: "events",
        origin: "/events",
        contents: &["+ $origin/**"],
    };
    for v in plots.iter().chain([&table, &motion, &events]) {
        v.log(&bp)?;
    }
    for v in &plots {
        bp.log(
            format!("{}/PlotLegend", v.path()),
            &PlotLegend::new().with_corner(Corner2D::RightTop),
        )
        .map_err(rerun_err)?;
    }
    // The event text says it all: no entity path or level columns.
    let column = |kind, visible: bool| {
        TextLogColumn(datatypes::TextLogColumn {
            kind,
            visible: visible.into(),
        })
    };
    bp.log(
        format!("{}/TextLogColumns", events.path()),
        &TextLogColumns::new().with_text_log_columns([
            column(TextLogColumnKind::EntityPath, false),
            column(TextLogColumnKind::LogLevel, false),
            column(TextLogColumnKind::Body, true),
        ]),
    )
    .map_err(rerun_err)?;

    if let Some((lo, hi)) = extent {
        let (eye, centre) = eye(lo, hi);
        bp.log(
            format!("{}/EyeControls3D", table.path()),
            &EyeControls3D::new()
                .with_kind(Eye3DKind::Orbital)
                .with_position([eye.x as f32, eye.y as f32, eye.z as f32])
                .with_look_target([centre.x as f32, centre.y as f32, 0.0])
                .with_eye_up([0.0, 0.0, 1.0]),
        )
        .map_err(rerun_err)?;
    }
    bp.log(
        format!("{}/LineGrid3D", table.path()),
        &LineGrid3D::new().with_visible(false),
    )
    .map_err(rerun_err)?;
    bp.log(
        format!("{}/Background", table.path()),
        &Background::new(BackgroundKind::SolidColor).with_color(Color::from_rgb(38, 38, 42)),
    )
    .map_err(rerun_err)?;

    let tabs = id(10);
    let bottom = id(11);
    let root = id(12);
    container(
        &bp,
        tabs,
        ContainerKind::Tabs,
        &plots.iter().map(View::path).collect::<Vec<_>>(),
        &[],
    )?;
    container(
        &bp,
        bottom,
        ContainerKind::Horizontal,
        &[format!("container/{tabs}"), motion.path(), events.path()],
        &[5.0, 3.0, 4.0],
    )?;
    container(
        &bp,
        root,
        ContainerKind::Vertical,
        &[table.path(), format!("container/{bottom}")],
        &[2.0, 1.0],
    )?;
    bp.log(
        "viewport",
        &ViewportBlueprint::new()
            .with_root_container(RootContainer(root.into()))
            .with_auto_layout(false)
            .with_auto_views(false),
    )
    .map_err(rerun_err)?;
    // Open paused at the start of the shot (or following it to its end: the latest data), the
    // time series showing it all; the side panels folded away so that the views get the room.
    let play_state = match open_at {
        super::OpenAt::Start => PlayState::Paused,
        super::OpenAt::End => PlayState::Following,
    };
    bp.log(
        "time_panel",
        &TimePanelBlueprint::new()
            .with_timeline(TIMELINE)
            .with_play_state(play_state)
            .with_state(PanelState::Collapsed),
    )
    .map_err(rerun_err)?;
    for panel in ["blueprint_panel", "selection_panel"] {
        bp.log(
            panel,
            &PanelBlueprint::new().with_state(PanelState::Collapsed),
        )
        .map_err(rerun_err)?;
    }

    let msgs = storage.take();
    let blueprint_id: StoreId = msgs
        .first()
        .map(|m| m.store_id().clone())
        .ok_or_else(|| RecordError::Rerun("empty blueprint".into()))?;
    rec.send_blueprint(
        msgs,
        BlueprintActivationCommand {
            blueprint_id,
            make_active: true,
            make_default: true,
        },
    );
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_eye_frames_the_table_from_above_its_near_side() {
        let (lo, hi) = (Vec3::new(-0.14, -0.14, 0.0), Vec3::new(3.709, 1.918, 0.0));
        let (e, target) = eye(lo, hi);
        let mid = 0.5 * (lo.x + hi.x);
        let axis = (target - e).normalize();
        let near = (Vec3::new(mid, lo.y, 0.0) - e).normalize();
        let far = (Vec3::new(mid, hi.y, 0.0) - e).normalize();
        assert!((axis.angle(&near) - axis.angle(&far)).abs() < 1e-9);
        // It fits both ways, and one of the two fills the view.
        let tall = near.angle(&far) / (FILL * FOV_Y);
        let half_width = (MIN_ASPECT * (0.5 * FOV_Y).tan()).atan();
        let centre = 0.5 * (lo + hi);
        let wide = 0.5 * (hi.x - lo.x) / ((e - centre).norm() * (FILL * half_width).tan());
        assert!(tall <= 1.0 + 1e-9 && wide <= 1.0 + 1e-9, "{tall} {wide}");
        assert!((tall.max(wide) - 1.0).abs() < 1e-9, "{tall} {wide}");
        assert!(e.y < lo.y && e.z > 1.0 && (e.x - mid).abs() < 1e-12);
        assert!(target.z.abs() < 1e-12);
    }
}
