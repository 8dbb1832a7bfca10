//! The command line: argument types ([`args`]), one module per subcommand, and the console
//! helpers they share ([`console`]). Uses the library's study, report, figure, record and
//! regression layers; nothing in the library uses it.

pub mod args;
mod check;
mod compare;
pub mod console;
mod npy;
mod probe;
mod record;
mod render;
mod surface;
mod thermal;
mod wear;

use std::path::{Path, PathBuf};

use anyhow::{bail, Context, Result};

use args::Command;
use console::print_out;
use record::{record_all, Target};
use render::{render_all, RenderOptions};
use stressfield::study::commands::HertzStudy;

/// Runs one subcommand.
pub fn run(command: Command) -> Result<()> {
    match command {
        Command::Render(args) => {
            let named = !args.scenes.is_empty();
            let scenes = scene_paths(args.scenes, &args.scenes_dir)?;
            if args.rrd.is_some() && scenes.len() != 1 {
                bail!("--rrd FILE records one scene, got {}\nhint: name one scene, or use `stressfield record` for several (one out/<scene>.rrd each)", scenes.len());
            }
            let compare =
                compare::CompareOptions::from_args(&args.compare, args.save_field, &args.out_dir)?;
            let options = RenderOptions {
                svg: args.svg,
                save_field: args.save_field,
                compare: compare.as_ref(),
                rrd: args.rrd.as_deref(),
                named,
            };
            render_all(&scenes, &args.out_dir, &options)
        }
        Command::Record {
            mut scenes,
            output,
            spawn,
            connect,
            out_dir,
            scenes_dir,
        } => {
            // `--connect SCENE.toml`: the flag's value was a scene, not an address.
            let connect = match connect {
                Some(url) if !url.contains("://") => {
                    scenes.insert(0, PathBuf::from(url));
                    Some(args::DEFAULT_VIEWER_URL.to_string())
                }
                other => other,
            };
            let scenes = scene_paths(scenes, &scenes_dir)?;
            let stdout = output.as_deref() == Some(Path::new("-"));
            if output.is_some() && scenes.len() != 1 {
                bail!("-o {} records one scene, got {}\nhint: name one scene, or leave out -o to write <out-dir>/<scene>.rrd for each", if stdout { "-" } else { "FILE.rrd" }, scenes.len());
            }
            let target = match (output, spawn, connect) {
                (Some(_), _, _) if stdout => Target::Stdout,
                (Some(path), _, _) => Target::File(path),
                (None, true, _) => Target::Spawn,
                (None, false, Some(url)) => Target::Connect(url),
                (None, false, None) => Target::OutDir(out_dir),
            };
            record_all(&scenes, &target)
        }
        Command::Hertz {
            scene: scene_path,
            json,
        } => {
            let scene = stressfield::study::load_scene(&scene_path)?;
            // One study for every kind of scene, the Python package's too (issue 50).
            let mut bars = console::StudyBars::new(&scene);
            let study = stressfield::study::commands::hertz(&scene, &mut |p| bars.show(p));
            let iterations = match &study {
                Ok(HertzStudy::Rough(contact)) => Some(contact.solution.iterations),
                _ => None,
            };
            bars.finish(iterations);
            let study = study?;
            if json {
                let text = stressfield::report::commands::hertz_json(&scene, &study);
                return print_out(&format!("{text}\n"));
            }
            print_out(&match &study {
                HertzStudy::Coated(coated) => {
                    stressfield::report::coated::CoatedReport::new(coated).text(&scene, coated)
                }
                HertzStudy::Rough(contact) => surface::contact_text(&scene, contact),
                HertzStudy::Surface(characterisation) => {
                    surface::surface_scene_text(&scene, characterisation)
                }
                HertzStudy::Closed { maxima, heating } => {
                    let mut text = stressfield::report::hertz(&scene, maxima);
                    if let Some(heating) = heating {
                        let report = stressfield::report::commands::heating_report(heating);
                        text.push_str(&report.text(heating.study()));
                    }
                    text
                }
            })
        }
        Command::Check { scenes } => check::check(&scenes),
        Command::Sweep { scene, json, csv } => {
            let scene = stressfield::study::load_scene(&scene)?;
            let bar =
                console::progress_bar(scene.sweep.as_ref().map_or(0, |s| s.values.len()) as u64);
            let table = stressfield::report::sweep::sweep_table(&scene, &mut |done, _| {
                bar.set_position(done as u64)
            });
            bar.finish_and_clear();
            let table = table.with_context(|| format!("scene {}", scene.name))?;
            print_out(&if json {
                format!("{}\n", table.json())
            } else if csv {
                table.csv()
            } else {
                table.text()
            })
        }
        Command::Probe(args) => probe::probe_command(&args),
        Command::Contact {
            scene,
            json,
            pressure,
        } => surface::contact(&scene, json, pressure.as_deref()),
        Command::Surface(args) => surface::surface(&args),
        Command::Thermal {
            scene,
            json,
            temperature,
            figure,
        } => thermal::thermal(&scene, json, temperature.as_deref(), figure.as_deref()),
        Command::Wear {
            scene,
            json,
            heights_out,
        } => wear::wear(&scene, json, heights_out.as_deref()),
    }
}

/// The scenes named, or every `*.toml` in `scenes_dir` in name order.
fn scene_paths(named: Vec<PathBuf>, scenes_dir: &Path) -> Result<Vec<PathBuf>> {
    if !named.is_empty() {
        return Ok(named);
    }
    let entries = std::fs::read_dir(scenes_dir).with_context(|| {
        format!("cannot list scenes in {}\nhint: run from the repository root, or pass scene files or --scenes-dir", scenes_dir.display())
    })?;
    let mut paths: Vec<PathBuf> = entries
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|e| e == "toml"))
        .collect();
    paths.sort();
    if paths.is_empty() {
        bail!("no *.toml scenes in {}", scenes_dir.display());
    }
    Ok(paths)
}
