//! One chart as the report holds it, and the folder charts go in.

/// The folder of the report that holds the charts.
pub const FOLDER: &str = "plots";

/// One chart: its file name (in [`FOLDER`]), a title, a one-line caption
/// saying what it aggregates, and the SVG document.
#[derive(Clone, Debug)]
pub struct Plot {
    pub file: String,
    pub title: String,
    pub caption: String,
    pub svg: String,
}
