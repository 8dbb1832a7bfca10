//! The grid planes of a scene's panels, in units of a, each in its own section plane: the
//! figure's ranges in that plane at its resolution, or, for a numerical point-contact panel,
//! the traction grid's cell centres (so that whole layers come from one DC-FFT each).

use crate::field::{Axis, Plane, Section};
use crate::scene::{ContactKind, Method, Numerical, PanelSpec, Scene, SectionKind};

/// The grid of a panel, in units of a. A numerical (or difference) panel of a point contact
/// is sampled at the cell centres of the traction grid within the figure's range (and its
/// depths at the cell spacing), so that whole layers come from one DC-FFT each; an xz or
/// yz section then lies on the nearest row or column of centres.
pub fn plane(scene: &Scene, panel: &PanelSpec) -> Plane {
    let numerical = panel.method != Method::ClosedForm || !scene.contact.has_closed_form();
    if scene.contact.kind != ContactKind::Line && numerical {
        return grid_plane(scene, panel);
    }
    let unit_over_a = scene.length_unit_over_a();
    let ((u0, u1), (v0, v1)) = scene.figure.ranges(panel.section);
    let nu = scene.figure.resolution;
    let nv = grid_rows(nu, u1 - u0, v1 - v0);
    let u = Axis::new(u0 * unit_over_a, u1 * unit_over_a, nu);
    let v = Axis::new(v0 * unit_over_a, v1 * unit_over_a, nv);
    let at = panel.at * unit_over_a;
    let section = match panel.section {
        SectionKind::Xz => Section::Xz { y: at },
        SectionKind::Yz => Section::Yz { x: at },
        SectionKind::Xy => Section::Xy { z: at },
    };
    Plane { section, u, v }
}

/// The plane of a numerical point-contact panel on the traction grid's cell centres.
fn grid_plane(scene: &Scene, panel: &PanelSpec) -> Plane {
    let unit_over_a = scene.length_unit_over_a();
    let (x_axis, y_axis) = match &scene.tractions {
        // The user's grid as it is.
        Some(grid) => {
            let ([x0, y0], [dx, dy], [ny, nx]) = (grid.origin(), grid.cell(), grid.shape());
            (
                GridAxis {
                    origin: x0,
                    cell: dx,
                    cells: nx,
                },
                GridAxis {
                    origin: y0,
                    cell: dy,
                    cells: ny,
                },
            )
        }
        // The Hertz grid covers `extent` semi-axes each way: [-e, e] x [-e b/a, e b/a].
        None => {
            let Numerical {
                cells,
                extent_over_a: extent,
            } = scene.numerical;
            let stretch = if scene.contact.kind == ContactKind::Elliptical {
                scene.contact.aspect
            } else {
                1.0
            };
            (
                GridAxis::centred(extent, cells),
                GridAxis::centred(extent * stretch, cells),
            )
        }
    };
    // Centres within the figure range [lo, hi] (figure units; at least one).
    let centres = |axis: &GridAxis, (lo, hi): (f64, f64)| {
        let (first, last) = axis.within(lo * unit_over_a, hi * unit_over_a);
        Axis::new(axis.centre(first), axis.centre(last), last - first + 1)
    };
    // Depths at the smaller cell side: square map cells in an xz section of a sphere, and
    // rows as fine as the x cells across a long ellipse (whose y cells are b/a times
    // longer).
    let dz = x_axis.cell.min(y_axis.cell);
    let depths = |(lo, hi): (f64, f64), h: f64| {
        let (lo, hi) = (lo * unit_over_a, hi * unit_over_a);
        let count = ((hi - lo) / h + 1e-9).floor() as usize + 1;
        Axis::new(lo, lo + (count - 1) as f64 * h, count.max(1))
    };
    let at = panel.at * unit_over_a;
    let (horizontal, vertical) = scene.figure.ranges(panel.section);
    let (section, u, v) = match panel.section {
        SectionKind::Xz => (
            Section::Xz {
                y: y_axis.nearest_centre(at),
            },
            centres(&x_axis, horizontal),
            depths(vertical, dz),
        ),
        SectionKind::Yz => (
            Section::Yz {
                x: x_axis.nearest_centre(at),
            },
            centres(&y_axis, horizontal),
            depths(vertical, dz),
        ),
        SectionKind::Xy => (
            Section::Xy { z: at },
            centres(&x_axis, horizontal),
            centres(&y_axis, vertical),
        ),
    };
    Plane { section, u, v }
}

/// One axis of a numerical traction grid: `cells` cells over `[-extent, extent]` (units of a).
pub(crate) struct GridAxis {
    /// Edge of the first cell.
    origin: f64,
    cell: f64,
    cells: usize,
}

impl GridAxis {
    /// `cells` cells over `[-extent, extent]`.
    fn centred(extent: f64, cells: usize) -> Self {
        Self {
            origin: -extent,
            cell: 2.0 * extent / cells as f64,
            cells,
        }
    }

    fn centre(&self, index: usize) -> f64 {
        self.origin + (index as f64 + 0.5) * self.cell
    }

    /// Index of the first and last cell centre within `[lo, hi]` (at least one).
    fn within(&self, lo: f64, hi: f64) -> (usize, usize) {
        let last_cell = (self.cells - 1) as f64;
        let first = ((lo - self.origin) / self.cell - 0.5 - 1e-9)
            .ceil()
            .clamp(0.0, last_cell) as usize;
        let last = ((hi - self.origin) / self.cell - 0.5 + 1e-9)
            .floor()
            .clamp(first as f64, last_cell) as usize;
        (first, last)
    }

    fn nearest_centre(&self, u: f64) -> f64 {
        let index = ((u - self.origin) / self.cell - 0.5)
            .round()
            .clamp(0.0, (self.cells - 1) as f64);
        self.centre(index as usize)
    }
}

/// Rows of a grid with square cells: `nx` samples over `width`, as many as fit over `height`.
pub fn grid_rows(nx: usize, width: f64, height: f64) -> usize {
    let rows = (height / width * (nx - 1) as f64).round() as usize + 1;
    rows.max(2)
}
