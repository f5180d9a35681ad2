//! The library behind the `qsic` binary: reading quadrics from arguments and JSON, the
//! JSON result schema (see the README) and the batch driver.
//!
//! | module | owns |
//! |---|---|
//! | [`affine`] | the `"affine"` object of `qsic classify`: the pair in ℝ³ |
//! | [`input`] | reading a quadric from an argument or a JSON value, exactly |
//! | [`output`] | the JSON result object ([`output::classification_to_json`]) and the text report |
//! | [`reader`] | the lines of a batch input, bounded (terminators and a leading byte-order mark stripped) |
//! | [`mod@line`] | the fields of one batch line, borrowed from its text (a strict fast reader, then `serde_json`) |
//! | [`file`] | output files written whole or not at all (a temporary renamed into place) |
//! | [`contact`] | `qsic contact`: first contact of two moving quadrics and the relation of moving solid ellipsoids |
//! | [`batch`] | `--batch`: bounded, ordered, parallel JSON Lines processing, for any [`batch::Answer`] or line answer |
//! | [`motion`] | `qsic motion`: moving quadrics in, their timeline out (text, JSON, batch lines) |
//! | [`rigid`] | the JSON object form of a quadric under a rigid motion (`{"quadric", "rotate", "translate"}`) |
//! | [`motion_plot`] | `qsic motion --plot`: the timeline as an SVG picture |
//! | [`param`] | `qsic param`: the exact curve as JSON and text |
//! | [`nurbs`] | `qsic nurbs`: the real pieces as NURBS curves (JSON, STEP, text) |
//! | [`step`] | ISO 10303-21 text of NURBS curves |
//! | [`mod@sample`] | `qsic sample`: real points as JSON, CSV, OBJ |
//! | [`plot`] | `qsic plot`: the curve in a 3D view and the eigencurve, as SVG |
//! | `eigencurve` | the eigencurve panel of `qsic plot --eigencurve` |
//! | `plot_common` | the common surfaces in a plot (`A ∝ B`, a common plane): what is drawn, where the cube goes |
//! | `sections` | the drawn cube, polylines clipped to it, the surfaces' sections by planes (floats, drawing only) |
//! | [`stream`] | ordered streaming: answers in parallel, written in input order as soon as they and their predecessors are done, a bounded window of pending lines |
//! | [`svg`] | SVG helpers shared by the pictures: escaping, palette, panels |

pub mod affine;
pub mod batch;
pub mod contact;
mod eigencurve;
pub mod file;
pub mod floats;
pub mod frame;
pub mod input;
pub mod large;
pub mod line;
pub mod motion;
pub mod motion_plot;
pub mod nurbs;
pub mod output;
pub mod param;
pub mod plot;
mod plot_common;
pub mod reader;
pub mod rigid;
pub mod sample;
mod sections;
pub mod step;
pub mod stream;
pub mod svg;
