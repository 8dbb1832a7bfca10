//! The `[tractions]` table: a CSV grid of surface tractions.

use super::figure::MIN_SPAN_OVER_A;
#[allow(clippy::wildcard_imports)]
use super::*;

/// The largest traction, in units of the figures' p0: far beyond any contact (a traction
/// file in MPa with p0 = 1 Pa stays below it), and far from where sums of millions of cells
/// could overflow.
const MAX_TRACTION_OVER_P0: f64 = 1e12;

impl Validator<'_> {
    /// The `[tractions]` table of a `kind = "tractions"` scene: the CSV grid read and converted
    /// to units of a and p0 (the contact's `a` and `p0`, or the file's own units `a`, `p0`).
    pub(super) fn tractions(
        &self,
        raw: &RawScene,
        contact: &Contact,
    ) -> Result<Option<std::sync::Arc<TractionGrid>>, SceneError> {
        let table = match (&raw.tractions, contact.kind) {
            (None, ContactKind::Tractions) => {
                return Err(self.error(
                    "tractions",
                    "a traction scene needs its [tractions] table",
                    Some("add [tractions] with file = \"my_tractions.csv\" (rows x,y,p[,qx][,qy]), length_unit and stress_unit"),
                ))
            }
            (None, _) => return Ok(None),
            (Some(_), kind) if kind != ContactKind::Tractions => {
                return Err(self.error(
                    "tractions",
                    "tractions from a file need kind = \"tractions\"",
                    Some("set contact.kind = \"tractions\", or remove [tractions]"),
                ))
            }
            (Some(table), _) => table,
        };
        if raw.numerical.is_some() {
            return Err(self.error(
                "numerical",
                "the grid of a traction scene is the file's",
                Some("remove [numerical]"),
            ));
        }
        let length_unit = match table.length_unit.as_deref() {
            None => LengthUnit::HalfWidth,
            Some(key) => LengthUnit::from_key(key).ok_or_else(|| {
                self.error(
                    "tractions.length_unit",
                    format!("unknown length unit `{key}`"),
                    Some("use \"a\", \"mm\", \"um\" or \"m\""),
                )
            })?,
        };
        let stress_unit = match table.stress_unit.as_deref() {
            None => StressUnit::PeakPressure,
            Some(key) => StressUnit::from_key(key).ok_or_else(|| {
                self.error(
                    "tractions.stress_unit",
                    format!("unknown stress unit `{key}`"),
                    Some("use \"p0\", \"MPa\", \"GPa\" or \"Pa\""),
                )
            })?,
        };
        let dimensional_units =
            length_unit != LengthUnit::HalfWidth || stress_unit != StressUnit::PeakPressure;
        if dimensional_units && contact.scale.is_none() {
            return Err(self.error(
                "tractions.length_unit",
                "tractions in physical units need the reference length a and pressure p0 of the figures",
                Some("add contact.a (e.g. \"0.1 mm\") and contact.p0 (e.g. \"1 GPa\"), or give the file in units of a and p0"),
            ));
        }
        let path = std::path::Path::new(self.file)
            .parent()
            .unwrap_or_else(|| std::path::Path::new(""))
            .join(&table.file);
        let text = crate::io::input::read_to_string(&path, crate::io::input::TRACTION_FILE_LIMIT)
            .map_err(|e| {
            self.error(
                "tractions.file",
                format!("cannot read {}: {e}", path.display()),
                Some("the path is relative to the scene file"),
            )
        })?;
        let read = traction_csv::read(&text)
            .map_err(|m| self.error("tractions.file", format!("{}: {m}", path.display()), None))?;
        let a_m = contact.half_width_m();
        let p0_pa = contact.p0_pa();
        let length = length_unit.metres(a_m) / a_m;
        let stress = stress_unit.pascals(p0_pa) / p0_pa;
        // In units of p0 every traction must stay a number a sum of many cells can carry.
        let largest = read.largest;
        let over_p0 = largest.magnitude * stress;
        if over_p0.is_nan() || over_p0 > MAX_TRACTION_OVER_P0 {
            return Err(self.error(
                "tractions.file",
                format!(
                    "{}: line {}: {} = {} {} is {} p0 (p0 = {} Pa), more than the {} p0 allowed",
                    path.display(),
                    largest.line,
                    largest.column,
                    crate::io::text::number(largest.magnitude),
                    table.stress_unit.as_deref().unwrap_or("p0"),
                    crate::io::text::number(over_p0),
                    crate::io::text::number(p0_pa),
                    crate::io::text::compact(MAX_TRACTION_OVER_P0)
                ),
                Some("check the value and tractions.stress_unit; contact.p0 should be near the size of the tractions"),
            ));
        }
        let cell = [read.cell[0] * length, read.cell[1] * length];
        let origin = [
            read.first_centre[0] * length - 0.5 * cell[0],
            read.first_centre[1] * length - 0.5 * cell[1],
        ];
        // The nodes (cell centres) within reach of the figures' origin.
        let shape = [read.pressure.ncols(), read.pressure.nrows()];
        for axis in 0..2 {
            let key = "tractions.file";
            let name = ["x", "y"][axis];
            let suffix = unit_after(length_unit);
            let first = read.first_centre[axis];
            let last = first + (shape[axis] - 1) as f64 * read.cell[axis];
            for node in [first, last] {
                let written = format!("{name} = {}{suffix}", crate::io::text::number(node));
                self.within_reach(key, node * length, &written)?;
            }
            if cell[axis].is_nan() || cell[axis] < MIN_SPAN_OVER_A {
                return Err(self.error(
                    key,
                    format!(
                        "{}: the {name} spacing {} is {} a, less than the {} a a figure can resolve",
                        path.display(),
                        crate::io::text::number(read.cell[axis]),
                        crate::io::text::number(cell[axis]),
                        crate::io::text::compact(MIN_SPAN_OVER_A)
                    ),
                    Some("check tractions.length_unit"),
                ));
            }
        }
        let scaled = |a: ndarray::Array2<f64>| a.mapv(|v| v * stress);
        let grid = TractionGrid::new(
            origin,
            cell,
            Some(scaled(read.pressure)),
            read.shear_x.map(scaled),
            read.shear_y.map(scaled),
        )
        .map_err(|e| self.error("tractions.file", e.to_string(), None))?;
        Ok(Some(std::sync::Arc::new(grid)))
    }
}
