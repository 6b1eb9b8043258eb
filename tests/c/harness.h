/* The test groups of the C ABI harness (one file each). */
#ifndef LAMELLA_HARNESS_H
#define LAMELLA_HARNESS_H

#include "cylinder.h"
#include "hypar.h"
#include "lamella.h"

/* Versions, status names, error messages, the panic guard. */
void test_basics(void);
/* Mesh lifecycle, accessors, OBJ files (written into `scratch_dir`) and every invalid input. */
void test_mesh(const char *scratch_dir);
/* Field parameters and every invalid input of a field session. */
void test_field_inputs(const Cylinder *cylinder);
/* The real solve: theta = 60 degrees step by step on the cylinder, checked against its geometry.
 * Returns the converged session (owned by the caller) or NULL. */
LmlField *test_solve(const Cylinder *cylinder);
/* The frames of a converged field on the cylinder against its analytic normal (radial): at every
 * interior vertex a unit binormal at the signed angle `theta` (within `tolerance_degrees`) and a
 * tangent side vector. */
void check_cylinder_frames(const LmlField *field, const Cylinder *cylinder, double theta, double tolerance_degrees);
/* Handles moved between threads, different handles used concurrently, per-thread messages. */
void test_threads(const Cylinder *cylinder);
/* Save / load round trip of a session and corrupted, truncated and future-version data. */
void test_session(LmlField *field);
/* Level curves of the converged session: lifecycle, every invalid input, geometry on the
 * cylinder, the same curves from a restored session. Returns 3 curves resampled at spacing 1
 * (owned by the caller) or NULL. */
LmlCurves *test_curves(const LmlField *field, const Cylinder *cylinder);
/* Strips on `curves` (taken over and freed): parameters, every invalid input, Table 4 metrics
 * and independent checks of planarity, unrolling and width; skipped curves. */
void test_strips(const LmlField *field, LmlCurves *curves);
/* The default start search on a (small) cylinder: every invalid input, stepping until done,
 * candidates, texts and winner, the field taken once and converged; theta 60, and theta 90 and 0
 * named geodesics (helices) and asymptotic curves (rulings). */
void test_search(const Cylinder *cylinder);
/* Guide curves on the cylinder: boundary starts, traced 60 degree P-curves against the mesh
 * normals, crossings and the order check, initial fields from guides (then solved) and from
 * strokes along them, and every invalid input. */
void test_guides(const Cylinder *cylinder);
/* The workshop plan of strips on `curves` (not taken over): material presets, stock, every
 * invalid input, the strain of each strip against an independent curvature computation, pieces
 * covering their strips with the overlaps, the DXF's layers, piece ids and the bill of materials. */
void test_fabrication(const LmlCurves *curves);
/* The viewer page of strips on `curves` (not taken over): the two-call pattern, a
 * self-contained page with every strip and its figures, the title escaped, the same bytes twice,
 * the bounding box around every strip vertex, the utilisation, every invalid input. */
void test_view(const LmlCurves *curves);

/* A net of two families (geodesic circles and rulings on the cylinder): every invalid input,
 * stepping to convergence, both fields with the two-call pattern against the cylinder's axis,
 * strips on both families with their quad net and nodes. */
void test_net(const Cylinder *cylinder);
/* Field `k` of a net or 3-web session (`n` values, owned by the caller), or NULL when it cannot
 * be read. */
double *net_field(const LmlNet *net, unsigned k, size_t n);
/* Saves a net or 3-web session, restores it, and steps both five iterations: every field and the
 * reports keep the same bits; damaged bytes, a reshape session's magic and NULL arguments are
 * refused. */
void check_net_save_and_restore(LmlNet *net, size_t n);

/* A 3-web (Sec. 4.2) on a hyperbolic paraboloid: the AAG web from the asymptotic net's default
 * start, stepped to convergence, Eq. 18 from the fields read back, the strips of its three
 * families with the web of triangles and the Kagome pattern and their nodes, a saved session
 * restored, every invalid input; then the web of triangles optimised (test_base_mesh_web). */
void test_web(void);

/* Base-mesh optimisation (Sec. 3.5) of the AAG web of triangles `web` of z = xy/5 (its arrays
 * `arrays`) near `reference`: from the strip web and from flat arrays (the same session), stepped
 * to convergence; the diagonals' binormals against the exact normal before and after, the rows and
 * columns tangent, the vertices on the surface, the family reports, the triangles, the diagonals'
 * strips, save and restore, every invalid input. */
void test_base_mesh_web(const LmlMesh *reference, const LmlStripWeb *web, const WebArrays *arrays);

/* Surface optimisation (Sec. 3.3) of the cylinder towards 45 degrees within an absolute tolerance:
 * every invalid input, stepping, positions and deviations against the distance from the axis. */
void test_reshape(const Cylinder *cylinder);

/* The alternating schedule (Sec. 3.3) of field and surface steps on the cylinder towards 45
 * degrees within an absolute tolerance: every invalid input, stepping by rounds, positions,
 * field and deviations, and the resulting level curves against the moved surface's normals. */
void test_alternation(const Cylinder *cylinder);

/* Base-mesh optimisation (Sec. 3.5) with torsion-free nodes (Sec. 5.2.1) on a finer patch of the
 * cylinder: the net of +-45 degree helices, perturbed, stepped to convergence: every invalid input,
 * the vertices back on the cylinder and geodesic, the nodes' ruling angles, the strips of both
 * families (planar quads, the rulings at the nodes). */
void test_base_mesh(void);
/* Saves a base-mesh session (stepped 3 iterations), restores it, and steps both five iterations:
 * the same reports (every family's) and positions, to the bit. Truncated and damaged bytes, a net
 * session's magic, a future version and NULL arguments are refused. */
void check_base_mesh_save_and_restore(LmlBaseMesh *session);

/* Constant-slope families on the cylinder: every invalid input, the start field and the solve
 * about its axis (helices, straight in the development at the slope), and the boundary of the
 * reachable region about an axis across it (the ruling where the tangent planes have the slope). */
void test_slope(const Cylinder *cylinder);

/* Shading designs (Sec. 6) on a small vertical facade, from the paper's start and from a given
 * field: every invalid input, stepping, strips with one theta per curve against the noon sun's
 * elevation, the sun-path check's blocked fraction, and the strips' verdict status on a twisted
 * facade. */
void test_shading(void);
#endif
