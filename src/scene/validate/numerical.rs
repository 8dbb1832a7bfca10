//! The `[numerical]` table: the discretisation of the numerical method, and how far its panels reach.

#[allow(clippy::wildcard_imports)]
use super::*;

impl Validator<'_> {
    pub(super) fn numerical(
        &self,
        raw: Option<&raw::RawNumerical>,
        contact: &Contact,
    ) -> Result<Numerical, SceneError> {
        let empty = raw::RawNumerical::default();
        let raw = raw.unwrap_or(&empty);
        let (default_cells, range, hint) = match contact.kind {
            ContactKind::Line => (
                400,
                8..=100_000,
                "strips across the contact: 400 is accurate to about 1e-4 p0 at z >= 0.1a",
            ),
            ContactKind::Point
            | ContactKind::Elliptical
            | ContactKind::Tractions
            | ContactKind::Rough
            | ContactKind::Surface => (
                255,
                8..=2048,
                "cells per side of the traction grid: 255 over ±2a is accurate to about 0.2 % p0",
            ),
        };
        let cells = match raw.cells {
            None => default_cells,
            Some(n) if range.contains(&n) => n as usize,
            Some(n) => {
                return Err(self.error(
                    "numerical.cells",
                    format!("must lie in {}..={}, got {n}", range.start(), range.end()),
                    Some(hint),
                ))
            }
        };
        // A coated line contact is solved on a grid over ±extent half-widths of the coating's
        // Hertz contact, like a coated point contact; an uncoated one spans -a..a.
        let coated = contact.coating.is_some();
        let extent_over_a = match (raw.extent, contact.kind) {
            (Some(_), ContactKind::Line) if !coated => {
                return Err(self.error(
                    "numerical.extent",
                    "a line contact's strips always span the contact -a..a",
                    Some("remove it; set the number of strips with numerical.cells"),
                ))
            }
            (None, _) => 2.0,
            (Some(e), _) if (1.0..=20.0).contains(&e) => e,
            (Some(e), _) => {
                return Err(self.error(
                    "numerical.extent",
                    format!("must lie in 1..=20 semi-axes, got {}", crate::io::text::number(e)),
                    Some("the grid must cover the contact, -a..a (and -b..b across); 2 leaves room around it"),
                ))
            }
        };
        Ok(Numerical {
            cells,
            extent_over_a,
        })
    }

    /// A numerical panel of a point, elliptical or traction-grid contact is sampled at the
    /// traction grid's cell centres, so it ends where the grid ends: a figure range (or a
    /// section's position) reaching more than one cell beyond the grid would be cut there
    /// silently. It is refused instead, naming the grid's extent and the `numerical.extent`
    /// that would cover it (the grid is `extent` semi-axes each way; a traction file's grid is
    /// its own).
    pub(super) fn numerical_ranges(
        &self,
        contact: &Contact,
        figure: &FigureSpec,
        numerical: &Numerical,
        tractions: Option<&crate::solution::dcfft::TractionGrid>,
        raw_panels: &[raw::RawPanel],
        panels: &[PanelSpec],
    ) -> Result<(), SceneError> {
        if contact.kind == ContactKind::Line {
            return Ok(());
        }
        let drawn_numerically =
            |p: &PanelSpec| p.method != Method::ClosedForm || !contact.has_closed_form();
        if !panels.iter().any(drawn_numerically) {
            return Ok(());
        }
        let a_m = contact.half_width_m();
        let unit_over_a = figure.length_unit.metres(a_m) / a_m;
        let suffix = unit_after(figure.length_unit);
        // The grid along x and y, in units of a: (lo, hi, cell).
        let (x_grid, y_grid) = match tractions {
            Some(grid) => {
                let ([x0, y0], [dx, dy], [ny, nx]) = (grid.origin(), grid.cell(), grid.shape());
                ((x0, x0 + nx as f64 * dx, dx), (y0, y0 + ny as f64 * dy, dy))
            }
            None => {
                let e = numerical.extent_over_a;
                let stretch = if contact.kind == ContactKind::Elliptical {
                    contact.aspect
                } else {
                    1.0
                };
                let cells = numerical.cells as f64;
                (
                    (-e, e, 2.0 * e / cells),
                    (-e * stretch, e * stretch, 2.0 * e * stretch / cells),
                )
            }
        };
        let grid_of = |name: &str| if name == "x" { x_grid } else { y_grid };
        let fix = |name: &str, lo: f64, hi: f64| -> String {
            let (g0, g1, _) = grid_of(name);
            let within = format!(
                "give figure.{name} within [{}, {}]{suffix}",
                crate::io::text::approx(g0 / unit_over_a),
                crate::io::text::approx(g1 / unit_over_a)
            );
            if tractions.is_some() {
                return format!("{within}: the traction file's grid ends there");
            }
            let semi = if name == "y" && contact.kind == ContactKind::Elliptical {
                contact.aspect
            } else {
                1.0
            };
            let needed = (lo.abs().max(hi.abs()) / semi).ceil();
            if needed <= 20.0 {
                format!(
                    "{within}, or raise numerical.extent to {} (and numerical.cells in proportion, to keep the cells' size)",
                    crate::io::text::number(needed)
                )
            } else {
                format!("{within} (numerical.extent reaches 20 semi-axes at most)")
            }
        };
        let outside = |name: &str, lo: f64, hi: f64| {
            let (g0, g1, cell) = grid_of(name);
            lo < g0 - cell * (1.0 + 1e-9) || hi > g1 + cell * (1.0 + 1e-9)
        };
        let grid_words = |name: &str| {
            let (g0, g1, _) = grid_of(name);
            match tractions {
                Some(_) => format!(
                    "the traction file's grid, which covers {name} = [{}, {}]{suffix}",
                    crate::io::text::approx(g0 / unit_over_a),
                    crate::io::text::approx(g1 / unit_over_a)
                ),
                None => format!(
                    "the numerical grid, which covers {name} = ±{}{suffix} (numerical.extent = {} semi-axes)",
                    crate::io::text::approx(g1 / unit_over_a),
                    crate::io::text::number(numerical.extent_over_a)
                ),
            }
        };
        // The ranges along the surface of every numerical panel's plane.
        let mut ranges = Vec::new();
        for panel in panels.iter().filter(|p| drawn_numerically(p)) {
            let (h, v, _) = panel.section.coordinates();
            let (horizontal, vertical) = figure.ranges(panel.section);
            ranges.push((h, horizontal));
            if !panel.section.vertical_is_depth() {
                ranges.push((v, vertical));
            }
        }
        for (name, (lo, hi)) in ranges {
            let (lo_a, hi_a) = (lo * unit_over_a, hi * unit_over_a);
            if outside(name, lo_a, hi_a) {
                return Err(self.error(
                    &format!("figure.{name}"),
                    format!(
                        "the range [{}, {}]{suffix} reaches beyond {}; the numerical panels would end there, cut",
                        crate::io::text::number(lo),
                        crate::io::text::number(hi),
                        grid_words(name)
                    ),
                    Some(&fix(name, lo_a, hi_a)),
                ));
            }
        }
        // A section's position along its normal (not the depth of an xy plane).
        for (i, panel) in panels.iter().enumerate() {
            let (_, _, normal) = panel.section.coordinates();
            if panel.section != SectionKind::Xy {
                let at_a = panel.at * unit_over_a;
                if drawn_numerically(panel) && outside(normal, at_a, at_a) {
                    let key = if raw_panels.get(i).is_some_and(|p| p.at.is_some()) {
                        format!("panel[{i}].at")
                    } else {
                        "figure.at".to_string()
                    };
                    return Err(self.error(
                        &key,
                        format!(
                            "the section at {normal} = {}{suffix} lies beyond {}",
                            crate::io::text::number(panel.at),
                            grid_words(normal)
                        ),
                        Some(
                            &fix(normal, at_a, at_a)
                                .replace(&format!("figure.{normal}"), "the section"),
                        ),
                    ));
                }
            }
        }
        Ok(())
    }
}
