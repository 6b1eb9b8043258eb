//! `LmlSearch`: the default start search (which initial field leads to the asked family when
//! the caller has no guides or strokes), stepped one candidate at a time like an SQLite
//! statement, then turned into an `LmlField` that continues from the best candidate.

use super::failure::Failure;
use super::field::LmlField;
use super::field_params::LmlFieldParams;
use super::guard::guarded;
use super::mesh::LmlMesh;
use super::raw::{copy_out, handle, handle_mut, release, Out};
use super::status::LmlStatus;
use crate::initialisation::{Candidate, SearchError, SearchOptions, StartKind, StartSearch};

/// A start search (opaque). Create it with `lml_search_new`, step it with `lml_search_step`
/// until it returns `LML_STATUS_OK`, read its candidates, take the field with
/// `lml_search_field`, release it with `lml_search_free`.
pub struct LmlSearch {
    /// `None` once `lml_search_field` took the search's solver.
    search: Option<StartSearch>,
    /// The candidates as they were when the field was taken.
    finished: Vec<Candidate>,
    /// The winner when the field was taken.
    finished_winner: Option<usize>,
    /// Vertex count of the coarsening the candidates are probed on, 0 for the mesh itself.
    proxy_vertices: usize,
}

impl LmlSearch {
    fn candidates(&self) -> &[Candidate] {
        self.search.as_ref().map_or(&self.finished, StartSearch::candidates)
    }

    fn winner(&self) -> Option<usize> {
        self.search.as_ref().map_or(self.finished_winner, StartSearch::winner)
    }
}

/// `LmlCandidate::kind`: the height along `direction` (negated if `negated` is 1).
pub const LML_START_HEIGHT: u32 = 0;
/// `LmlCandidate::kind`: guides traced from boundary side `side` at `start_angle_degrees`.
pub const LML_START_GUIDES: u32 = 1;

/// One candidate start of a search and how its short solve ended. Angles in degrees.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LmlCandidate {
    /// `LML_START_HEIGHT` or `LML_START_GUIDES`.
    pub kind: u32,
    /// Height candidates: 1 when the field is minus the height.
    pub negated: u32,
    /// Height candidates: the unit direction.
    pub direction: [f64; 3],
    /// Guide candidates: the boundary side (of the outer loop split at corners of 30°).
    pub side: u64,
    /// Guide candidates: the angle of the guides' first segments against the boundary.
    pub start_angle_degrees: f64,
    /// 1 when the candidate was scored (`score` valid), 0 when it was rejected.
    pub scored: u32,
    /// 1 when it was rejected (degenerate family, unmeasurable curves, a failed or stalled
    /// solve; the reason is in `lml_search_candidate_text`).
    pub rejected: u32,
    /// Lower is better: RMS + a quarter of the max angle error along the level curves, plus
    /// penalties for nearly straight pieces and singular vertices.
    pub score: f64,
    pub rms_error_degrees: f64,
    pub max_error_degrees: f64,
    /// Fraction of the measured level-curve points that are nearly straight.
    pub straight_fraction: f64,
    pub singular_vertices: u64,
}

impl From<&Candidate> for LmlCandidate {
    fn from(c: &Candidate) -> LmlCandidate {
        let (kind, negated, direction, side, start_angle_degrees) = match &c.kind {
            StartKind::Height { direction, negated } => (LML_START_HEIGHT, u32::from(*negated), *direction, 0, 0.0),
            StartKind::Guides { side, start_angle_degrees } => (LML_START_GUIDES, 0, [0.0; 3], *side as u64, *start_angle_degrees),
        };
        LmlCandidate {
            kind,
            negated,
            direction,
            side,
            start_angle_degrees,
            scored: u32::from(c.score.is_some()),
            rejected: u32::from(c.rejected.is_some()),
            score: c.score.unwrap_or(0.0),
            rms_error_degrees: c.rms_error_degrees,
            max_error_degrees: c.max_error_degrees,
            straight_fraction: c.straight_fraction,
            singular_vertices: c.singular_vertices as u64,
        }
    }
}

/// Prepares a start search on `mesh` for a field of `params` (its family by θ: 0° and 180° the
/// asymptotic curves, 90° the geodesics; its weights and schedule; its gradient target is
/// ignored: each candidate brings its own). The search keeps its own copy of the mesh.
///
/// Returns `LML_STATUS_OK`; `LML_STATUS_INVALID_ARGUMENT` (NULL pointer, a parameter out of
/// range, named). `*out` is set to NULL on failure.
#[no_mangle]
pub unsafe extern "C" fn lml_search_new(mesh: *const LmlMesh, params: *const LmlFieldParams, out: *mut *mut LmlSearch) -> LmlStatus {
    guarded(|| {
        // SAFETY (all blocks): writable `out`, live `mesh`, readable `params`.
        let mut out = unsafe { Out::new(out, "out") }?;
        out.set(std::ptr::null_mut());
        let mesh = unsafe { handle(mesh, "mesh") }?;
        let mut params = unsafe { handle(params, "params") }?.to_params()?;
        // The family by θ, as lml_field_new takes it: the search's candidates (one sign for geodesics
        // and asymptotic curves), its degenerate-family rejection and its measure depend on it.
        params.family = params.family.by_name();
        let search = StartSearch::new(&mesh.mesh, params, SearchOptions::default())?;
        let proxy_vertices = search.proxy_vertex_count().unwrap_or(0);
        out.set_owned(LmlSearch { search: Some(search), finished: Vec::new(), finished_winner: None, proxy_vertices });
        Ok(LmlStatus::Ok)
    })
}

/// Releases a search. NULL is accepted and ignored. The handle must not be used (or freed) again.
#[no_mangle]
pub unsafe extern "C" fn lml_search_free(search: *mut LmlSearch) {
    guarded(|| {
        // SAFETY: `search` is NULL or a live handle from lml_search_new.
        unsafe { release(search) };
        Ok(LmlStatus::Ok)
    });
}

/// Probes the next candidate: a short solve (20 iterations) from its start, then its level
/// curves measured against the smooth surface. A call that solves also runs the short solve of
/// the next candidate that needs one beside it (the two on the machine's cores; candidates
/// rejected without a solve, such as traced guides that cross, are passed over), which that
/// candidate's call then only records: calls take about 20 field iterations' time or almost
/// none. The candidates and the winner are the same whichever core runs which probe.
///
/// Returns `LML_STATUS_MORE` (candidates remain: step again), `LML_STATUS_OK` (the search is
/// complete), `LML_STATUS_INVALID_ARGUMENT` (NULL handle, or the field was already taken).
/// A candidate whose own solve fails is rejected, not a failure of the call.
#[no_mangle]
pub unsafe extern "C" fn lml_search_step(search: *mut LmlSearch) -> LmlStatus {
    guarded(|| {
        // SAFETY: live handle used by this thread only.
        let handle = unsafe { handle_mut(search, "search") }?;
        let search = handle.search.as_mut().ok_or_else(|| Failure::argument("search", "its field was already taken"))?;
        Ok(if search.step()? { LmlStatus::More } else { LmlStatus::Ok })
    })
}

/// Writes the number of candidates probed so far to `*count`.
/// Returns `LML_STATUS_OK` or `LML_STATUS_INVALID_ARGUMENT` (NULL argument).
#[no_mangle]
pub unsafe extern "C" fn lml_search_candidate_count(search: *const LmlSearch, count: *mut usize) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle, writable `count`.
        let search = unsafe { handle(search, "search") }?;
        unsafe { Out::new(count, "count") }?.set(search.candidates().len());
        Ok(LmlStatus::Ok)
    })
}

/// Writes candidate `index` (in probing order) to `*candidate`.
/// Returns `LML_STATUS_OK` or `LML_STATUS_INVALID_ARGUMENT` (NULL argument, index out of range).
#[no_mangle]
pub unsafe extern "C" fn lml_search_candidate(search: *const LmlSearch, index: usize, candidate: *mut LmlCandidate) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle, writable `candidate`.
        let search = unsafe { handle(search, "search") }?;
        let mut out = unsafe { Out::new(candidate, "candidate") }?;
        let all = search.candidates();
        let c = all.get(index).ok_or_else(|| Failure::argument("index", format!("{index} is out of range ({} candidates)", all.len())))?;
        out.set(LmlCandidate::from(c));
        Ok(LmlStatus::Ok)
    })
}

/// Writes a description of candidate `index` as UTF-8 text with a terminating NUL, e.g.
/// "height along (1.000, 0.000, 0.000): score 1.19" or "...: rejected: degenerate: ...", with
/// the two-call pattern: `*needed` receives the byte count including the NUL.
/// Returns `LML_STATUS_OK`, `LML_STATUS_BUFFER_TOO_SMALL`, or `LML_STATUS_INVALID_ARGUMENT`.
#[no_mangle]
pub unsafe extern "C" fn lml_search_candidate_text(
    search: *const LmlSearch,
    index: usize,
    text: *mut u8,
    capacity: usize,
    needed: *mut usize,
) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle; `needed` writable, `text` NULL or `capacity` bytes.
        let search = unsafe { handle(search, "search") }?;
        let all = search.candidates();
        let c = all.get(index).ok_or_else(|| Failure::argument("index", format!("{index} is out of range ({} candidates)", all.len())))?;
        let outcome = match (&c.rejected, c.score) {
            (Some(reason), _) => format!("rejected: {reason}"),
            (None, Some(score)) => format!("score {score:.2}"),
            (None, None) => "not scored".to_string(),
        };
        let mut bytes = format!("{}: {outcome}", c.kind.describe()).into_bytes();
        bytes.push(0);
        unsafe { copy_out(&bytes, text, capacity, needed, "text") }
    })
}

/// Writes the index of the best candidate so far (after `lml_search_field`: the one the field
/// continues from) to `*index`: the best scored one, or when none is scored the best of those
/// rejected only for nearly straight level curves (its `rejected` stays 1: every family the
/// search found is nearly straight over most of the surface, and the strips' verdict decides).
/// Returns `LML_STATUS_OK`, or `LML_STATUS_INVALID_ARGUMENT` (NULL argument, or no such
/// candidate yet: every one so far was rejected for another reason).
#[no_mangle]
pub unsafe extern "C" fn lml_search_winner(search: *const LmlSearch, index: *mut usize) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle, writable `index`.
        let handle = unsafe { handle(search, "search") }?;
        let mut out = unsafe { Out::new(index, "index") }?;
        out.set(handle.winner().ok_or_else(|| Failure::argument("search", "no candidate has been scored"))?);
        Ok(LmlStatus::Ok)
    })
}

/// Writes to `*count` the vertex count of the coarsening the candidates are probed on, or 0
/// when they are probed on the mesh itself. A mesh of more than 1.5 × 1,500 vertices is
/// searched on a coarsening of about 1,500 vertices (a subset of its vertices, same outline and
/// topology); the winner's field is carried to the full mesh by `lml_search_field`.
/// Returns `LML_STATUS_OK` or `LML_STATUS_INVALID_ARGUMENT` (NULL argument).
#[no_mangle]
pub unsafe extern "C" fn lml_search_proxy_vertex_count(search: *const LmlSearch, count: *mut usize) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle, writable `count`.
        let search = unsafe { handle(search, "search") }?;
        unsafe { Out::new(count, "count") }?.set(search.proxy_vertices);
        Ok(LmlStatus::Ok)
    })
}

/// Takes the field of the best candidate (`lml_search_winner`): a new `LmlField` (owned by the caller, released with
/// `lml_field_free`) that continues from where that candidate's short solve ended, with the
/// final weights; step it to convergence. Ends the search (its candidates stay readable).
///
/// Returns `LML_STATUS_OK`; `LML_STATUS_SINGULAR_FIELD` (every candidate was rejected, none only
/// for nearly straight level curves: the message gives each reason; the search stays usable for reading); `LML_STATUS_INVALID_ARGUMENT`
/// (NULL argument, the field was already taken). `*out` is set to NULL on failure.
#[no_mangle]
pub unsafe extern "C" fn lml_search_field(search: *mut LmlSearch, out: *mut *mut LmlField) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): writable `out`, live handle used by this thread only.
        let mut out = unsafe { Out::new(out, "out") }?;
        out.set(std::ptr::null_mut());
        let handle = unsafe { handle_mut(search, "search") }?;
        let search = handle.search.take().ok_or_else(|| Failure::argument("search", "its field was already taken"))?;
        let candidates = search.candidates().to_vec();
        let winner = search.winner();
        if winner.is_none() {
            let message = SearchError::NoStart { reasons: candidates.iter().map(|c| format!("{}: {}", c.kind.describe(), c.rejected.as_deref().unwrap_or("not probed"))).collect() }
                .to_string();
            handle.search = Some(search);
            return Err(Failure::new(LmlStatus::SingularField, message));
        }
        let solver = search.into_solver().map_err(|e| match e {
            SearchError::Field(error) => Failure::from(error),
            other => Failure::new(LmlStatus::SingularField, other.to_string()),
        })?;
        handle.finished = candidates;
        handle.finished_winner = winner;
        out.set_owned(LmlField::new(solver));
        Ok(LmlStatus::Ok)
    })
}
