//! Command-line syntax: the subcommands and their flags, each documented with default and unit.
use clap::{Args, Parser, Subcommand};
use std::path::PathBuf;

/// Rectifying strip patterns (Wang, Wang, Schling, Pottmann 2023): pseudo-geodesic curve families
/// on a triangle mesh and the developable strips that follow them.
///
/// Without a subcommand: designs a θ = 60° pattern on the built-in hall roof into ./lamella-out/
/// (the same as `lamella design`).
#[derive(Parser, Debug)]
#[command(name = "lamella", version, args_conflicts_with_subcommands = true)]
pub struct Cli {
    #[command(subcommand)]
    pub command: Option<Command>,
    #[command(flatten)]
    pub design: DesignArgs,
}

#[derive(Subcommand, Debug)]
pub enum Command {
    /// The whole pipeline: field → level curves → rectifying strips → cut sheet, plots, report,
    /// 3D viewer (view.html).
    Design(DesignArgs),
    /// Mesh validation report: counts, boundary loops, disk or not, bounding box, mean edge
    /// length and the problems found (the first 100 one per line, the rest counted).
    Info(InfoArgs),
    /// Trace guide P-curves (paper Sec. 3.2.1, Eq. 4) from evenly spaced points of one side of the
    /// boundary. Writes guides.json (for `field --guides-file` / `design --guides-file`),
    /// guides.obj and report.json (lengths, why each curve stopped, crossings).
    Trace(TraceArgs),
    /// Optimise the scalar field whose level sets are the pseudo-geodesics, or continue a saved
    /// session (--resume). Writes field.csv, session.bin, energies.csv, convergence.svg, report.json.
    Field(FieldArgs),
    /// Level curves of a field and the rectifying strips along them. Writes curves.obj,
    /// strips.obj, rulings.obj, diagnostics.csv (Sec. 5.1 per strip vertex), preview.svg, report.json.
    Strips(StripsArgs),
    /// Lay the strips of a strips.obj flat into a cut sheet (unrolled.svg, millimetres).
    Unroll(UnrollArgs),
    /// Table 4 quality measures of the strips in a strips.obj.
    Metrics(MetricsArgs),
    /// Workshop files for the strips in a strips.obj: the bending and twisting check of each
    /// strip for a material and thickness, strips longer than the stock split at splices, the
    /// pieces laid out on stock boards. Writes cut.dxf, cut.svg, bom.csv, utilisation.svg,
    /// report.json.
    Fabricate(FabricateArgs),
    /// A gridshell net of two curve families (paper Sec. 4.1): both fields optimised together,
    /// strips per family, the quad net of their crossings and the nodes. Writes curves_<k>.obj,
    /// strips_<k>.obj, net.obj, nodes.csv, unrolled.svg (with node marks), preview.svg, view.html, report.json.
    Net(NetArgs),
    /// The interactive 3D viewer of an output directory: prints the path of DIR/view.html, which
    /// `design` and `net` write, first writing it from the directory's files (strips.obj,
    /// report.json, surface.obj, curves.obj) when it is missing. Open it in any browser: one
    /// self-contained file, no network needed.
    View(ViewArgs),
    /// Move the surface a little so that the level sets of a fixed field become P-curves of θ
    /// (paper Sec. 3.3, Fig. 17), within a bound on the deviation from the original surface.
    /// Writes surface.obj, deviation.csv, reshape.bin, curves.obj, strips.obj, rulings.obj,
    /// preview.svg (coloured by displacement), report.json; exits 3 when the strips on the moved
    /// surface still miss θ. With --alternate the field changes too (field and surface steps in
    /// turn) and field.csv is written instead of reshape.bin.
    Reshape(ReshapeArgs),
    /// Optimise a net's vertices (paper Sec. 3.5) so that its rows and columns form the asked
    /// families exactly near a reference surface, with --torsion-free also a common ruling of
    /// both strips at every node (Sec. 5.2.1, Eq. 21). Reads the net.obj of `net`. Writes net.obj
    /// (optimised), strips_<k>.obj, nodes.csv, report.json; exits 3 when a family misses its angle
    /// or the nodes are not torsion-free as asked.
    Optimise(OptimiseArgs),
    /// A shading system (paper Sec. 6): strips that block the sun of the given dates and hours
    /// (or let it through where --pass says), then a sun-path check casting the sun's rays from
    /// behind the surface through the strips. Writes curves.obj, strips.obj, rulings.obj,
    /// field.csv, unrolled.svg, shading.svg (surface coloured by blocked fraction), sunpath.svg,
    /// report.json; exits 3 when a block region is not blocked or a pass region not passed to
    /// the stated fractions.
    Shade(ShadeArgs),
    /// Write a built-in surface as surface.obj (for --mesh of the other commands): the hall roof of
    /// the default design, or the Brauner surface of the paper's Fig. 32 (Sec. 5.2.4, Eq. 23),
    /// whose u-lines are asymptotic curves of constant slope against the horizontal; for it also
    /// asymptotic.obj, those u-lines computed exactly, a validation case for
    /// `field --family slope` and the asymptotic family. Writes report.json too.
    Surface(SurfaceArgs),
}

/// Progress and summary output.
#[derive(Args, Debug, Clone, Copy, Default)]
pub struct VerbosityArgs {
    /// Print nothing but errors.
    #[arg(short, long, conflicts_with = "verbose")]
    pub quiet: bool,
    /// Print every iteration with all energy terms, and every strip warning.
    #[arg(short, long)]
    pub verbose: bool,
}

/// Where the input surface comes from.
#[derive(Args, Debug, Clone, Default)]
pub struct MeshArgs {
    /// Input surface, a triangle mesh in OBJ format, in metres (a topological disk, possibly with
    /// holes) [default: the built-in hall roof, 40 m × 24 m, about 3000 vertices].
    #[arg(long, value_name = "M.obj")]
    pub mesh: Option<PathBuf>,
}

/// The output directory, written to a temporary directory and moved into place at the end.
#[derive(Args, Debug, Clone, Default)]
pub struct OutArgs {
    /// Output directory [default: lamella-out].
    #[arg(long, value_name = "DIR")]
    pub out: Option<PathBuf>,
    /// Replace an existing output directory that a previous Lamella run wrote (it holds the marker
    /// .lamella-output and only the files listed there); any other existing path is refused.
    #[arg(long)]
    pub force: bool,
}

/// The curve family: its angle θ, or its name.
#[derive(Args, Debug, Clone, Default)]
pub struct FamilyFlags {
    /// Target angle θ between the strips' binormals and the surface normal, in degrees, 0 to 180:
    /// 0 and 180 are the asymptotic curves (E_asy), 90 the geodesics (E_geo), other angles the
    /// pseudo-geodesics (E_angle) [default: 60, or the --family's angle].
    #[arg(long, value_name = "DEGREES", allow_negative_numbers = true)]
    pub theta: Option<f64>,
    /// The curve family by name: asymptotic (θ = 0), geodesic (θ = 90) or pseudo-geodesic (θ from
    /// --theta, neither 0, 90 nor 180); `lamella field` also takes slope (curves of constant slope
    /// about --axis, see --slope) [default: named by θ].
    #[arg(long, value_name = "asymptotic|geodesic|pseudo-geodesic")]
    pub family: Option<String>,
}

/// Parameters of the field optimisation.
#[derive(Args, Debug, Clone, Default)]
pub struct FieldFlags {
    #[command(flatten)]
    pub family: FamilyFlags,
    /// Upper bound on the total number of Levenberg–Marquardt iterations of the field, 1 to
    /// 100000 [default: 400].
    #[arg(long, value_name = "N")]
    pub max_iterations: Option<usize>,
}

/// Where the field optimisation starts (paper Sec. 3.2.2). At most one of these; without any,
/// a search tries several starts (heights along the surface's principal directions, then guides
/// traced from each boundary side), runs a short solve from each, judges the level curves each
/// reaches and continues the best; report.json lists the candidates with their scores.
#[derive(Args, Debug, Clone, Default)]
pub struct StartFlags {
    /// Trace this many guide P-curves of angle θ from one side of the boundary (see
    /// --guide-side, --guide-angle) and start from the field that takes the value i on guide i
    /// (Eq. 5–7), 2 to 100 [default: none].
    #[arg(long, value_name = "N", conflicts_with_all = ["guides_file", "strokes", "direction", "start_field"])]
    pub guides: Option<usize>,
    /// Start from the guide curves in a guides.json written by `lamella trace` (traced on the same
    /// mesh) [default: none].
    #[arg(long, value_name = "guides.json", conflicts_with_all = ["strokes", "direction", "start_field"])]
    pub guides_file: Option<PathBuf>,
    /// Start from the height along this direction (three numbers, any length but not zero): the
    /// level sets start as the sections orthogonal to it [default: none].
    #[arg(long, value_name = "X,Y,Z", allow_negative_numbers = true, conflicts_with_all = ["strokes", "start_field"])]
    pub direction: Option<String>,
    /// Start from this field: one value per mesh vertex, one per line (field.csv of `field` or
    /// `design`) [default: none].
    #[arg(long, value_name = "F.csv", conflicts_with = "strokes")]
    pub start_field: Option<PathBuf>,
    /// Start from sketched strokes: a JSON file {"strokes": [[[x, y, z], ...], ...]} of at least two
    /// polylines drawn on (within one mean edge length of) the surface, in metres. The level sets
    /// are fitted to them and θ is estimated from them unless --theta is given (Fig. 14)
    /// [default: none].
    #[arg(long, value_name = "S.json")]
    pub strokes: Option<PathBuf>,
    #[command(flatten)]
    pub seeding: GuideSeedingFlags,
}

/// Where guide curves start (for --guides and `lamella trace`).
#[derive(Args, Debug, Clone, Default)]
pub struct GuideSeedingFlags {
    /// The side of the outer boundary the guides start from: the boundary split at corners
    /// (turns of 30° or more) into sides numbered from 0 along the boundary; 'longest' picks the
    /// longest side [default: longest].
    #[arg(long, value_name = "K|longest")]
    pub guide_side: Option<String>,
    /// Angle between each guide's first segment and the boundary, in degrees, 0 to 180 exclusive
    /// (90 = perpendicular) [default: 90].
    #[arg(long, value_name = "DEGREES", allow_negative_numbers = true)]
    pub guide_angle: Option<f64>,
}

/// Parameters of the strips.
#[derive(Args, Debug, Clone, Default)]
pub struct StripFlags {
    /// Number of strips: level curves at equally spaced field values, 1 to 1000 [default: 20].
    #[arg(long, value_name = "N")]
    pub strips: Option<usize>,
    /// Strip width in metres (mesh units), > 0 [default: half the mean spacing of the level curves].
    #[arg(long, value_name = "METRES", allow_negative_numbers = true)]
    pub width: Option<f64>,
    /// Largest angle error of a strip quad, in degrees, between 0 and 180 exclusive: strips off
    /// by more (or with flipped quads) make the run exit with code 3, "no acceptable family",
    /// after writing its outputs [default: 2].
    #[arg(long, value_name = "DEGREES", allow_negative_numbers = true)]
    pub tolerance: Option<f64>,
}

/// Parameters from a TOML file.
#[derive(Args, Debug, Clone, Default)]
pub struct ConfigArgs {
    /// TOML file with any of: mesh, out, theta, family, max_iterations, strips, width,
    /// tolerance, guides, guides_file, strokes, direction ([x, y, z]), start_field, guide_side,
    /// guide_angle (same meanings and units as the flags; a flag wins over the file)
    /// [default: none].
    #[arg(long, value_name = "design.toml")]
    pub config: Option<PathBuf>,
}

#[derive(Args, Debug, Clone, Default)]
pub struct DesignArgs {
    #[command(flatten)]
    pub mesh: MeshArgs,
    #[command(flatten)]
    pub field: FieldFlags,
    #[command(flatten)]
    pub start: StartFlags,
    #[command(flatten)]
    pub strips: StripFlags,
    /// Boxed: the workshop flags are rarely given and would make every command large.
    #[command(flatten)]
    pub fabrication: Box<FabricationFlags>,
    #[command(flatten)]
    pub out: OutArgs,
    #[command(flatten)]
    pub config: ConfigArgs,
    #[command(flatten)]
    pub verbosity: VerbosityArgs,
}

#[derive(Args, Debug, Clone)]
pub struct InfoArgs {
    /// The OBJ file to check.
    #[arg(value_name = "M.obj")]
    pub mesh: PathBuf,
}

#[derive(Args, Debug, Clone, Default)]
pub struct TraceArgs {
    #[command(flatten)]
    pub mesh: MeshArgs,
    #[command(flatten)]
    pub family: FamilyFlags,
    /// Number of guide curves, 1 to 100 [default: 4].
    #[arg(long, value_name = "N")]
    pub guides: Option<usize>,
    #[command(flatten)]
    pub seeding: GuideSeedingFlags,
    #[command(flatten)]
    pub out: OutArgs,
    #[command(flatten)]
    pub config: ConfigArgs,
    #[command(flatten)]
    pub verbosity: VerbosityArgs,
}

#[derive(Args, Debug, Clone, Default)]
pub struct FieldArgs {
    #[command(flatten)]
    pub mesh: MeshArgs,
    #[command(flatten)]
    pub field: FieldFlags,
    #[command(flatten)]
    pub start: StartFlags,
    /// Continue the saved session (session.bin of an earlier `field` or `design` run) up to
    /// --max-iterations in total; its mesh and θ are used, and energies.csv beside it extends
    /// the history [default: start a new optimisation].
    #[arg(long, value_name = "session.bin", conflicts_with_all = ["mesh", "theta", "family", "guides", "guides_file", "strokes", "direction", "start_field"])]
    pub resume: Option<PathBuf>,
    #[command(flatten)]
    pub slope: SlopeFlags,
    #[command(flatten)]
    pub out: OutArgs,
    #[command(flatten)]
    pub config: ConfigArgs,
    #[command(flatten)]
    pub verbosity: VerbosityArgs,
}

/// A constant-slope family (paper Sec. 5.2.3, Eq. 22), chosen with `--family slope`.
#[derive(Args, Debug, Clone, Default)]
pub struct SlopeFlags {
    /// With --family slope: the axis d (three numbers, any length but not zero) [default: 0,0,1].
    #[arg(long, value_name = "X,Y,Z", allow_negative_numbers = true)]
    pub axis: Option<String>,
    /// With --family slope: the slope β in degrees, −90 to 90 exclusive, of the level curves'
    /// tangents against the planes orthogonal to the axis (t·d = sin β = cos γ); −β gives the
    /// other family of slope |β| [default: 30].
    #[arg(long, value_name = "DEGREES", allow_negative_numbers = true)]
    pub slope: Option<f64>,
    /// With --family slope: let the family's slope vary (started at --slope) [default: fixed].
    #[arg(long)]
    pub free_slope: bool,
}

#[derive(Args, Debug, Clone, Default)]
pub struct StripsArgs {
    #[command(flatten)]
    pub mesh: MeshArgs,
    /// The field, one value per mesh vertex (field.csv of `field` or `design`).
    #[arg(long = "field", value_name = "field.csv")]
    pub field_csv: PathBuf,
    #[command(flatten)]
    pub family: FamilyFlags,
    #[command(flatten)]
    pub strips: StripFlags,
    #[command(flatten)]
    pub out: OutArgs,
    #[command(flatten)]
    pub config: ConfigArgs,
    #[command(flatten)]
    pub verbosity: VerbosityArgs,
}

#[derive(Args, Debug, Clone, Default)]
pub struct UnrollArgs {
    /// The strips (strips.obj of `strips` or `design`).
    #[arg(long = "strips", value_name = "strips.obj")]
    pub strips_obj: PathBuf,
    #[command(flatten)]
    pub out: OutArgs,
    #[command(flatten)]
    pub verbosity: VerbosityArgs,
}

#[derive(Args, Debug, Clone, Default)]
pub struct MetricsArgs {
    #[command(flatten)]
    pub mesh: MeshArgs,
    /// The strips (strips.obj of `strips` or `design`).
    #[arg(long = "strips", value_name = "strips.obj")]
    pub strips_obj: PathBuf,
    #[command(flatten)]
    pub family: FamilyFlags,
    /// Largest angle error of a strip quad in degrees (the verdict, as for `design`) [default: 2].
    #[arg(long, value_name = "DEGREES", allow_negative_numbers = true)]
    pub tolerance: Option<f64>,
    /// Print JSON instead of a table.
    #[arg(long)]
    pub json: bool,
    #[command(flatten)]
    pub verbosity: VerbosityArgs,
}

/// Material, thickness and stock of the strips (`fabricate`, and `design` when --thickness is given).
#[derive(Args, Debug, Clone, Default)]
pub struct FabricationFlags {
    /// Strip material: timber (C24), plywood (birch), steel (S355) or aluminium (6082 T6), or
    /// custom with --youngs-modulus, --shear-modulus and --allowable-stress [default: timber].
    #[arg(long, value_name = "NAME")]
    pub material: Option<String>,
    /// Strip thickness, a length such as 6mm (metres without a unit), > 0; `design` writes the
    /// workshop files only when it is given [default: none].
    #[arg(long, value_name = "LENGTH", allow_hyphen_values = true)]
    pub thickness: Option<String>,
    /// Length of the stock boards or sheets, such as 4.8m, longer than twice the overlap
    /// [default: 4.8m].
    #[arg(long, value_name = "LENGTH", allow_hyphen_values = true)]
    pub stock: Option<String>,
    /// Width of the stock sheets, such as 1.25m [default: as wide as the widest piece, one row per board].
    #[arg(long, value_name = "LENGTH", allow_hyphen_values = true)]
    pub stock_width: Option<String>,
    /// Splice overlap between consecutive pieces of a strip, such as 300mm [default: 0.3m].
    #[arg(long, value_name = "LENGTH", allow_hyphen_values = true)]
    pub overlap: Option<String>,
    /// Young's modulus, such as 11GPa, replacing the material's [default: the material's].
    #[arg(long, value_name = "STRESS", allow_hyphen_values = true)]
    pub youngs_modulus: Option<String>,
    /// Shear modulus, such as 0.69GPa, replacing the material's [default: the material's].
    #[arg(long, value_name = "STRESS", allow_hyphen_values = true)]
    pub shear_modulus: Option<String>,
    /// Allowable stress (compared with the von Mises stress of bending and torsion), such as
    /// 24MPa, replacing the material's [default: the material's characteristic strength].
    #[arg(long, value_name = "STRESS", allow_hyphen_values = true)]
    pub allowable_stress: Option<String>,
}

#[derive(Args, Debug, Clone, Default)]
pub struct FabricateArgs {
    /// The strips (strips.obj of `strips` or `design`).
    #[arg(long = "strips", value_name = "strips.obj")]
    pub strips_obj: PathBuf,
    /// θ of the strips' family in degrees, for the bill of materials [default: unknown, left empty].
    #[arg(long, value_name = "DEGREES", allow_negative_numbers = true)]
    pub theta: Option<f64>,
    #[command(flatten)]
    pub fabrication: FabricationFlags,
    #[command(flatten)]
    pub out: OutArgs,
    #[command(flatten)]
    pub verbosity: VerbosityArgs,
}

#[derive(Args, Debug, Clone)]
pub struct NetArgs {
    #[command(flatten)]
    pub mesh: MeshArgs,
    /// The two families of a net or the three of a 3-web, comma-separated: P<θ>
    /// (pseudo-geodesics of angle θ in degrees), G (geodesics) or A (asymptotic curves), e.g.
    /// P60,P60 or A,A; a web's third family is the diagonal one (F + G + H = 0), e.g. A,A,G or
    /// P60,P60,G.
    #[arg(long, value_name = "F,G[,H]", required_unless_present = "resume")]
    pub families: Option<String>,
    /// A 3-web's third family shifted by half a level spacing: a Kagome pattern (paper Fig. 1),
    /// whose curves cross in pairs, the third family halfway between the others' crossings.
    #[arg(long)]
    pub kagome: bool,
    /// Continue a net optimisation saved by an earlier `net` (its net.bin: mesh, families,
    /// angles and both fields), bit for bit as if it had not stopped; --max-iterations includes
    /// the iterations it ran before.
    #[arg(long, value_name = "net.bin", conflicts_with_all = ["mesh", "families", "angle", "min_angle", "start_field"])]
    pub resume: Option<PathBuf>,
    /// Start a family from this field instead of the default start: one value per mesh vertex,
    /// one per line (field.csv of `field` or `design`, e.g. started from guides or strokes).
    /// Given once per family of a net, or for the first two of a 3-web, in --families order
    /// [default: the default start of both]
    #[arg(long, value_name = "F.csv")]
    pub start_field: Vec<PathBuf>,
    /// Target intersection angle of the two families in degrees, in (0, 180), held as a weak term
    /// [default: none, only --min-angle is held].
    #[arg(long, value_name = "DEGREES")]
    pub angle: Option<f64>,
    /// Minimum intersection angle of the two families (of every two in a 3-web) in degrees, in [0, 90).
    #[arg(long, value_name = "DEGREES", default_value_t = 30.0)]
    pub min_angle: f64,
    /// Level curves (strips) per family; in a 3-web, of the first two families at one even
    /// spacing, the third family's levels being their diagonals.
    #[arg(long, value_name = "N", default_value_t = 10)]
    pub lines: usize,
    /// Strip width in metres [default: half the mean spacing of neighbouring curves].
    #[arg(long, value_name = "M")]
    pub width: Option<f64>,
    /// Most Levenberg–Marquardt iterations of the net solve.
    #[arg(long, value_name = "N", default_value_t = 300)]
    pub max_iterations: usize,
    /// Largest strip-plane angle error (degrees) of an acceptable family; above it the command exits 3.
    #[arg(long, value_name = "DEGREES", default_value_t = 2.0)]
    pub tolerance: f64,
    /// The workshop files of both families' strips, with the nodes marked and kept clear of splices.
    #[command(flatten)]
    pub fabrication: Box<FabricationFlags>,
    #[command(flatten)]
    pub out: OutArgs,
    #[command(flatten)]
    pub verbosity: VerbosityArgs,
}

#[derive(Args, Debug, Clone)]
pub struct OptimiseArgs {
    /// The net: vertices, and its rows and columns as `l` polylines after `o rows` and
    /// `o columns`, a web's third family after `o diagonals` (the net.obj of `lamella net`).
    #[arg(long, value_name = "net.obj", required_unless_present = "resume")]
    pub net: Option<PathBuf>,
    /// The family of the rows and of the columns (and of a web's diagonals), comma-separated:
    /// P<θ> (pseudo-geodesics of angle θ in degrees), G (geodesics), A (asymptotic curves) or
    /// S<β> (constant slope β in degrees against the planes orthogonal to --axis; two of them make
    /// every node axis parallel to it, Sec. 5.2.2), e.g. P60,P60, S20,S20 or A,A,G.
    #[arg(long, value_name = "F,G[,H]", required_unless_present = "resume")]
    pub types: Option<String>,
    /// The axis of S<β> families (three numbers, any length but not zero) [default: 0,0,1].
    #[arg(long, value_name = "X,Y,Z")]
    pub axis: Option<String>,
    /// Continue a base-mesh optimisation saved by an earlier `optimise` (its optimise.bin: net,
    /// reference, families, torsion-free nodes, tolerance and the optimised net), bit for bit as
    /// if it had not stopped; --max-iterations includes the iterations it ran before.
    #[arg(long, value_name = "optimise.bin", conflicts_with_all = ["net", "types", "axis", "reference", "torsion_free", "tolerance", "weights"])]
    pub resume: Option<PathBuf>,
    /// Also make every node torsion-free: one ruling shared by both strips there (Eq. 21).
    #[arg(long)]
    pub torsion_free: bool,
    /// The reference surface the net stays near, a triangle mesh in OBJ format [default: the
    /// built-in hall roof, the default surface of `lamella net`].
    #[arg(long, value_name = "M.obj")]
    pub reference: Option<PathBuf>,
    /// Most Levenberg–Marquardt iterations.
    #[arg(long, value_name = "N", default_value_t = 300)]
    pub max_iterations: usize,
    /// Strip width in metres [default: half the mean segment length of the net as given].
    #[arg(long, value_name = "M")]
    pub width: Option<f64>,
    /// The weights of the terms, comma-separated `name=value` on the net scaled to mean segment 1
    /// (the paper's Table 3 gives them per figure): curve (the family rows, default 1), fair
    /// (fairness along the polylines, 1e-3), close (distance to the reference along its normal,
    /// 1), pull (toward the start positions, 1e-4: raise it to keep a net's extent, which shrinks
    /// where the families cannot be met as placed), torsion (Eq. 21's rows, 1); unnamed ones keep
    /// their default, e.g. `pull=1e-2,fair=1e-4`.
    #[arg(long, value_name = "NAME=W,...")]
    pub weights: Option<String>,
    /// Largest angle error (degrees) of a family at a vertex, measured against the reference's
    /// normal; above it the command exits 3 (with --resume, the session's).
    #[arg(long, value_name = "DEGREES", default_value_t = 1.0)]
    pub tolerance: f64,
    #[command(flatten)]
    pub out: OutArgs,
    #[command(flatten)]
    pub verbosity: VerbosityArgs,
}

#[derive(Args, Debug, Clone)]
pub struct ViewArgs {
    /// An output directory of `lamella design` (or `strips`, `net`).
    #[arg(value_name = "DIR")]
    pub dir: PathBuf,
}

#[derive(Args, Debug, Clone)]
pub struct ReshapeArgs {
    #[command(flatten)]
    pub mesh: MeshArgs,
    /// The field, one value per mesh vertex (field.csv of `field` or `design`); it stays fixed.
    #[arg(long = "field", value_name = "field.csv", required_unless_present_any = ["session", "resume"], conflicts_with_all = ["session", "resume"])]
    pub field_csv: Option<PathBuf>,
    /// Take mesh and field from a saved session (session.bin of `field` or `design`) instead of
    /// --mesh and --field.
    #[arg(long, value_name = "session.bin", conflicts_with_all = ["mesh", "resume"])]
    pub session: Option<PathBuf>,
    /// Continue a surface optimisation saved by an earlier `reshape` (its reshape.bin: original
    /// surface, field, θ, tolerance and the moved surface), bit for bit as if it had not stopped;
    /// --max-iterations includes the iterations it ran before.
    #[arg(long, value_name = "reshape.bin", conflicts_with_all = ["mesh", "theta", "tolerance"])]
    pub resume: Option<PathBuf>,
    /// Target angle θ between the binormals of the level curves and the surface normal, in
    /// degrees, 0 to 180 exclusive.
    #[arg(long, value_name = "DEGREES", allow_negative_numbers = true, required_unless_present = "resume")]
    pub theta: Option<f64>,
    /// Largest distance of a vertex from the original surface: a length (metres, or with mm, cm
    /// or m) or a percentage of the bounding-box diagonal such as 0.5% [default: 1%].
    #[arg(long, value_name = "LENGTH|P%", allow_hyphen_values = true)]
    pub tolerance: Option<String>,
    /// Most Levenberg–Marquardt iterations of the surface, 1 to 100000 (with --alternate: of
    /// each field step and each surface step).
    #[arg(long, value_name = "N", default_value_t = 300)]
    pub max_iterations: usize,
    /// Alternate field steps (the surface fixed) and surface steps (the field fixed), at most
    /// ROUNDS rounds, 1 to 1000, until a round in which both converge (Sec. 3.3): the field
    /// changes too and is written as field.csv; the deviation stays within --tolerance
    /// throughout. No reshape.bin then (a single surface session is what --resume continues).
    #[arg(long, value_name = "ROUNDS", conflicts_with = "resume")]
    pub alternate: Option<usize>,
    /// Number of strips on the moved surface, 1 to 1000.
    #[arg(long, value_name = "N", default_value_t = 20)]
    pub strips: usize,
    /// Largest angle error of a strip quad in degrees, between 0 and 180 exclusive: above it the
    /// command exits 3, "no acceptable family" (as `design`).
    #[arg(long, value_name = "DEGREES", default_value_t = 2.0, allow_negative_numbers = true)]
    pub angle_tolerance: f64,
    #[command(flatten)]
    pub out: OutArgs,
    #[command(flatten)]
    pub verbosity: VerbosityArgs,
}

#[derive(Args, Debug, Clone)]
pub struct ShadeArgs {
    #[command(flatten)]
    pub mesh: MeshArgs,
    /// Geographic latitude in degrees, north positive.
    #[arg(long, value_name = "DEGREES", allow_negative_numbers = true)]
    pub latitude: f64,
    /// Longitude in degrees, east positive; with --time-zone the hours are clock time,
    /// without both they are true solar time.
    #[arg(long, value_name = "DEGREES", allow_negative_numbers = true, requires = "time_zone")]
    pub longitude: Option<f64>,
    /// Time zone in hours east of UTC (e.g. 1 for CET); needs --longitude.
    #[arg(long, value_name = "HOURS", allow_negative_numbers = true, requires = "longitude")]
    pub time_zone: Option<f64>,
    /// North in model coordinates, X,Y,Z (made horizontal).
    #[arg(long, value_name = "X,Y,Z", default_value = "0,1,0", allow_hyphen_values = true)]
    pub north: String,
    /// Up in model coordinates, X,Y,Z.
    #[arg(long, value_name = "X,Y,Z", default_value = "0,0,1", allow_hyphen_values = true)]
    pub up: String,
    /// Dates MM-DD..MM-DD, both included (a range may run over the new year).
    #[arg(long, value_name = "MM-DD..MM-DD", default_value = "06-01..08-31")]
    pub dates: String,
    /// Daily hours H..H to shade (decimal hours, e.g. 9.5..16).
    #[arg(long, value_name = "H..H", default_value = "10..16")]
    pub hours: String,
    /// Daily hours H..H whose light the --pass vertices let through [default: --hours].
    #[arg(long, value_name = "H..H")]
    pub pass_hours: Option<String>,
    /// The light region of blocking given directly as δ interval MIN..MAX in degrees (paper
    /// Sec. 6, Eq. 24) instead of from the dates and hours; needs --gamma.
    #[arg(long, value_name = "MIN..MAX", allow_hyphen_values = true, requires = "gamma")]
    pub delta: Option<String>,
    /// The γ interval MIN..MAX in degrees of a direct light region; needs --delta.
    #[arg(long, value_name = "MIN..MAX", allow_hyphen_values = true, requires = "delta")]
    pub gamma: Option<String>,
    /// Vertices that block (one value per vertex and line, non-zero = block); the others are
    /// free unless --pass names them [default: every vertex not in --pass blocks].
    #[arg(long, value_name = "mask.csv")]
    pub mask: Option<PathBuf>,
    /// Vertices that let the light through (one value per vertex and line, non-zero = pass).
    #[arg(long, value_name = "pass.csv")]
    pub pass: Option<PathBuf>,
    /// Width in edge rings of the free transition on each side of a block/pass border.
    #[arg(long, value_name = "N", default_value_t = 1)]
    pub ring: usize,
    /// Start field: the height along X,Y,Z [default: along the earth axis when blocking (the
    /// paper's planar start), across the central light when only letting through].
    #[arg(long, value_name = "X,Y,Z", allow_hyphen_values = true, conflicts_with = "start_field")]
    pub start_direction: Option<String>,
    /// Start field from a file (one value per vertex and line).
    #[arg(long, value_name = "field.csv")]
    pub start_field: Option<PathBuf>,
    /// Most Levenberg–Marquardt iterations, 1 to 100000.
    #[arg(long, value_name = "N", default_value_t = 100)]
    pub max_iterations: usize,
    /// Number of strips, 1 to 1000.
    #[arg(long, value_name = "N", default_value_t = 20)]
    pub strips: usize,
    /// Strip width in metres [default: the spacing of the level curves].
    #[arg(long, value_name = "LENGTH")]
    pub width: Option<String>,
    /// Distance of the sample points behind the surface, in metres [default: 5 % of the mean
    /// curve spacing].
    #[arg(long, value_name = "LENGTH")]
    pub offset: Option<String>,
    /// Least blocked fraction of the direct-sun hours in the block region; below it, exit 3.
    #[arg(long, value_name = "FRACTION", default_value_t = 0.8)]
    pub min_blocked: f64,
    /// Largest blocked fraction of the direct-sun hours in the pass region; above it, exit 3.
    #[arg(long, value_name = "FRACTION", default_value_t = 0.2)]
    pub max_blocked_pass: f64,
    /// Largest angle error of a strip quad in degrees against its own curve's θ, between 0 and
    /// 180 exclusive: above it the command exits 3 (the strips' verdict, as `design`).
    #[arg(long, value_name = "DEGREES", default_value_t = 2.0, allow_negative_numbers = true)]
    pub tolerance: f64,
    #[command(flatten)]
    pub out: OutArgs,
    #[command(flatten)]
    pub verbosity: VerbosityArgs,
}

#[derive(Args, Debug, Clone)]
pub struct SurfaceArgs {
    /// Which surface: hall-roof (40 m × 24 m, the default design's) or brauner (Fig. 32:
    /// x = cos²u − 2v, y = sin u cos u − u, z = 2μ e^{−v} cos u over u ∈ [0.6, π − 0.6],
    /// v ∈ [−0.5, 0.5]).
    #[arg(value_name = "KIND", value_parser = ["hall-roof", "brauner"])]
    pub kind: String,
    /// Approximate number of vertices, 100 to 1000000 [default: 3000].
    #[arg(long, value_name = "N")]
    pub vertices: Option<usize>,
    /// brauner: the constant μ > 0 of Eq. 23 (the u-line v has the slope atan(μ e^{−v}))
    /// [default: 1].
    #[arg(long, value_name = "MU", allow_negative_numbers = true)]
    pub mu: Option<f64>,
    /// brauner: number of u-lines in asymptotic.obj, 2 to 1000, evenly spaced in v
    /// [default: 11].
    #[arg(long, value_name = "N")]
    pub lines: Option<usize>,
    #[command(flatten)]
    pub out: OutArgs,
    #[command(flatten)]
    pub verbosity: VerbosityArgs,
}
