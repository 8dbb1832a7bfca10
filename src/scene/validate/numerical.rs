//! The `[numerical]` table: the discretisation of the numerical method.

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
}
