//! The JSON objects of the reporting commands from their studies
//! ([`crate::study::commands`]): `hertz --json` of every kind of scene, `contact --json`,
//! `thermal --json`. The command line prints them; the Python package parses them, so that
//! every number it returns is the command line's to the last digit.

use crate::scene::Scene;
use crate::study::commands::{ContactStudy, Heating, HertzStudy};

use super::coated::CoatedReport;
use super::hertz::HertzReport;
use super::rough::ContactReport;
use super::surface::SurfaceReport;
use super::thermal::ThermalReport;

/// The heating's report: at the contact, or along the gears' path of contact.
pub fn heating_report(heating: &Heating) -> ThermalReport {
    match heating {
        Heating::Contact(study) => ThermalReport::new(study),
        Heating::Gears(gear) => ThermalReport::for_gears(gear),
    }
}

/// `contact SCENE --json`: the contact's keys, then the heating's as `thermal`.
pub fn contact_json(scene: &Scene, study: &ContactStudy) -> String {
    let thermal = study.heating.as_ref().map(ThermalReport::new);
    ContactReport::new(scene, &study.solution, &study.findings).json_with(thermal.as_ref())
}

/// `hertz SCENE --json` (a coated scene's keys with `coating`; a rough scene's those of
/// `contact --json`; a surface scene's those of `surface --json`).
pub fn hertz_json(scene: &Scene, study: &HertzStudy) -> String {
    match study {
        HertzStudy::Coated(coated) => {
            serde_json::to_string_pretty(&CoatedReport::new(coated).json_fields())
                .unwrap_or_else(|e| format!("{{\"error\": \"{e}\"}}"))
        }
        HertzStudy::Rough(contact) => contact_json(scene, contact),
        HertzStudy::Surface(characterisation) => {
            let rough = scene.contact.rough;
            SurfaceReport::new(
                characterisation,
                rough.and_then(|r| r.e_star_pa),
                rough.and_then(|r| r.hardness_pa),
            )
            .json()
        }
        HertzStudy::Closed { maxima, heating } => {
            let thermal = heating.as_ref().map(heating_report);
            HertzReport::new(scene, maxima).json(thermal.as_ref())
        }
    }
}
