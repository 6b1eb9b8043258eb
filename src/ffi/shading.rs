//! `LmlShading`: a shading design session (paper Sec. 6), stepped like `LmlField`: create from a
//! mesh, a site (`LmlShadingSite`) and per-vertex labels, step until converged, build the strips
//! along the level curves (one θ per curve), run the sun-path check through them, read the
//! field, the strips' θ and the blocked fractions, free.

use super::failure::Failure;
use super::guard::guarded;
use super::last_error::set_last_error;
use super::mesh::LmlMesh;
use super::raw::{copy_out, handle, handle_mut, input, release, Out};
use super::status::LmlStatus;
use super::strips::LmlStrips;
use crate::mesh::{TriMesh, Vec3};
use crate::shading::{
    default_start, shading_strips, sun_path_check, with_transition_ring, Clock, DateRange, HourRange, LightRegion, MonthDay, ShadingError, ShadingParams,
    ShadingReport, ShadingSolver, ShadingWeights, Site, StartKind, VertexLabel,
};

/// A vertex label (`labels` of `lml_shading_new` and `lml_shading_new_from_field`).
pub type LmlShadingLabel = u32;
/// The vertex's strips block the light of the block region (`E_block`, Eq. 26).
pub const LML_SHADING_BLOCK: LmlShadingLabel = 0;
/// The vertex's strips let the light of the pass region through (`E_light`, Eq. 27).
pub const LML_SHADING_PASS: LmlShadingLabel = 1;
/// A transition vertex: fairness and gradient terms only.
pub const LML_SHADING_FREE: LmlShadingLabel = 2;
/// Most strips `lml_shading_strips` builds.
pub const LML_MAX_SHADING_STRIPS: u32 = 1000;

/// Where the building stands, how the model is oriented and when the shading is for (filled by
/// `lml_shading_site_default`, then edited). Angles in degrees, hours 0–24.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LmlShadingSite {
    /// Geographic latitude, north positive, in [−90, 90].
    pub latitude_degrees: f64,
    /// North and up in model coordinates (north is made horizontal; not parallel to up).
    pub north: [f64; 3],
    pub up: [f64; 3],
    /// With `clock_time` 1: longitude (east positive, [−180, 180]) and time zone (hours east of
    /// UTC, [−14, 14]) of clock-time hours; ignored with `clock_time` 0 (true solar time).
    pub longitude_degrees: f64,
    pub time_zone_hours: f64,
    /// Daily hours whose sun the block vertices block (`first < last`).
    pub first_hour: f64,
    pub last_hour: f64,
    /// Daily hours whose sun the pass vertices let through.
    pub pass_first_hour: f64,
    pub pass_last_hour: f64,
    /// With `direct_region` 1: the block region `R_l` as δ and γ intervals (Eq. 24; δ within
    /// (−90, 90)) instead of from the dates and hours.
    pub delta_degrees: [f64; 2],
    pub gamma_degrees: [f64; 2],
    /// Dates `first_month-first_day .. last_month-last_day`, both included (may run over the new year).
    pub first_month: u32,
    pub first_day: u32,
    pub last_month: u32,
    pub last_day: u32,
    /// 0: hours are true solar time; 1: clock time of `longitude_degrees` and `time_zone_hours`.
    pub clock_time: u32,
    /// 0: the block region from the dates and hours; 1: from `delta_degrees` and `gamma_degrees`.
    pub direct_region: u32,
}

impl LmlShadingSite {
    fn sites(&self) -> (Site, Site) {
        let clock = if self.clock_time != 0 {
            Clock { longitude_degrees: Some(self.longitude_degrees), time_zone_hours: Some(self.time_zone_hours) }
        } else {
            Clock::solar()
        };
        let site = Site {
            latitude_degrees: self.latitude_degrees,
            clock,
            north: Vec3::from(self.north),
            up: Vec3::from(self.up),
            dates: DateRange { first: MonthDay { month: self.first_month, day: self.first_day }, last: MonthDay { month: self.last_month, day: self.last_day } },
            hours: HourRange { first: self.first_hour, last: self.last_hour },
        };
        (site, Site { hours: HourRange { first: self.pass_first_hour, last: self.pass_last_hour }, ..site })
    }
}

/// The state of a shading optimisation after `lml_shading_step` (written by the library; the
/// caller owns the struct). Energies unweighted on the problem scaled to mean edge length 1.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LmlShadingReport {
    /// Iterations run since the session was created.
    pub iterations: u64,
    /// 1 when converged (further steps do nothing), else 0.
    pub converged: u64,
    /// Vertices with a light term (blocking, letting through), and those of them where the level
    /// curve is not regular.
    pub block_vertices: u64,
    pub pass_vertices: u64,
    pub singular_vertices: u64,
    /// 1 when the start was the constant-slope family of the slope vote (Fig. 34–35), 0 when it
    /// was a height field (no usable vote, or no blocking vertex) or the caller's field
    /// (`lml_shading_new_from_field`).
    pub constant_slope_start: u64,
    /// The slope of that family against the earth axis in degrees (0 for any other start).
    pub start_slope_degrees: f64,
    /// `E_fair`, `E_grad`, `E_block` (Eq. 26), `E_light` (Eq. 27), the constraints, and the
    /// weighted total minimised (Eq. 25).
    pub energy_fair: f64,
    pub energy_grad: f64,
    pub energy_block: f64,
    pub energy_light: f64,
    pub energy_constraints: f64,
    pub energy_total: f64,
}

impl LmlShadingReport {
    /// The report of a session started from `start` (`None`: the caller's field).
    fn of(r: &ShadingReport, start: Option<StartKind>) -> LmlShadingReport {
        let e = &r.energies;
        let slope = match start {
            Some(StartKind::ConstantSlope { slope_degrees }) => Some(slope_degrees),
            Some(StartKind::EarthAxisHeight | StartKind::AcrossCentralLight) | None => None,
        };
        LmlShadingReport {
            constant_slope_start: u64::from(slope.is_some()),
            start_slope_degrees: slope.unwrap_or(0.0),
            iterations: r.iterations as u64,
            converged: u64::from(r.converged),
            block_vertices: r.block_vertices as u64,
            pass_vertices: r.pass_vertices as u64,
            singular_vertices: r.singular_vertices as u64,
            energy_fair: e.fair,
            energy_grad: e.grad,
            energy_block: e.block,
            energy_light: e.light,
            energy_constraints: e.constraints,
            energy_total: e.total,
        }
    }
}

/// The outcome of `lml_shading_evaluate`: blocked fractions of the direct-sun hours, −1 for a
/// region without a sample the sun reaches.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LmlSunPathSummary {
    /// Block vertices against the block hours' suns, pass vertices against the pass hours'
    /// suns, free vertices against the block hours' suns.
    pub block_fraction: f64,
    pub pass_fraction: f64,
    pub free_fraction: f64,
    /// Sun positions above the horizon (every hour of every day) of the block and pass hours.
    pub block_suns: u64,
    pub pass_suns: u64,
    /// Rays cast.
    pub rays: u64,
}

/// A shading design session (opaque): a copy of the mesh, the site, the labels, the solver
/// state, and the strips' θ and the blocked fractions of the last strips and evaluation.
/// Create it with `lml_shading_new` or `lml_shading_new_from_field`, release it with
/// `lml_shading_free`.
pub struct LmlShading {
    solver: ShadingSolver,
    /// How the library made the start field; `None` for the caller's (`lml_shading_new_from_field`).
    start: Option<StartKind>,
    mesh: TriMesh,
    sites: (Site, Site),
    /// θ of every strip of the last `lml_shading_strips`, in strip order.
    thetas: Vec<f64>,
    /// Per vertex, of the last `lml_shading_evaluate` (−1 where the sun never reaches).
    fractions: Vec<f64>,
}

impl From<ShadingError> for Failure {
    fn from(e: ShadingError) -> Failure {
        match e {
            ShadingError::Field(error) => Failure::from(error),
            other => Failure::new(LmlStatus::InvalidArgument, other.to_string()),
        }
    }
}

/// Fills `*out` with the defaults: latitude 47.4° (Zurich), north +y, up +z, 1 June to
/// 31 August, 10 to 16 h true solar time for blocking and letting through, the region from the
/// dates and hours. Returns `LML_STATUS_OK` or `LML_STATUS_INVALID_ARGUMENT` (NULL `out`).
#[no_mangle]
pub unsafe extern "C" fn lml_shading_site_default(out: *mut LmlShadingSite) -> LmlStatus {
    guarded(|| {
        // SAFETY: writable `out`.
        unsafe { Out::new(out, "out") }?.set(LmlShadingSite {
            latitude_degrees: 47.4,
            north: [0.0, 1.0, 0.0],
            up: [0.0, 0.0, 1.0],
            longitude_degrees: 0.0,
            time_zone_hours: 0.0,
            first_hour: 10.0,
            last_hour: 16.0,
            pass_first_hour: 10.0,
            pass_last_hour: 16.0,
            delta_degrees: [0.0, 0.0],
            gamma_degrees: [0.0, 0.0],
            first_month: 6,
            first_day: 1,
            last_month: 8,
            last_day: 31,
            clock_time: 0,
            direct_region: 0,
        });
        Ok(LmlStatus::Ok)
    })
}

/// Starts a shading design on `mesh` for `site` (Table 2 weights: blocking ones when some vertex
/// blocks), from the paper's start (Sec. 6, Fig. 34–35): when some vertex blocks, the
/// constant-slope family about the earth axis of the slope most faces vote for (the height along
/// the earth axis when no face votes or none is steep enough for it; `LmlShadingReport` says
/// which), else the height across the central light of the pass region. To start from a field of
/// your own, use `lml_shading_new_from_field`.
///
/// - `mesh`: the surface (copied).
/// - `site`: the site, dates and hours (copied); the block region `R_l` comes from the dates and
///   hours (sun every 15 minutes) unless `site->direct_region` is 1; the pass region always from
///   the dates and the pass hours.
/// - `labels`: `n` labels, one per vertex (`LML_SHADING_BLOCK`, `_PASS`, `_FREE`); not all free.
/// - `ring`: edge rings on each side of a block/pass border made free (0 to 100).
/// - `out`: receives the new session (release with `lml_shading_free`); NULL on failure.
///
/// Returns `LML_STATUS_OK`; `LML_STATUS_INVALID_ARGUMENT` (NULL pointer, `n` ≠ vertex count, a
/// label out of range, a site value out of range or hours more than 6 h from solar noon, the sun
/// never up; the message names the element); `LML_STATUS_SINGULAR_FIELD` (the start field is
/// constant).
#[no_mangle]
pub unsafe extern "C" fn lml_shading_new(
    mesh: *const LmlMesh,
    site: *const LmlShadingSite,
    labels: *const LmlShadingLabel,
    n: usize,
    ring: u32,
    out: *mut *mut LmlShading,
) -> LmlStatus {
    // SAFETY: the pointer contracts are those documented above.
    guarded(|| unsafe { create(mesh, site, labels, n, ring, None, out) })
}

/// Starts a shading design like `lml_shading_new`, but from the caller's field instead of the
/// paper's start (as `lamella shade --start-field`): the session's field right after creation
/// (`lml_shading_field`) is `start_field` (up to the rounding of the solver's internal rescaling,
/// about 1 ulp), and `LmlShadingReport::constant_slope_start` is 0.
///
/// - `mesh`, `site`, `labels`, `n`, `ring`, `out`: as `lml_shading_new`.
/// - `start_field`: `n` doubles, one value per mesh vertex (in vertex order), not constant, each
///   finite with magnitude at most 1e100; its level curves should roughly run where the strips
///   are wanted. Copied.
///
/// Returns `LML_STATUS_OK`; `LML_STATUS_INVALID_ARGUMENT` (as `lml_shading_new`, and a NULL
/// `start_field`, a non-finite value or one beyond ±1e100 in it: the message names the argument
/// `start_field` and the vertex); `LML_STATUS_SINGULAR_FIELD` (`start_field` is constant, or its
/// gradient vanishes everywhere: no level curves).
#[no_mangle]
pub unsafe extern "C" fn lml_shading_new_from_field(
    mesh: *const LmlMesh,
    site: *const LmlShadingSite,
    labels: *const LmlShadingLabel,
    n: usize,
    ring: u32,
    start_field: *const f64,
    out: *mut *mut LmlShading,
) -> LmlStatus {
    // SAFETY: the pointer contracts are those documented above.
    guarded(|| unsafe { create(mesh, site, labels, n, ring, Some(start_field), out) })
}

/// The body of `lml_shading_new` (`start_field` `None`: the paper's start) and
/// `lml_shading_new_from_field` (`Some`: the caller's `n` values, checked with the library's
/// field validation, errors naming `start_field` and the vertex).
///
/// # Safety
/// The pointer contracts of `lml_shading_new_from_field`.
unsafe fn create(
    mesh: *const LmlMesh,
    site: *const LmlShadingSite,
    labels: *const LmlShadingLabel,
    n: usize,
    ring: u32,
    start_field: Option<*const f64>,
    out: *mut *mut LmlShading,
) -> Result<LmlStatus, Failure> {
    // SAFETY (all blocks): forwarded contracts.
    let mut out = unsafe { Out::new(out, "out") }?;
    out.set(std::ptr::null_mut());
    let mesh = unsafe { handle(mesh, "mesh") }?;
    let site = unsafe { handle(site, "site") }?;
    if n != mesh.mesh.vertex_count() {
        return Err(Failure::argument("n", format!("{n} labels for {} vertices", mesh.mesh.vertex_count())));
    }
    let codes = unsafe { input(labels, n, "labels") }?;
    let given = match start_field {
        Some(values) => {
            let values = unsafe { input(values, n, "start_field") }?;
            crate::field::validate_field(&mesh.mesh, values).map_err(|e| {
                let failure = Failure::from(e);
                Failure::new(failure.status, format!("argument `start_field`: {}", failure.message))
            })?;
            Some(values)
        }
        None => None,
    };
    let labels = codes
        .iter()
        .enumerate()
        .map(|(v, &code)| match code {
            LML_SHADING_BLOCK => Ok(VertexLabel::Block),
            LML_SHADING_PASS => Ok(VertexLabel::Pass),
            LML_SHADING_FREE => Ok(VertexLabel::Free),
            other => Err(Failure::argument(&format!("labels[{v}]"), format!("must be 0 (block), 1 (pass) or 2 (free), got {other}"))),
        })
        .collect::<Result<Vec<_>, _>>()?;
    if ring > 100 {
        return Err(Failure::argument("ring", format!("must lie in 0..=100, got {ring}")));
    }
    let (block_site, pass_site) = site.sites();
    let frame = block_site.frame()?;
    pass_site.frame().map_err(|e| Failure::new(LmlStatus::InvalidArgument, format!("pass hours: {e}")))?;
    let block_region = if site.direct_region != 0 { LightRegion::new(site.delta_degrees, site.gamma_degrees)? } else { LightRegion::of_site(&block_site)? };
    let pass_region = LightRegion::of_site(&pass_site)?;
    let labels = with_transition_ring(&mesh.mesh, &labels, ring as usize)?;
    let params = ShadingParams { pass_region, weights: ShadingWeights::for_labels(&labels), ..ShadingParams::new(frame, block_region) };
    let (solver, start) = match given {
        Some(field) => (ShadingSolver::new(&mesh.mesh, field, &labels, params)?, None),
        None => {
            let start = default_start(&mesh.mesh, &params, &labels);
            (ShadingSolver::new(&mesh.mesh, &start.field, &labels, params)?, Some(start.kind))
        }
    };
    out.set_owned(LmlShading { solver, start, mesh: mesh.mesh.clone(), sites: (block_site, pass_site), thetas: Vec::new(), fractions: Vec::new() });
    Ok(LmlStatus::Ok)
}

/// Releases a session. NULL is accepted and ignored. The handle must not be used again.
#[no_mangle]
pub unsafe extern "C" fn lml_shading_free(shading: *mut LmlShading) {
    guarded(|| {
        // SAFETY: `shading` is NULL or a live handle from lml_shading_new.
        unsafe { release(shading) };
        Ok(LmlStatus::Ok)
    });
}

/// Runs at most `max_iterations` iterations and writes the state to `*report` (may be NULL).
///
/// Returns `LML_STATUS_MORE` (step again), `LML_STATUS_CONVERGED`, `LML_STATUS_INVALID_ARGUMENT`
/// (NULL or misaligned pointer) or `LML_STATUS_DID_NOT_CONVERGE` (an iteration failed
/// numerically; the field keeps its last good state).
#[no_mangle]
pub unsafe extern "C" fn lml_shading_step(shading: *mut LmlShading, max_iterations: u32, report: *mut LmlShadingReport) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle used by this thread only; `report` NULL or writable.
        let shading = unsafe { handle_mut(shading, "shading") }?;
        let report = unsafe { Out::optional(report, "report") }?;
        let step = shading.solver.step(usize::try_from(max_iterations).unwrap_or(usize::MAX))?;
        if let Some(mut report) = report {
            report.set(LmlShadingReport::of(&step, shading.start));
        }
        Ok(if step.converged { LmlStatus::Converged } else { LmlStatus::More })
    })
}

/// Writes the state after the last step (or after creation) to `*report`.
/// Returns `LML_STATUS_OK` or `LML_STATUS_INVALID_ARGUMENT` (NULL argument).
#[no_mangle]
pub unsafe extern "C" fn lml_shading_report(shading: *const LmlShading, report: *mut LmlShadingReport) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle; writable `report`.
        let shading = unsafe { handle(shading, "shading") }?;
        unsafe { Out::new(report, "report") }?.set(LmlShadingReport::of(shading.solver.report(), shading.start));
        Ok(LmlStatus::Ok)
    })
}

/// Copies the field (one value per vertex, in the scale of the start field) into `values` with
/// the two-call pattern: `*needed` receives the vertex count; with `capacity` below it nothing is
/// copied and `LML_STATUS_BUFFER_TOO_SMALL` is returned (`values` may be NULL then). Returns
/// `LML_STATUS_OK`, `LML_STATUS_BUFFER_TOO_SMALL` or `LML_STATUS_INVALID_ARGUMENT` (NULL
/// session or `needed`).
#[no_mangle]
pub unsafe extern "C" fn lml_shading_field(shading: *const LmlShading, values: *mut f64, capacity: usize, needed: *mut usize) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle; `values` writable for `capacity` doubles; `needed` writable.
        let shading = unsafe { handle(shading, "shading") }?;
        unsafe { copy_out(&shading.solver.field(), values, capacity, needed, "values") }
    })
}

/// Builds strips of `width` (mesh units, > 0) along `count` (1 to `LML_MAX_SHADING_STRIPS`)
/// equally spaced level curves of the current field, each curve with its own θ (the median
/// angle between the optimised binormal and the surface normal along it), judged with
/// `tolerance_degrees` in (0, 180) against that θ. The strips are a new `LmlStrips` handle
/// (read it with the `lml_strips_*` functions, release it with `lml_strips_free`); their θ are
/// kept for `lml_shading_thetas`.
///
/// Returns `LML_STATUS_OK` (every strip within the tolerance of its θ, no flipped quad);
/// `LML_STATUS_NO_ACCEPTABLE_FAMILY` (the strips are built and `*out` is valid, but some quad
/// misses its curve's θ by more than the tolerance, or is flipped, or no strip could be built:
/// `lml_last_error_message()` names the worst strip and quad, `lml_strips_verdict` gives the
/// numbers); `LML_STATUS_INVALID_ARGUMENT` (NULL pointer, `count`, `width` or
/// `tolerance_degrees` out of range, named).
#[no_mangle]
pub unsafe extern "C" fn lml_shading_strips(shading: *mut LmlShading, count: u32, width: f64, tolerance_degrees: f64, out: *mut *mut LmlStrips) -> LmlStatus {
    guarded(|| {
        // SAFETY (all blocks): writable `out`; live handle used by this thread only.
        let mut out = unsafe { Out::new(out, "out") }?;
        out.set(std::ptr::null_mut());
        let shading = unsafe { handle_mut(shading, "shading") }?;
        if !(1..=LML_MAX_SHADING_STRIPS).contains(&count) {
            return Err(Failure::argument("count", format!("must lie in 1..={LML_MAX_SHADING_STRIPS}, got {count}")));
        }
        if !(width.is_finite() && width > 0.0) {
            return Err(Failure::argument("width", format!("must be finite and > 0, got {width}")));
        }
        if !(tolerance_degrees.is_finite() && tolerance_degrees > 0.0 && tolerance_degrees < 180.0) {
            return Err(Failure::argument("tolerance_degrees", format!("must lie in (0, 180), got {tolerance_degrees}")));
        }
        let built = shading_strips(&shading.mesh, &shading.solver.field(), &shading.solver.binormals(), count as usize, width, tolerance_degrees)?;
        // Every strip's curve has a θ (curves without one get no strip).
        shading.thetas = built.pattern.strips.iter().filter_map(|s| built.thetas[s.curve]).collect();
        let status = match built.miss() {
            None => LmlStatus::Ok,
            Some(miss) => {
                set_last_error(&format!("no acceptable shading strips: {miss}"));
                LmlStatus::NoAcceptableFamily
            }
        };
        out.set_owned(LmlStrips { pattern: built.pattern, theta_degrees: None });
        Ok(status)
    })
}

/// Copies θ in degrees of every strip of the last `lml_shading_strips` (in the strips' order;
/// none before) into `values` with the two-call pattern as `lml_shading_field`.
#[no_mangle]
pub unsafe extern "C" fn lml_shading_thetas(shading: *const LmlShading, values: *mut f64, capacity: usize, needed: *mut usize) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle; `values` writable for `capacity` doubles; `needed` writable.
        let shading = unsafe { handle(shading, "shading") }?;
        unsafe { copy_out(&shading.thetas, values, capacity, needed, "values") }
    })
}

/// The sun-path check of `strips` (any strips on this session's surface, e.g. from
/// `lml_shading_strips`): samples `offset` (mesh units, > 0) behind every vertex, a ray towards
/// the sun every hour of every day of the site's dates when the sun is in front of the surface
/// there, tested against the strips. Writes the region fractions to `*summary` (may be NULL) and
/// keeps the per-vertex fractions for `lml_shading_vertex_fractions`.
///
/// Returns `LML_STATUS_OK` or `LML_STATUS_INVALID_ARGUMENT` (NULL pointer, `offset` out of
/// range, the sun never up; named).
#[no_mangle]
pub unsafe extern "C" fn lml_shading_evaluate(shading: *mut LmlShading, strips: *const LmlStrips, offset: f64, summary: *mut LmlSunPathSummary) -> LmlStatus {
    guarded(|| {
        // SAFETY (all blocks): live handles, `shading` used by this thread only; `summary` NULL or writable.
        let shading = unsafe { handle_mut(shading, "shading") }?;
        let strips = unsafe { handle(strips, "strips") }?;
        let summary = unsafe { Out::optional(summary, "summary") }?;
        let (site, pass_site) = &shading.sites;
        let check = sun_path_check(&shading.mesh, shading.solver.labels(), &strips.pattern.strips, site, pass_site, offset)?;
        let fraction = |f: Option<f64>| f.unwrap_or(-1.0);
        shading.fractions = check.vertex_fractions.iter().map(|&f| fraction(f)).collect();
        if let Some(mut summary) = summary {
            summary.set(LmlSunPathSummary {
                block_fraction: fraction(check.block_fraction()),
                pass_fraction: fraction(check.pass_fraction()),
                free_fraction: fraction(check.block.regions.free),
                block_suns: check.block_suns.len() as u64,
                pass_suns: check.pass_suns.len() as u64,
                rays: check.rays() as u64,
            });
        }
        Ok(LmlStatus::Ok)
    })
}

/// Copies the blocked fraction of every vertex's direct-sun hours of its own region (−1 where
/// the sun never reaches it) of the last `lml_shading_evaluate` (none before) into `values`
/// with the two-call pattern as `lml_shading_field`.
#[no_mangle]
pub unsafe extern "C" fn lml_shading_vertex_fractions(shading: *const LmlShading, values: *mut f64, capacity: usize, needed: *mut usize) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle; `values` writable for `capacity` doubles; `needed` writable.
        let shading = unsafe { handle(shading, "shading") }?;
        unsafe { copy_out(&shading.fractions, values, capacity, needed, "values") }
    })
}
