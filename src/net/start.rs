//! The default start of a net (Sec. 4.1): each family from the single-family start search, the
//! second one among the candidates that cross the first family's level sets.

use super::params::NetParams;
use crate::field::{FieldParams, FieldSolver};
use crate::initialisation::{SearchError, SearchOptions, StartSearch};
use crate::mesh::TriMesh;

/// Smallest area-weighted mean angle (degrees) at which the second family's start must cross the
/// first's: well above the default minimum angle, so that the solve does not have to turn one
/// family across the other.
pub const START_CROSSING_DEGREES: f64 = 45.0;

/// One start field per family of `params` on `mesh` (for a 3-web: per family of the first two,
/// the third starts as `−F − H`, see [`super::NetSolver::new`]): the first family's winner of the
/// start search, then the second family's winner among the candidates crossing it at
/// [`START_CROSSING_DEGREES`] or more on average. Each field is the one its short solve reached.
pub fn net_start(mesh: &TriMesh, params: &NetParams, options: &SearchOptions) -> Result<Vec<Vec<f64>>, SearchError> {
    params.validate().map_err(SearchError::Field)?;
    let mut fields: Vec<Vec<f64>> = Vec::with_capacity(params.families.len());
    for &family in &params.families[..2] {
        let mut search = StartSearch::new(mesh, FieldParams { family, ..params.field.clone() }, options.clone()).map_err(SearchError::Field)?;
        if let Some(first) = fields.first() {
            search = search.crossing(first, START_CROSSING_DEGREES).map_err(SearchError::Field)?;
        }
        search.run().map_err(SearchError::Field)?;
        let solver: FieldSolver = search.into_solver()?;
        fields.push(solver.field());
    }
    Ok(fields)
}
