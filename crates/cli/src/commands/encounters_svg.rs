//! `polyguard encounters --svg FILE`: the picture of one mover and every area it meets,
//! or of one area and every mover that meets it (docs/moving-features.md); the drawing
//! is the earth crate's (`picture::mover_svg`, `picture::area_svg`).

use polyguard_earth::moving::broad::{encounters_of, Areas};
use polyguard_earth::moving::encounter::{Encounter, Options};
use polyguard_earth::moving::model::{Area, Trajectory};
use polyguard_earth::picture::{self, Met};
use rayon::prelude::*;
use std::path::Path;

/// What `--svg`, `--svg-mover` and `--svg-area` ask for.
#[derive(Clone, Copy, Debug, Default)]
pub struct Ask<'a> {
    /// Where to write the picture (`None`: no picture).
    pub file: Option<&'a Path>,
    /// The mover to draw, by id or callsign.
    pub mover: Option<&'a str>,
    /// The area to draw, by id.
    pub area: Option<&'a str>,
}

/// What the picture shows: an index into the movers or the areas read.
#[derive(Clone, Copy, Debug)]
pub enum Focus {
    /// The mover of this index (by `--svg-mover`).
    Mover(usize),
    /// The area of this index (by `--svg-area`).
    Area(usize),
}

/// How many ids an error about an unknown one lists.
const IDS_LISTED: usize = 5;

/// `what` ids as a short list: the first few, and how many there are.
fn some_ids<'a>(ids: impl ExactSizeIterator<Item = &'a str>) -> String {
    let n = ids.len();
    let first: Vec<&str> = ids.take(IDS_LISTED).collect();
    if n > IDS_LISTED {
        format!("{}, … ({n} in all)", first.join(", "))
    } else {
        first.join(", ")
    }
}

/// The focus `a` names: `--svg-mover ID` (an id, or else a callsign) or
/// `--svg-area ID` (`None`: neither); or a message naming a few ids that exist.
pub fn focus(a: Ask, movers: &[Trajectory], areas: &[Area]) -> Result<Option<Focus>, String> {
    if let Some(id) = a.mover {
        let found = movers.iter().position(|t| t.id == id).or_else(|| {
            movers
                .iter()
                .position(|t| t.callsign.as_deref() == Some(id))
        });
        return match found {
            Some(t) => Ok(Some(Focus::Mover(t))),
            None => Err(format!(
                "--svg-mover {id}: no mover has this id or callsign; movers are {}",
                some_ids(movers.iter().map(|t| t.id.as_str()))
            )),
        };
    }
    if let Some(id) = a.area {
        return match areas.iter().position(|a| a.id == id) {
            Some(a) => Ok(Some(Focus::Area(a))),
            None => Err(format!(
                "--svg-area {id}: no area has this id; areas are {}",
                some_ids(areas.iter().map(|a| a.id.as_str()))
            )),
        };
    }
    Ok(None)
}

/// With `--svg FILE`: the picture `a` asks for, written to FILE (movers and
/// areas as read, `areas` as laid out, `opts` as answered); or a message.
pub fn write(
    a: Ask,
    movers: &[Trajectory],
    inputs: &[Area],
    areas: &Areas,
    opts: &Options,
) -> Result<(), String> {
    let Some(p) = a.file else {
        return Ok(());
    };
    let svg = draw(focus(a, movers, inputs)?, movers, inputs, areas, opts)?;
    std::fs::write(p, svg).map_err(|e| format!("{}: {e}", p.display()))
}

/// The picture's SVG for `focus` (`None`: the first mover, in input order, that meets an
/// area), or a message when there is nothing to draw.
fn draw(
    focus: Option<Focus>,
    movers: &[Trajectory],
    inputs: &[Area],
    areas: &Areas,
    opts: &Options,
) -> Result<String, String> {
    let by_id = |id: &str| inputs.iter().find(|a| a.id == id);
    let mover = |t: &Trajectory, list: &[Encounter]| {
        let met: Vec<Met<Area>> = list
            .iter()
            .filter_map(|e| {
                by_id(&e.area).map(|a| Met {
                    other: a,
                    encounter: e,
                })
            })
            .collect();
        picture::mover_svg(t, &met, opts)
    };
    match focus {
        Some(Focus::Mover(i)) => {
            let t = &movers[i];
            let list = encounters_of(t, areas, opts).map_err(|e| format!("mover {}: {e}", t.id))?;
            Ok(mover(t, &list))
        }
        None => {
            for t in movers {
                if let Ok(list) = encounters_of(t, areas, opts) {
                    if !list.is_empty() {
                        return Ok(mover(t, &list));
                    }
                }
            }
            Err("no mover meets an area: nothing to draw (name one with --svg-mover)".into())
        }
        Some(Focus::Area(i)) => {
            let a = &inputs[i];
            let (one, errors) = Areas::new(std::slice::from_ref(a), opts.geodesy);
            if let Some(e) = errors.first() {
                return Err(format!("area {e}"));
            }
            let lists: Vec<(usize, Vec<Encounter>)> = movers
                .par_iter()
                .enumerate()
                .filter_map(|(i, t)| encounters_of(t, &one, opts).ok().map(|l| (i, l)))
                .collect();
            let met: Vec<Met<Trajectory>> = lists
                .iter()
                .flat_map(|(i, l)| {
                    l.iter().map(|e| Met {
                        other: &movers[*i],
                        encounter: e,
                    })
                })
                .collect();
            Ok(picture::area_svg(a, &met, opts))
        }
    }
}
