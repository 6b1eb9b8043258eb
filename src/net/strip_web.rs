//! A 3-web gridshell as built: the web at the levels its strips were built on, and its nodes
//! (paper Sec. 4.2 and 5.1).

use super::nodes::{web_nodes, Node};
use super::strip_net::NODE_TOLERANCE_EDGES;
use super::web::{extract_web, Web, WebLevels};
use crate::field::{validate_field, FieldError};
use crate::mesh::TriMesh;
use crate::strips::StripPattern;

/// The web of a 3-web's fields and the nodes of its strips.
#[derive(Clone, Debug, PartialEq)]
pub struct StripWeb {
    pub web: Web,
    pub nodes: Vec<Node>,
}

/// The web of `fields[0]` and `fields[1]` at `levels` ([`super::web_levels`]) and the nodes
/// where the strips `patterns[k]` (built on `fields[k]`'s level curves at `levels.levels[k]`)
/// cross ([`web_nodes`], within [`NODE_TOLERANCE_EDGES`] mean edge lengths).
///
/// Errors: a field of the wrong length, with a non-finite or out-of-range value (naming the
/// vertex), or constant.
pub fn strip_web(mesh: &TriMesh, fields: [&[f64]; 3], levels: WebLevels, patterns: [&StripPattern; 3]) -> Result<StripWeb, FieldError> {
    for field in fields {
        validate_field(mesh, field)?;
    }
    let web = extract_web(mesh, fields[0], fields[1], levels);
    let nodes = web_nodes(&web, patterns, NODE_TOLERANCE_EDGES * mesh.mean_edge_length());
    Ok(StripWeb { web, nodes })
}
