//! The `[tractions]` table: a CSV grid of surface tractions.

#[allow(clippy::wildcard_imports)]
use super::*;

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
        let text = std::fs::read_to_string(&path).map_err(|e| {
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
        let cell = [read.cell[0] * length, read.cell[1] * length];
        let origin = [
            read.first_centre[0] * length - 0.5 * cell[0],
            read.first_centre[1] * length - 0.5 * cell[1],
        ];
        let scaled = |a: ndarray::Array2<f64>| a.mapv(|v| v * stress);
        let grid = TractionGrid::new(
            origin,
            cell,
            Some(scaled(read.pressure)),
            read.shear_x.map(scaled),
            read.shear_y.map(scaled),
        )
        .map_err(|e| self.error("tractions.file", e.to_string(), None))?;
        let [ny, nx] = grid.shape();
        if nx > 4096 || ny > 4096 {
            return Err(self.error(
                "tractions.file",
                format!("a {nx} x {ny} grid is larger than 4096 x 4096"),
                Some("resample the tractions more coarsely"),
            ));
        }
        Ok(Some(std::sync::Arc::new(grid)))
    }
}
