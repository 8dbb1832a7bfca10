//! The viewer layout (blueprint) of a recording, written with Rerun's blueprint archetypes.
//!
//! Rerun's Rust blueprint builder (0.36) cannot set a 3-D view's camera, a 2-D view's visible
//! area or a plot's legend, so the few archetypes it would write are written here: containers
//! (with their shares and active tab), views (with their properties), the viewport and the
//! panels. The viewer reads them from the blueprint store like any other layout.

use rerun::blueprint::components::{
    ActiveTab, ColumnShare, ContainerKind, Corner2D, IncludedContent, PanelState, PlayState,
    QueryExpression, RootContainer, RowShare, TimelineName, ViewClass,
};
use rerun::external::re_sdk_types::blueprint::archetypes::{
    ContainerBlueprint, EyeControls3D, LineGrid3D, PanelBlueprint, PlotLegend, TensorScalarMapping,
    TimePanelBlueprint, ViewBlueprint, ViewContents, ViewportBlueprint, VisualBounds2D,
};
use rerun::RecordingStream;

use super::RecordError;

/// A 3-D view's initial camera: where the eye is, what it looks at, which way is up.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Eye {
    pub position: [f32; 3],
    pub target: [f32; 3],
    pub up: [f32; 3],
}

/// What a view shows.
#[derive(Clone, Debug, PartialEq)]
pub enum ViewKind {
    /// A 2-D view; optionally the area shown at first (`[x_min, x_max, y_min, y_max]`).
    Spatial2D(Option<[f64; 4]>),
    Spatial3D(Option<Eye>),
    TimeSeries,
    TextDocument,
    TextLog,
    /// A tensor view, its values coloured by this colour map.
    Tensor(rerun::components::Colormap),
}

impl ViewKind {
    fn class(&self) -> &'static str {
        match self {
            ViewKind::Spatial2D(_) => "2D",
            ViewKind::Spatial3D(_) => "3D",
            ViewKind::TimeSeries => "TimeSeries",
            ViewKind::TextDocument => "TextDocument",
            ViewKind::TextLog => "TextLog",
            ViewKind::Tensor(_) => "Tensor",
        }
    }
}

/// A view: its title, what it shows, the entity subtree it shows (`origin`) and the queries
/// selecting its entities (default: everything under the origin).
#[derive(Clone, Debug, PartialEq)]
pub struct View {
    pub name: String,
    pub kind: ViewKind,
    pub origin: String,
    pub contents: Vec<String>,
}

impl View {
    pub fn new(kind: ViewKind, name: impl Into<String>, origin: impl Into<String>) -> Self {
        Self {
            name: name.into(),
            kind,
            origin: origin.into(),
            contents: vec!["$origin/**".into()],
        }
    }

    pub fn with_contents(mut self, contents: &[&str]) -> Self {
        self.contents = contents.iter().map(|c| c.to_string()).collect();
        self
    }
}

/// A layout node.
#[derive(Clone, Debug, PartialEq)]
pub enum Node {
    View(View),
    /// Side by side, with relative widths.
    Horizontal(Vec<Node>, Vec<f32>),
    /// Stacked, with relative heights.
    Vertical(Vec<Node>, Vec<f32>),
    /// Tabs; the active one by index.
    Tabs(Vec<Node>, usize),
}

/// The whole layout: the root node, and the timeline the time panel shows first (`None`
/// collapses the time panel for a recording of one step).
#[derive(Clone, Debug, PartialEq)]
pub struct Layout {
    pub root: Node,
    pub timeline: Option<String>,
}

/// Ids of blueprint entities: 16 bytes, a counter in the low bytes (unique within one
/// blueprint, which is all the viewer asks).
struct Ids(u64);

impl Ids {
    fn next(&mut self) -> [u8; 16] {
        self.0 += 1;
        let mut bytes = [0u8; 16];
        // A version-4-looking UUID with the counter in its last eight bytes.
        bytes[..8].copy_from_slice(&0x5354_5245_5353_4000u64.to_be_bytes());
        bytes[6] = 0x40;
        bytes[8..].copy_from_slice(&(0x8000_0000_0000_0000 | self.0).to_be_bytes());
        bytes
    }
}

fn uuid_text(bytes: [u8; 16]) -> String {
    rerun::external::uuid::Uuid::from_bytes(bytes).to_string()
}

/// Logs `node` (children first) into the blueprint stream; returns its blueprint path.
fn log_node(stream: &RecordingStream, node: &Node, ids: &mut Ids) -> Result<String, RecordError> {
    let id = uuid_text(ids.next());
    match node {
        Node::View(view) => {
            let path = format!("view/{id}");
            stream.log(
                format!("{path}/ViewContents"),
                &ViewContents::new(
                    view.contents
                        .iter()
                        .map(|q| QueryExpression(q.clone().into())),
                ),
            )?;
            stream.log(
                path.as_str(),
                &ViewBlueprint::new(ViewClass(view.kind.class().into()))
                    .with_display_name(view.name.clone())
                    .with_space_origin(view.origin.clone()),
            )?;
            match &view.kind {
                ViewKind::Spatial2D(Some([x0, x1, y0, y1])) => {
                    let range = rerun::datatypes::Range2D {
                        x_range: [*x0, *x1].into(),
                        y_range: [*y0, *y1].into(),
                    };
                    stream.log(
                        format!("{path}/VisualBounds2D"),
                        &VisualBounds2D::new(range),
                    )?;
                }
                ViewKind::Spatial3D(Some(eye)) => {
                    // No ground grid: it would cut through the body under the surface.
                    stream.log(
                        format!("{path}/LineGrid3D"),
                        &LineGrid3D::new().with_visible(false),
                    )?;
                    stream.log(
                        format!("{path}/EyeControls3D"),
                        &EyeControls3D::new()
                            .with_position(eye.position)
                            .with_look_target(eye.target)
                            .with_eye_up(eye.up),
                    )?;
                }
                ViewKind::Tensor(colormap) => {
                    stream.log(
                        format!("{path}/TensorScalarMapping"),
                        &TensorScalarMapping::new().with_colormap(*colormap),
                    )?;
                }
                ViewKind::TimeSeries => {
                    stream.log(
                        format!("{path}/PlotLegend"),
                        &PlotLegend::new().with_corner(Corner2D::LeftTop),
                    )?;
                }
                _ => {}
            }
            Ok(path)
        }
        Node::Horizontal(children, _) | Node::Vertical(children, _) | Node::Tabs(children, _) => {
            let paths = children
                .iter()
                .map(|child| log_node(stream, child, ids))
                .collect::<Result<Vec<_>, _>>()?;
            let kind = match node {
                Node::Horizontal(..) => ContainerKind::Horizontal,
                Node::Vertical(..) => ContainerKind::Vertical,
                _ => ContainerKind::Tabs,
            };
            let mut container = ContainerBlueprint::new(kind)
                .with_contents(paths.iter().map(|p| IncludedContent(p.as_str().into())));
            match node {
                Node::Horizontal(_, shares) if !shares.is_empty() => {
                    container =
                        container.with_col_shares(shares.iter().map(|&s| ColumnShare(s.into())));
                }
                Node::Vertical(_, shares) if !shares.is_empty() => {
                    container =
                        container.with_row_shares(shares.iter().map(|&s| RowShare(s.into())));
                }
                Node::Tabs(_, active) => {
                    if let Some(path) = paths.get(*active) {
                        container = container.with_active_tab(ActiveTab(path.as_str().into()));
                    }
                }
                _ => {}
            }
            let path = format!("container/{id}");
            stream.log(path.as_str(), &container)?;
            Ok(path)
        }
    }
}

/// Sends `layout` to `recording` as its active and default blueprint. The blueprint and
/// selection panels start collapsed, so that the views get the window. The time cursor starts
/// at the first step of a file, and follows the newest step of a `live` stream (a viewer
/// watching a run as it arrives).
pub fn send(recording: &RecordingStream, layout: &Layout, live: bool) -> Result<(), RecordError> {
    let (stream, storage) = rerun::RecordingStreamBuilder::new(super::APPLICATION_ID)
        .blueprint()
        .memory()?;
    stream.set_time_sequence("blueprint", 0);
    let mut ids = Ids(0);
    let root = log_node(&stream, &layout.root, &mut ids)?;
    let root_id = match root.split_once('/') {
        Some((_, id)) => rerun::external::uuid::Uuid::parse_str(id)
            .map_err(|e| RecordError::Rerun(e.to_string()))?,
        None => return Err(RecordError::Rerun("the layout has no root".into())),
    };
    // The root must be a container.
    let root_id = if root.starts_with("view/") {
        let id = uuid_text(ids.next());
        stream.log(
            format!("container/{id}"),
            &ContainerBlueprint::new(ContainerKind::Tabs)
                .with_contents([IncludedContent(root.as_str().into())]),
        )?;
        rerun::external::uuid::Uuid::parse_str(&id)
            .map_err(|e| RecordError::Rerun(e.to_string()))?
    } else {
        root_id
    };
    stream.log(
        "viewport",
        &ViewportBlueprint::new()
            .with_root_container(RootContainer(root_id.into()))
            .with_auto_layout(false)
            .with_auto_views(false),
    )?;
    stream.log(
        "blueprint_panel",
        &PanelBlueprint::new().with_state(PanelState::Collapsed),
    )?;
    stream.log(
        "selection_panel",
        &PanelBlueprint::new().with_state(PanelState::Collapsed),
    )?;
    let time_panel = match &layout.timeline {
        Some(timeline) => TimePanelBlueprint::new()
            .with_state(PanelState::Collapsed)
            .with_timeline(TimelineName(timeline.as_str().into()))
            .with_play_state(if live {
                PlayState::Following
            } else {
                PlayState::Paused
            }),
        None => TimePanelBlueprint::new().with_state(PanelState::Hidden),
    };
    stream.log("time_panel", &time_panel)?;
    stream
        .flush_blocking()
        .map_err(|e| RecordError::Rerun(e.to_string()))?;
    let messages = storage.take();
    let blueprint_id = messages
        .first()
        .map(|m| m.store_id().clone())
        .ok_or_else(|| RecordError::Rerun("an empty blueprint".into()))?;
    recording.send_blueprint(
        messages,
        rerun::external::re_log_types::BlueprintActivationCommand {
            blueprint_id,
            make_active: true,
            make_default: true,
        },
    );
    Ok(())
}
