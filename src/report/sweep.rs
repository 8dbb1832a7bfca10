//! `stressfield sweep SCENE [--json | --csv]`: a `[sweep]` scene as a table, one row per step
//! with the swept value and the values its recording charts against it (issue 39).
//!
//! Columns by kind of sweep:
//! - friction, load, position (Hertz scenes): the swept value (`friction`, `load_n` or
//!   `load_n_per_m`, `position` in the figure's length unit), then per panel `k` of the figure
//!   `panel<k>_maximum`, `panel<k>_maximum_depth` (depth sections) and `panel<k>_minimum`: the
//!   extremes the figure marks, in its stress and length units (each column's unit is given),
//!   as the recording's `series/<k>/...`;
//! - a rough scene's load sweep: `load_n`, `contact_fraction`, `spots`, `max_pressure_pa`;
//! - a speed sweep (`parameter = "peclet"`): `peclet`, `sliding_speed_m_per_s`,
//!   `max_temperature_rise_k`, `mean_temperature_rise_k`, `max_x_over_a`, `body1_share`;
//! - a coating-thickness sweep (`parameter = "coating_thickness"`): `coating_thickness_m`,
//!   `max_pressure_pa`, `von_mises_max_pa`, `von_mises_max_depth_m`,
//!   `max_depth_over_thickness` (below 1: in the coating, 1: at the interface, above: in the
//!   substrate), `coating_von_mises_max_pa`, `substrate_von_mises_max_pa`,
//!   `interface_shear_max_pa` (as the recording's charts).
//!
//! A value a step does not have (an extreme the figure does not mark) is `null` in JSON and
//! empty in CSV. JSON: `{"scene", "parameter", "units": {column: unit}, "steps": [{column:
//! value, ...}, ...]}`, the columns in table order.

use std::fmt::Write as _;

use crate::contact::rough::Control;
use crate::scene::{ContactKind, Scene, SweepParameter};
use crate::study;

/// Why a scene's sweep cannot be tabulated.
#[derive(Debug, thiserror::Error)]
pub enum SweepTableError {
    #[error("the scene has no [sweep] table ({0} is not a recording scene)\nhint: `stressfield sweep` tabulates recording scenes with a [sweep] table (see docs/reference.md); `stressfield hertz SCENE --json` reports a single contact")]
    NoSweep(String),
    #[error("step {step} of the sweep: {message}")]
    Step { step: usize, message: String },
}

/// A sweep's table: named columns with their units, one row per step.
#[derive(Clone, Debug, PartialEq)]
pub struct SweepTable {
    pub scene: String,
    /// The swept parameter's key (`friction`, `load`, `position`, `peclet`).
    pub parameter: &'static str,
    /// `(name, unit)` of each column.
    pub columns: Vec<(String, String)>,
    /// One row per step, a value per column (`None`: not defined at that step).
    pub rows: Vec<Vec<Option<f64>>>,
}

fn step_error(step: usize, error: impl std::fmt::Display) -> SweepTableError {
    SweepTableError::Step {
        step: step + 1,
        message: error.to_string(),
    }
}

/// Computes every step of `scene`'s sweep as its recording does; `on_step(done, total)` after
/// each.
pub fn sweep_table(
    scene: &Scene,
    on_step: &mut dyn FnMut(usize, usize),
) -> Result<SweepTable, SweepTableError> {
    let sweep = scene
        .sweep
        .as_ref()
        .ok_or_else(|| SweepTableError::NoSweep(scene.name.clone()))?;
    let steps = sweep.values.len();
    let mut table = SweepTable {
        scene: scene.name.clone(),
        parameter: sweep.parameter.key(),
        columns: Vec::new(),
        rows: Vec::new(),
    };
    let column = |name: &str, unit: &str| (name.to_string(), unit.to_string());
    if matches!(
        scene.contact.kind,
        ContactKind::Rough | ContactKind::Surface
    ) {
        // A rough load sweep: each load solved (as record's log_load_sweep does).
        let problem =
            study::rough::problem(scene).ok_or_else(|| step_error(0, "no rough contact"))?;
        table.columns = vec![
            column("load_n", "N"),
            column("contact_fraction", "1"),
            column("spots", "1"),
            column("max_pressure_pa", "Pa"),
        ];
        for (k, &load) in sweep.values.iter().enumerate() {
            let mut step = problem.clone();
            step.control = Control::Load { newtons: load };
            let solution = crate::contact::rough::solve(&step, &mut |_, _| {})
                .map_err(|e| step_error(k, e))?;
            table.rows.push(vec![
                Some(load),
                Some(solution.contact_fraction),
                Some(solution.spots as f64),
                Some(solution.max_pressure_pa),
            ]);
            on_step(k + 1, steps);
        }
        return Ok(table);
    }
    if sweep.parameter == SweepParameter::CoatingThickness {
        let studies = study::coated::sweep(scene, on_step).map_err(|e| step_error(0, e))?;
        table.columns = vec![
            column("coating_thickness_m", "m"),
            column("max_pressure_pa", "Pa"),
            column("von_mises_max_pa", "Pa"),
            column("von_mises_max_depth_m", "m"),
            column("max_depth_over_thickness", "h"),
            column("coating_von_mises_max_pa", "Pa"),
            column("substrate_von_mises_max_pa", "Pa"),
            column("interface_shear_max_pa", "Pa"),
        ];
        for step in &studies {
            let m = &step.maxima;
            let h = step.spec.thickness_m;
            table.rows.push(vec![
                Some(h),
                Some(step.solution.max_pressure_pa()),
                Some(m.von_mises.value_pa),
                Some(m.von_mises.z_m),
                Some(m.von_mises.z_m / h),
                Some(m.coating_von_mises.value_pa),
                Some(m.substrate_von_mises.value_pa),
                Some(m.interface_shear.value_pa),
            ]);
        }
        return Ok(table);
    }
    if sweep.parameter == SweepParameter::EntrainmentSpeed {
        let steps = study::ehl::speed_sweep(
            scene,
            &sweep.values,
            study::ehl::SWEEP_COLUMNS,
            study::ehl::SWEEP_ROWS,
        )
        .map_err(|e| step_error(0, e))?;
        table.columns = vec![
            column("entrainment_speed_m_per_s", "m/s"),
            column("moes_m", "1"),
            column("moes_l", "1"),
            column("central_film_m", "m"),
            column("minimum_film_m", "m"),
            column("max_pressure_pa", "Pa"),
            column("spike_pressure_pa", "Pa"),
            column("spike_x_m", "m"),
            column("von_mises_max_pa", "Pa"),
            column("von_mises_max_depth_m", "m"),
            column("near_surface_von_mises_max_pa", "Pa"),
        ];
        for step in &steps {
            let s = &step.study.solution;
            let (b, ph) = (s.half_width_m, s.hertz_p0_pa);
            table.rows.push(vec![
                Some(step.entrainment_m_per_s),
                Some(s.moes_m),
                Some(s.moes_l),
                Some(s.central_film_m),
                Some(s.minimum_film_m),
                Some(s.max_pressure_pa),
                s.spike_pressure_pa,
                s.spike_x_m,
                Some(step.study.von_mises.value_over_p0 * ph),
                Some(step.study.von_mises.z_over_a * b),
                Some(step.near_surface_von_mises.value_over_p0 * ph),
            ]);
        }
        on_step(steps.len(), steps.len());
        return Ok(table);
    }
    if sweep.parameter == SweepParameter::Peclet {
        let speeds = study::thermal_sweep::speed_sweep(scene, &sweep.values, on_step)
            .map_err(|e| step_error(0, e))?;
        table.columns = vec![
            column("peclet", "1"),
            column("sliding_speed_m_per_s", "m/s"),
            column("max_temperature_rise_k", "K"),
            column("mean_temperature_rise_k", "K"),
            column("max_x_over_a", "a"),
            column("body1_share", "1"),
        ];
        for step in &speeds.steps {
            table.rows.push(vec![
                Some(step.peclet),
                Some(step.sliding_speed_m_per_s),
                Some(step.body1.max_temperature_rise_k),
                Some(step.body1.mean_temperature_rise_k),
                Some(step.body1.max_at_m[0] / speeds.half_width_m),
                Some(step.body1.share),
            ]);
        }
        return Ok(table);
    }
    // Friction, load or position: each step's figure, its marked extremes per panel.
    let name = match sweep.parameter {
        SweepParameter::Friction => "friction",
        SweepParameter::Load if scene.contact.kind == ContactKind::Line => "load_n_per_m",
        SweepParameter::Load => "load_n",
        _ => "position",
    };
    for k in 0..steps {
        let step_scene = study::at_step(scene, k).map_err(|e| step_error(k, e))?;
        let fields = study::panel_fields(&step_scene, &|| {}).map_err(|e| step_error(k, e))?;
        let figure = crate::figure::build(&step_scene, &fields);
        if k == 0 {
            let unit = match sweep.parameter {
                SweepParameter::Friction => "1".to_string(),
                SweepParameter::Load if name == "load_n_per_m" => "N/m".to_string(),
                SweepParameter::Load => "N".to_string(),
                // The load's centre, in the figure's horizontal unit.
                _ => figure.x_label.clone(),
            };
            table.columns.push(column(name, &unit));
            for (p, panel) in figure.panels.iter().enumerate() {
                let depth = figure.axes_of(panel).vertical_is_depth;
                let value_unit = panel
                    .scale
                    .as_ref()
                    .map_or(&figure.value_label, |s| &s.value_label)
                    .clone();
                table
                    .columns
                    .push(column(&format!("panel{p}_maximum"), &value_unit));
                if depth {
                    table.columns.push(column(
                        &format!("panel{p}_maximum_depth"),
                        figure.axes_of(panel).z_label,
                    ));
                }
                table
                    .columns
                    .push(column(&format!("panel{p}_minimum"), &value_unit));
            }
        }
        let mut row = vec![Some(sweep.values[k])];
        for panel in &figure.panels {
            let (largest, smallest) = crate::figure::extremes(panel, figure.mark);
            let largest =
                largest.or_else(|| crate::figure::extremes(panel, crate::render::Mark::Max).0);
            row.push(largest.map(|e| e.value));
            if figure.axes_of(panel).vertical_is_depth {
                row.push(largest.map(|e| e.v));
            }
            row.push(smallest.map(|e| e.value));
        }
        table.rows.push(row);
        on_step(k + 1, steps);
    }
    Ok(table)
}

impl SweepTable {
    /// One JSON object (see the module doc).
    pub fn json(&self) -> String {
        let text = |s: &str| serde_json::to_string(s).unwrap_or_else(|_| "\"\"".into());
        let number = |v: Option<f64>| match v {
            Some(v) if v.is_finite() => serde_json::to_string(&v).unwrap_or_else(|_| "null".into()),
            _ => "null".to_string(),
        };
        let mut out = String::new();
        let _ = writeln!(out, "{{\n  \"scene\": {},", text(&self.scene));
        let _ = writeln!(out, "  \"parameter\": {},", text(self.parameter));
        let units: Vec<String> = self
            .columns
            .iter()
            .map(|(name, unit)| format!("    {}: {}", text(name), text(unit)))
            .collect();
        let _ = writeln!(out, "  \"units\": {{\n{}\n  }},", units.join(",\n"));
        let rows: Vec<String> = self
            .rows
            .iter()
            .map(|row| {
                let cells: Vec<String> = self
                    .columns
                    .iter()
                    .zip(row)
                    .map(|((name, _), v)| format!("{}: {}", text(name), number(*v)))
                    .collect();
                format!("    {{{}}}", cells.join(", "))
            })
            .collect();
        let _ = write!(out, "  \"steps\": [\n{}\n  ]\n}}", rows.join(",\n"));
        out
    }

    /// CSV: a header of the column names, then one line per step (shortest exact numbers).
    pub fn csv(&self) -> String {
        let mut out = self
            .columns
            .iter()
            .map(|(name, _)| name.as_str())
            .collect::<Vec<_>>()
            .join(",");
        out.push('\n');
        for row in &self.rows {
            let cells: Vec<String> = row
                .iter()
                .map(|v| {
                    v.filter(|v| v.is_finite())
                        .map_or(String::new(), |v| format!("{v:?}"))
                })
                .collect();
            out.push_str(&cells.join(","));
            out.push('\n');
        }
        out
    }

    /// The readable table: a line of units under the header, values to five significant
    /// digits.
    pub fn text(&self) -> String {
        let header: Vec<String> = self.columns.iter().map(|(n, _)| n.clone()).collect();
        let units: Vec<String> = self.columns.iter().map(|(_, u)| format!("[{u}]")).collect();
        let body: Vec<Vec<String>> = self
            .rows
            .iter()
            .map(|row| {
                row.iter()
                    .map(|v| v.map_or("-".to_string(), |v| format!("{v:.5}")))
                    .collect()
            })
            .collect();
        let widths: Vec<usize> = (0..header.len())
            .map(|c| {
                body.iter()
                    .map(|r| r[c].chars().count())
                    .chain([header[c].chars().count(), units[c].chars().count()])
                    .max()
                    .unwrap_or(0)
            })
            .collect();
        let line = |cells: &[String]| {
            cells
                .iter()
                .zip(&widths)
                .map(|(c, w)| format!("{c:>w$}"))
                .collect::<Vec<_>>()
                .join("  ")
        };
        let mut out = format!("scene {}: sweep of {}\n", self.scene, self.parameter);
        out.push_str(&line(&header));
        out.push('\n');
        out.push_str(&line(&units));
        out.push('\n');
        for row in &body {
            out.push_str(&line(row));
            out.push('\n');
        }
        out
    }
}
