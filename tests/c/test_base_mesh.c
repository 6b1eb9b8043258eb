/* Base-mesh optimisation through the C ABI (paper Sec. 3.5) with torsion-free nodes (Sec. 5.2.1,
 * Eq. 21): on the cylinder, the net of +-45 degree helices (geodesics) through a diagonal grid of
 * its development, every vertex moved a little, stepped to convergence. Judged from outside: the
 * vertices back on the cylinder, geodesic against its exact normal, the nodes' ruling angles
 * recomputed from lml_base_mesh_nodes, the strips of both families made of planar quads whose
 * rulings agree at the nodes; a saved session restored and stepped in step with the original;
 * every invalid input refused with a message naming it. */
#include "check.h"
#include "harness.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846
/* Lines of the diagonal grid per direction, its spacing along the axis and around it, and the
 * largest displacement of a coordinate. */
#define LINES 40
#define STEP 1.2
#define NOISE 0.02
#define BUDGET 300
/* The reference: the harness's cylinder patch, finer than its other tests' (a cell about half the
 * net's spacing; on cells as wide as the net's the surface's facets hold the nodes off
 * torsion-free). */
#define REFERENCE_COLUMNS 72
#define REFERENCE_ROWS 40
#define STRIP_WIDTH 0.3
#define STRIP_TOLERANCE_DEGREES 1.0

/* The net: vertex (i, j) of the grid at s = 1.5 + (i + j) h / 2 around the axis and z = 7.5 +
 * (j - i) h / 2 along it, kept inside the patch with a margin; row i runs along increasing j,
 * column j along increasing i. */
typedef struct {
    size_t n;
    double xyz[3 * LINES * LINES];
    /* The rows, then the columns, one after another, and their lengths. */
    uint32_t polylines[2 * LINES * LINES];
    size_t polyline_vertex_count;
    uint32_t lengths[2 * LINES];
    size_t count[2];
    /* Per vertex: its grid indices (i, j). Per family and grid line: the polyline's index within
     * its family (-1 for fewer than two vertices) and its first vertex's index along the line. */
    int ij[2 * LINES * LINES];
    int polyline[2][LINES];
    int first[2][LINES];
} HelixNet;

/* A deterministic displacement in [-NOISE, NOISE]. */
static double noise(size_t v, int k)
{
    double x = sin(12.9898 * (double)v + 78.233 * (double)k) * 43758.5453;
    return NOISE * (2.0 * (x - floor(x)) - 1.0);
}

static void helix_net(HelixNet *net)
{
    int index[LINES][LINES];
    int i, j, k, a, b;
    memset(net, 0, sizeof *net);
    for (i = 0; i < LINES; i++) {
        for (j = 0; j < LINES; j++) {
            double s = 1.5 + (i + j) * STEP / 2.0, z = 7.5 + (j - i) * STEP / 2.0, phi = s / CYLINDER_RADIUS;
            index[i][j] = -1;
            if (s > 24.5 || z < 0.8 || z > CYLINDER_HEIGHT - 0.8) {
                continue;
            }
            index[i][j] = (int)net->n;
            net->ij[2 * net->n] = i;
            net->ij[2 * net->n + 1] = j;
            net->xyz[3 * net->n] = CYLINDER_RADIUS * cos(phi) + noise(net->n, 0);
            net->xyz[3 * net->n + 1] = CYLINDER_RADIUS * sin(phi) + noise(net->n, 1);
            net->xyz[3 * net->n + 2] = z + noise(net->n, 2);
            net->n++;
        }
    }
    /* The patch is convex in (s, z): the kept vertices of a grid line are consecutive. */
    for (k = 0; k < 2; k++) {
        for (a = 0; a < LINES; a++) {
            size_t start = net->polyline_vertex_count;
            net->polyline[k][a] = -1;
            net->first[k][a] = -1;
            for (b = 0; b < LINES; b++) {
                int v = k == 0 ? index[a][b] : index[b][a];
                if (v >= 0) {
                    if (net->first[k][a] < 0) {
                        net->first[k][a] = b;
                    }
                    net->polylines[net->polyline_vertex_count++] = (uint32_t)v;
                }
            }
            if (net->polyline_vertex_count - start < 2) {
                net->polyline_vertex_count = start;
                continue;
            }
            net->polyline[k][a] = (int)net->count[k];
            net->lengths[(k == 1 ? net->count[0] : 0) + net->count[k]] = (uint32_t)(net->polyline_vertex_count - start);
            net->count[k]++;
        }
    }
}

/* Where vertex `v` lies on its polyline of family `k`: the polyline's index and the position
 * along it, or 0 when it lies on none. */
static int place(const HelixNet *net, size_t v, int k, size_t *line, size_t *at)
{
    int a = net->ij[2 * v + k], b = net->ij[2 * v + 1 - k];
    if (net->polyline[k][a] < 0) {
        return 0;
    }
    *line = (size_t)net->polyline[k][a];
    *at = (size_t)(b - net->first[k][a]);
    return 1;
}

/* Every input the library must refuse, each with the session left NULL and the message naming it. */
static void invalid_inputs(const HelixNet *net, const LmlMesh *mesh)
{
    LmlBaseMesh *session = NULL;
    double *xyz = malloc(3 * net->n * sizeof(double));
    uint32_t *polylines = malloc(net->polyline_vertex_count * sizeof(uint32_t));
    size_t rows = net->count[0], columns = net->count[1], total = net->polyline_vertex_count;
    char vertex[64];
    if (xyz == NULL || polylines == NULL) {
        CHECK(!"out of memory");
        free(xyz);
        free(polylines);
        return;
    }
    memcpy(xyz, net->xyz, 3 * net->n * sizeof(double));
    memcpy(polylines, net->polylines, total * sizeof(uint32_t));

    CHECK_STATUS(lml_base_mesh_new(NULL, xyz, net->n, polylines, total, net->lengths, rows, columns, 90.0, 90.0, 1, &session),
                 LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("reference");
    CHECK(session == NULL);
    CHECK_STATUS(lml_base_mesh_new(mesh, NULL, net->n, polylines, total, net->lengths, rows, columns, 90.0, 90.0, 1, &session),
                 LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("xyz");
    CHECK_STATUS(lml_base_mesh_new(mesh, xyz, net->n, NULL, total, net->lengths, rows, columns, 90.0, 90.0, 1, &session),
                 LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("polyline_vertices");
    CHECK_STATUS(lml_base_mesh_new(mesh, xyz, net->n, polylines, total, NULL, rows, columns, 90.0, 90.0, 1, &session),
                 LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("polyline_lengths");
    CHECK_STATUS(lml_base_mesh_new(mesh, xyz, net->n, polylines, total, net->lengths, rows, columns, 90.0, 90.0, 1, NULL),
                 LML_STATUS_INVALID_ARGUMENT);
    CHECK_STATUS(lml_base_mesh_new(mesh, xyz, (size_t)-1, polylines, total, net->lengths, rows, columns, 90.0, 90.0, 1, &session),
                 LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("vertex_count");
    CHECK_STATUS(lml_base_mesh_new(mesh, xyz, net->n, polylines, total, net->lengths, (size_t)-1, 2, 90.0, 90.0, 1, &session),
                 LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("row_count + column_count");
    /* The lengths sum to one vertex more than the array holds. */
    CHECK_STATUS(lml_base_mesh_new(mesh, xyz, net->n, polylines, total - 1, net->lengths, rows, columns, 90.0, 90.0, 1, &session),
                 LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("polyline_lengths");
    CHECK_MESSAGE("polyline_vertex_count");
    CHECK(session == NULL);
    CHECK_STATUS(lml_base_mesh_new(mesh, xyz, net->n, polylines, total, net->lengths, rows, columns, 200.0, 90.0, 1, &session),
                 LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("theta_degrees_rows");
    CHECK_STATUS(lml_base_mesh_new(mesh, xyz, net->n, polylines, total, net->lengths, rows, columns, 90.0, NAN, 1, &session),
                 LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("theta_degrees_columns");

    /* The third vertex of the first row refers past the vertices. */
    polylines[2] = (uint32_t)net->n + 5;
    snprintf(vertex, sizeof vertex, "refers to vertex %lu", (unsigned long)net->n + 5);
    CHECK_STATUS(lml_base_mesh_new(mesh, xyz, net->n, polylines, total, net->lengths, rows, columns, 90.0, 90.0, 1, &session),
                 LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("row 0");
    CHECK_MESSAGE(vertex);
    memcpy(polylines, net->polylines, total * sizeof(uint32_t));

    xyz[3 * 7 + 1] = NAN;
    CHECK_STATUS(lml_base_mesh_new(mesh, xyz, net->n, polylines, total, net->lengths, rows, columns, 90.0, 90.0, 1, &session),
                 LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("vertex 7");
    CHECK(session == NULL);

    CHECK_STATUS(lml_base_mesh_from_strip_net(NULL, mesh, 90.0, 90.0, 1, &session), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("net");
    CHECK(session == NULL);
    free(xyz);
    free(polylines);
}

/* Defines `static TYPE *NAME(get, handle, count)`: the whole output of a two-call getter in a new
 * array (one element more: never malloc(0)), its length in `*count`; NULL when it cannot be read. */
#define TWO_CALL_READER(NAME, HANDLE, TYPE)                                                                             \
    static TYPE *NAME(LmlStatus (*get)(const HANDLE *, TYPE *, size_t, size_t *), const HANDLE *handle, size_t *count) \
    {                                                                                                                  \
        TYPE *values;                                                                                                  \
        *count = 0;                                                                                                    \
        CHECK_STATUS(get(handle, NULL, 0, count), LML_STATUS_BUFFER_TOO_SMALL);                                        \
        values = malloc((*count + 1) * sizeof(TYPE));                                                                  \
        if (values != NULL && get(handle, values, *count, count) != LML_STATUS_OK) {                                   \
            free(values);                                                                                              \
            values = NULL;                                                                                             \
        }                                                                                                              \
        return values;                                                                                                 \
    }

TWO_CALL_READER(strip_doubles, LmlStrips, double)
TWO_CALL_READER(strip_indices, LmlStrips, uint32_t)
TWO_CALL_READER(strip_offsets, LmlStrips, size_t)
TWO_CALL_READER(strip_metrics, LmlStrips, LmlStripMetrics)
TWO_CALL_READER(base_mesh_doubles, LmlBaseMesh, double)

void check_base_mesh_save_and_restore(LmlBaseMesh *session)
{
    size_t size = 0, needed = 0, count[2] = {0, 0};
    unsigned char *bytes;
    LmlBaseMesh *restored = NULL;
    LmlBaseMeshReport a, b;

    CHECK_STATUS(lml_base_mesh_save(session, NULL, 0, &size), LML_STATUS_BUFFER_TOO_SMALL);
    CHECK(size > 8);
    CHECK_STATUS(lml_base_mesh_save(NULL, NULL, 0, &size), LML_STATUS_INVALID_ARGUMENT);
    CHECK_STATUS(lml_base_mesh_save(session, NULL, 0, NULL), LML_STATUS_INVALID_ARGUMENT);
    bytes = malloc(size);
    if (bytes == NULL) {
        CHECK(!"out of memory");
        return;
    }
    CHECK_STATUS(lml_base_mesh_save(session, bytes, size - 1, &needed), LML_STATUS_BUFFER_TOO_SMALL);
    CHECK_STATUS(lml_base_mesh_save(session, bytes, size, &needed), LML_STATUS_OK);
    CHECK(needed == size && memcmp(bytes, "LMLB", 4) == 0);
    CHECK_STATUS(lml_base_mesh_load(bytes, size, &restored), LML_STATUS_OK);
    if (restored != NULL) {
        double *mine, *theirs;
        uint32_t families = 0, k;
        LmlStatus original = lml_base_mesh_step(session, 5, &a);
        CHECK_STATUS(lml_base_mesh_step(restored, 5, &b), original);
        CHECK(memcmp(&a, &b, sizeof a) == 0 && a.iterations == 8);
        CHECK_STATUS(lml_base_mesh_family_count(restored, &families), LML_STATUS_OK);
        for (k = 0; k < families; k++) {
            LmlBaseMeshFamilyReport f[2];
            CHECK_STATUS(lml_base_mesh_family_report(session, k, &f[0]), LML_STATUS_OK);
            CHECK_STATUS(lml_base_mesh_family_report(restored, k, &f[1]), LML_STATUS_OK);
            CHECK(memcmp(&f[0], &f[1], sizeof f[0]) == 0);
        }
        mine = base_mesh_doubles(lml_base_mesh_positions, session, &count[0]);
        theirs = base_mesh_doubles(lml_base_mesh_positions, restored, &count[1]);
        CHECK(mine != NULL && theirs != NULL && count[0] == count[1] && memcmp(mine, theirs, count[0] * sizeof(double)) == 0);
        free(mine);
        free(theirs);
        lml_base_mesh_free(restored);
    }
    restored = NULL;
    CHECK_STATUS(lml_base_mesh_load(bytes, size - 1, &restored), LML_STATUS_CORRUPT_DATA);
    CHECK(restored == NULL);
    CHECK_STATUS(lml_base_mesh_load(bytes, 0, &restored), LML_STATUS_CORRUPT_DATA);
    bytes[12] ^= 0xFF; /* the count of the net's vertices, now far beyond the bytes */
    CHECK_STATUS(lml_base_mesh_load(bytes, size, &restored), LML_STATUS_CORRUPT_DATA);
    CHECK(restored == NULL);
    bytes[12] ^= 0xFF;
    bytes[3] = 'N'; /* "LMLN": a net session's magic */
    CHECK_STATUS(lml_base_mesh_load(bytes, size, &restored), LML_STATUS_CORRUPT_DATA);
    CHECK_MESSAGE("not a Lamella base-mesh session");
    bytes[3] = 'B';
    bytes[4] = 99; /* a future version */
    CHECK_STATUS(lml_base_mesh_load(bytes, size, &restored), LML_STATUS_CORRUPT_DATA);
    CHECK_MESSAGE("version 99");
    CHECK_STATUS(lml_base_mesh_load(NULL, 5, &restored), LML_STATUS_INVALID_ARGUMENT);
    CHECK_STATUS(lml_base_mesh_load(bytes, size, NULL), LML_STATUS_INVALID_ARGUMENT);
    CHECK(restored == NULL);
    free(bytes);
}

/* One family's strips on the optimised net, read whole. */
typedef struct {
    LmlStrips *strips;
    size_t count, quad_count;
    LmlStripMetrics *metrics;
    size_t *offsets; /* of the centre points (and rulings) */
    double *vertices, *rulings;
    uint32_t *quads;
} FamilyStrips;

static int read_strips(FamilyStrips *f)
{
    size_t length = 0;
    CHECK_STATUS(lml_strips_count(f->strips, &f->count), LML_STATUS_OK);
    f->metrics = strip_metrics(lml_strips_metrics, f->strips, &length);
    f->offsets = strip_offsets(lml_strips_point_offsets, f->strips, &length);
    f->vertices = strip_doubles(lml_strips_vertices, f->strips, &length);
    f->rulings = strip_doubles(lml_strips_rulings, f->strips, &length);
    f->quads = strip_indices(lml_strips_quads, f->strips, &f->quad_count);
    f->quad_count /= 4;
    return f->metrics != NULL && f->offsets != NULL && f->vertices != NULL && f->rulings != NULL && f->quads != NULL;
}

static void free_strips(FamilyStrips *f)
{
    lml_strips_free(f->strips);
    free(f->metrics);
    free(f->offsets);
    free(f->vertices);
    free(f->rulings);
    free(f->quads);
}

static void difference(const double *a, const double *b, double *out)
{
    out[0] = a[0] - b[0];
    out[1] = a[1] - b[1];
    out[2] = a[2] - b[2];
}

static double norm(const double *a)
{
    return sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
}

/* |det(b - a, c - a, d - a)| over the lengths of the three edges: 0 for a planar quad a b c d,
 * the sine of the angle of d - a out of the plane of the other two for a square. */
/* The largest distance of a vertex of `session` from where the net started (`net->xyz`); -1 when
 * the positions cannot be read. */
static double largest_move(const LmlBaseMesh *session, const HelixNet *net)
{
    size_t v, needed = 0;
    double largest = -1.0, *xyz = malloc(3 * net->n * sizeof(double));
    if (xyz != NULL && lml_base_mesh_positions(session, xyz, 3 * net->n, &needed) == LML_STATUS_OK) {
        for (v = 0; v < net->n; v++) {
            double d[3];
            difference(xyz + 3 * v, net->xyz + 3 * v, d);
            largest = fmax(largest, norm(d));
        }
    }
    free(xyz);
    return largest;
}

/* The weights (paper Table 3 gives them per figure): the defaults, read back from a session, set
 * before its first iteration (a pull a million times the default holds every vertex where the net
 * was given, where the default weights move them to restore the geodesics), and refused by name
 * once it has iterated or out of range. */
static void weights(const HelixNet *net, const LmlMesh *mesh)
{
    LmlBaseMesh *held = NULL, *free_net = NULL;
    LmlBaseMeshWeights defaults, got, strong;
    LmlStatus status;
    double held_move, free_move;
    CHECK_STATUS(lml_base_mesh_weights_default(NULL), LML_STATUS_INVALID_ARGUMENT);
    CHECK_STATUS(lml_base_mesh_weights_default(&defaults), LML_STATUS_OK);
    CHECK(defaults.curve == 1.0 && defaults.fair == 1e-3 && defaults.close == 1.0 && defaults.pull == 1e-4 && defaults.torsion == 1.0);
    CHECK_STATUS(lml_base_mesh_new(mesh, net->xyz, net->n, net->polylines, net->polyline_vertex_count, net->lengths, net->count[0],
                                   net->count[1], 90.0, 90.0, 0, &held),
                 LML_STATUS_OK);
    CHECK_STATUS(lml_base_mesh_new(mesh, net->xyz, net->n, net->polylines, net->polyline_vertex_count, net->lengths, net->count[0],
                                   net->count[1], 90.0, 90.0, 0, &free_net),
                 LML_STATUS_OK);
    if (held == NULL || free_net == NULL) {
        lml_base_mesh_free(held);
        lml_base_mesh_free(free_net);
        return;
    }
    CHECK_STATUS(lml_base_mesh_weights(NULL, &got), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("base_mesh");
    CHECK_STATUS(lml_base_mesh_weights(held, NULL), LML_STATUS_INVALID_ARGUMENT);
    CHECK_STATUS(lml_base_mesh_weights(held, &got), LML_STATUS_OK);
    CHECK(memcmp(&got, &defaults, sizeof got) == 0);

    strong = defaults;
    strong.pull = -1.0;
    CHECK_STATUS(lml_base_mesh_set_weights(held, &strong), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("weights.pull");
    strong.pull = 1e-4;
    strong.curve = 0.0;
    CHECK_STATUS(lml_base_mesh_set_weights(held, &strong), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("weights.curve");
    CHECK_STATUS(lml_base_mesh_set_weights(held, NULL), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("weights");
    CHECK_STATUS(lml_base_mesh_set_weights(NULL, &defaults), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("base_mesh");
    CHECK_STATUS(lml_base_mesh_weights(held, &got), LML_STATUS_OK);
    CHECK(memcmp(&got, &defaults, sizeof got) == 0);

    strong = defaults;
    strong.pull = 100.0;
    CHECK_STATUS(lml_base_mesh_set_weights(held, &strong), LML_STATUS_OK);
    CHECK_STATUS(lml_base_mesh_weights(held, &got), LML_STATUS_OK);
    CHECK(got.pull == 100.0 && got.fair == defaults.fair);
    /* Held where it was given, the net settles at once. */
    status = lml_base_mesh_step(held, 10, NULL);
    CHECK(status == LML_STATUS_MORE || status == LML_STATUS_CONVERGED);
    CHECK_STATUS(lml_base_mesh_step(free_net, 10, NULL), LML_STATUS_MORE);
    held_move = largest_move(held, net);
    free_move = largest_move(free_net, net);
    CHECK(held_move >= 0.0 && free_move > 0.0 && held_move < 0.1 * free_move);
    printf("  base mesh weights: after 10 iterations the vertices moved by up to %.5f with the pull at 100, %.5f with the defaults\n",
           held_move, free_move);
    CHECK_STATUS(lml_base_mesh_set_weights(held, &defaults), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("weights");
    CHECK_MESSAGE("first iteration");
    lml_base_mesh_free(held);
    lml_base_mesh_free(free_net);
}

static double non_planarity(const double *xyz, const uint32_t *q)
{
    double u[3], v[3], w[3];
    difference(xyz + 3 * q[1], xyz + 3 * q[0], u);
    difference(xyz + 3 * q[2], xyz + 3 * q[0], v);
    difference(xyz + 3 * q[3], xyz + 3 * q[0], w);
    return fabs(u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) + u[2] * (v[0] * w[1] - v[1] * w[0])) /
           (norm(u) * norm(v) * norm(w));
}

/* The strip of family `f` on polyline `line`, or -1 when that polyline carries none. */
static long strip_on(const FamilyStrips *f, size_t line)
{
    size_t s;
    for (s = 0; s < f->count; s++) {
        if (f->metrics[s].curve == line) {
            return (long)s;
        }
    }
    return -1;
}

/* The strips of both families on the converged net: every invalid input; acceptable, of planar
 * quads; at every node, the rulings of the row's and the column's strips meet at the node's
 * reported angle. */
static void check_strips(const LmlBaseMesh *session, const HelixNet *net, const LmlBaseMeshNode *nodes, size_t node_count)
{
    FamilyStrips family[2];
    LmlStrips *strips = NULL;
    double worst_planarity = 0.0, worst_difference = 0.0;
    size_t i, k, q, compared = 0, expected = 0;
    memset(family, 0, sizeof family);

    CHECK_STATUS(lml_base_mesh_strips(session, 2, STRIP_WIDTH, STRIP_TOLERANCE_DEGREES, &strips), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("k");
    CHECK(strips == NULL);
    CHECK_STATUS(lml_base_mesh_strips(session, 0, -1.0, STRIP_TOLERANCE_DEGREES, &strips), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("width");
    CHECK_STATUS(lml_base_mesh_strips(session, 0, STRIP_WIDTH, 0.0, &strips), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("tolerance_degrees");
    CHECK_STATUS(lml_base_mesh_strips(NULL, 0, STRIP_WIDTH, STRIP_TOLERANCE_DEGREES, &strips), LML_STATUS_INVALID_ARGUMENT);
    CHECK_STATUS(lml_base_mesh_strips(session, 0, STRIP_WIDTH, STRIP_TOLERANCE_DEGREES, NULL), LML_STATUS_INVALID_ARGUMENT);
    for (k = 0; k < 2; k++) {
        LmlVerdict verdict;
        CHECK_STATUS(lml_base_mesh_strips(session, (uint32_t)k, STRIP_WIDTH, STRIP_TOLERANCE_DEGREES, &family[k].strips), LML_STATUS_OK);
        if (family[k].strips == NULL || !read_strips(&family[k])) {
            CHECK(!"the strips can be read");
            goto done;
        }
        CHECK_STATUS(lml_strips_verdict(family[k].strips, &verdict), LML_STATUS_OK);
        CHECK(verdict.acceptable == 1 && verdict.tolerance_degrees == STRIP_TOLERANCE_DEGREES);
        /* Every polyline of three or more vertices carries a strip. */
        CHECK(family[k].count >= net->count[k] - 4 && family[k].count <= net->count[k]);
        for (q = 0; q < family[k].quad_count; q++) {
            double planarity = non_planarity(family[k].vertices, family[k].quads + 4 * q);
            worst_planarity = fmax(worst_planarity, planarity);
        }
    }
    CHECK(worst_planarity < 1e-9);
    for (i = 0; i < node_count; i++) {
        size_t v = nodes[i].vertex, line[2], at[2];
        long s[2];
        const double *d[2];
        double cosine, angle;
        if (!nodes[i].defined || !place(net, v, 0, &line[0], &at[0]) || !place(net, v, 1, &line[1], &at[1])) {
            continue;
        }
        expected++;
        for (k = 0; k < 2; k++) {
            s[k] = strip_on(&family[k], line[k]);
        }
        if (s[0] < 0 || s[1] < 0) {
            CHECK(!"a node's polylines carry strips");
            continue;
        }
        for (k = 0; k < 2; k++) {
            d[k] = family[k].rulings + 3 * (family[k].offsets[s[k]] + at[k]);
        }
        cosine = fabs(d[0][0] * d[1][0] + d[0][1] * d[1][1] + d[0][2] * d[1][2]) / (norm(d[0]) * norm(d[1]));
        angle = acos(fmin(1.0, cosine)) * 180.0 / PI;
        worst_difference = fmax(worst_difference, fabs(angle - nodes[i].ruling_angle_degrees));
        compared++;
    }
    CHECK(compared == expected && compared > 0);
    CHECK(worst_difference < 1e-6);
    printf("  base mesh strips: %lu + %lu, quads planar within %.1e; rulings at %lu nodes as reported within %.1e deg\n",
           (unsigned long)family[0].count, (unsigned long)family[1].count, worst_planarity, (unsigned long)compared, worst_difference);
done:
    for (k = 0; k < 2; k++) {
        free_strips(&family[k]);
    }
}

/* The largest |angle - 90 degrees| between a polyline's discrete binormal and the cylinder's
 * normal at the inner vertices of family `k`, at the positions `xyz`. */
static double worst_geodesic_error(const HelixNet *net, const double *xyz, int k)
{
    const uint32_t *line = net->polylines;
    double worst = 0.0;
    size_t l, a;
    for (l = 0; l < net->count[0] + net->count[1]; line += net->lengths[l], l++) {
        if ((l >= net->count[0]) != (k == 1)) {
            continue;
        }
        for (a = 1; a + 1 < net->lengths[l]; a++) {
            worst = fmax(worst, fabs(cylinder_binormal_angle(xyz + 3 * line[a - 1], xyz + 3 * line[a], xyz + 3 * line[a + 1]) - 90.0));
        }
    }
    return worst;
}

/* The same helices as curves of constant slope about the axis (45 degrees: a helix climbs its own
 * development's diagonal): lml_base_mesh_new_slopes makes every segment climb at the slope and
 * every node's axis vertical, checked here from the positions and the nodes. */
static void slope_net(const HelixNet *net, const Cylinder *reference)
{
    const double axis[3] = {0.0, 0.0, 2.0}, zero[3] = {0.0, 0.0, 0.0};
    LmlMesh *mesh = NULL;
    LmlBaseMesh *session = NULL;
    LmlBaseMeshReport report;
    LmlBaseMeshNode *nodes;
    LmlStatus status = LML_STATUS_MORE;
    double xyz[3 * LINES * LINES], worst_slope = 0.0;
    size_t i, k, needed = 0, offset = 0, node_count = 0, vertical = 0;
    unsigned steps = 0;
    CHECK_STATUS(lml_mesh_new(reference->xyz, reference->vertex_count, reference->triangles, reference->triangle_count, &mesh), LML_STATUS_OK);
    CHECK_STATUS(lml_base_mesh_new_slopes(mesh, net->xyz, net->n, net->polylines, net->polyline_vertex_count, net->lengths, net->count[0],
                                          net->count[1], 45.0, 45.0, zero, &session),
                 LML_STATUS_INVALID_ARGUMENT);
    CHECK(session == NULL && strstr(lml_last_error_message(), "axis") != NULL);
    CHECK_STATUS(lml_base_mesh_new_slopes(mesh, net->xyz, net->n, net->polylines, net->polyline_vertex_count, net->lengths, net->count[0],
                                          net->count[1], 90.0, 45.0, axis, &session),
                 LML_STATUS_INVALID_ARGUMENT);
    CHECK(session == NULL && strstr(lml_last_error_message(), "slope_degrees_rows") != NULL);
    CHECK_STATUS(lml_base_mesh_new_slopes(mesh, net->xyz, net->n, net->polylines, net->polyline_vertex_count, net->lengths, net->count[0],
                                          net->count[1], 45.0, 45.0, axis, &session),
                 LML_STATUS_OK);
    lml_mesh_free(mesh);
    if (session == NULL) {
        return;
    }
    while (status == LML_STATUS_MORE && steps * 10 < BUDGET) {
        status = lml_base_mesh_step(session, 10, &report);
        steps++;
    }
    CHECK(status == LML_STATUS_CONVERGED && report.families_met == 1 && report.torsion_free == 1);
    CHECK(fabs(fabs(report.target_degrees[0]) - 45.0) < 1e-9 && fabs(fabs(report.target_degrees[1]) - 45.0) < 1e-9);
    CHECK_STATUS(lml_base_mesh_positions(session, xyz, 3 * net->n, &needed), LML_STATUS_OK);
    /* Every segment of every polyline at 45 degrees to the horizontal planes. */
    for (k = 0; k < 2; k++) {
        size_t line;
        for (line = 0; line < net->count[k]; line++) {
            size_t length = net->lengths[(k == 1 ? net->count[0] : 0) + line], at;
            for (at = 0; at + 1 < length; at++) {
                uint32_t a = net->polylines[offset + at], b = net->polylines[offset + at + 1];
                double e[3];
                difference(xyz + 3 * b, xyz + 3 * a, e);
                worst_slope = fmax(worst_slope, fabs(fabs(asin(e[2] / norm(e))) * 180.0 / PI - 45.0));
            }
            offset += length;
        }
    }
    CHECK(worst_slope <= 0.5);
    CHECK_STATUS(lml_base_mesh_nodes(session, NULL, 0, &node_count), LML_STATUS_BUFFER_TOO_SMALL);
    nodes = malloc(node_count * sizeof *nodes);
    if (nodes != NULL) {
        CHECK_STATUS(lml_base_mesh_nodes(session, nodes, node_count, &needed), LML_STATUS_OK);
        for (i = 0; i < node_count; i++) {
            if (nodes[i].defined && nodes[i].ruling_angle_degrees <= 0.5 && fabs(nodes[i].axis[2]) >= cos(0.5 * PI / 180.0)) {
                vertical++;
            }
        }
        CHECK(node_count > 200 && vertical == node_count);
        free(nodes);
    }
    printf("  base mesh, constant slope: %u iterations; segments within %.3f deg of 45; %zu of %zu node axes vertical within 0.5 deg\n",
           (unsigned)report.iterations, worst_slope, vertical, node_count);
    lml_base_mesh_free(session);
}

void test_base_mesh(void)
{
    Cylinder reference;
    HelixNet *net = malloc(sizeof *net);
    LmlMesh *mesh = NULL;
    LmlBaseMesh *session = NULL;
    LmlBaseMeshReport initial, report;
    LmlBaseMeshNode *nodes = NULL;
    LmlStatus status = LML_STATUS_MORE;
    double *xyz = NULL, worst_radius = 0.0, worst_node = 0.0, sagitta;
    size_t v, i, needed = 0, node_count = 0, defined = 0;
    unsigned steps = 0;
    if (net == NULL || !cylinder_generate(&reference, REFERENCE_COLUMNS, REFERENCE_ROWS, 7)) {
        CHECK(!"out of memory");
        free(net);
        return;
    }
    helix_net(net);
    CHECK_STATUS(lml_mesh_new(reference.xyz, reference.vertex_count, reference.triangles, reference.triangle_count, &mesh), LML_STATUS_OK);
    invalid_inputs(net, mesh);
    weights(net, mesh);
    slope_net(net, &reference);

    CHECK_STATUS(lml_base_mesh_new(mesh, net->xyz, net->n, net->polylines, net->polyline_vertex_count, net->lengths, net->count[0],
                                   net->count[1], 90.0, 90.0, 1, &session),
                 LML_STATUS_OK);
    lml_mesh_free(mesh);
    if (session == NULL) {
        free(net);
        cylinder_free(&reference);
        return;
    }
    CHECK_STATUS(lml_base_mesh_initial_report(session, &initial), LML_STATUS_OK);
    CHECK_STATUS(lml_base_mesh_initial_report(session, NULL), LML_STATUS_INVALID_ARGUMENT);
    CHECK_STATUS(lml_base_mesh_report(NULL, &report), LML_STATUS_INVALID_ARGUMENT);
    CHECK_STATUS(lml_base_mesh_report(session, &report), LML_STATUS_OK);
    CHECK(memcmp(&initial, &report, sizeof report) == 0);
    /* Geodesics on the cylinder: the targets are 90 degrees whichever way the polylines run. */
    CHECK(initial.iterations == 0 && initial.target_degrees[0] == 90.0 && initial.target_degrees[1] == 90.0);
    CHECK(!initial.torsion_free && initial.node_count > 0);
    CHECK_STATUS(lml_base_mesh_step(NULL, 1, &report), LML_STATUS_INVALID_ARGUMENT);
    CHECK_STATUS(lml_base_mesh_step(session, 3, NULL), LML_STATUS_MORE);
    check_base_mesh_save_and_restore(session);
    while (status == LML_STATUS_MORE && steps * 10 < BUDGET) {
        status = lml_base_mesh_step(session, 10, &report);
        steps++;
    }
    CHECK(status == LML_STATUS_CONVERGED && report.converged == 1);
    CHECK_STATUS(lml_base_mesh_step(session, 10, NULL), LML_STATUS_CONVERGED);
    CHECK(isfinite(report.energy) && isfinite(report.max_deviation) && isfinite(report.rms_deviation) && isfinite(report.max_deviation_percent));
    CHECK(report.families_met == 1 && report.torsion_free == 1);
    for (i = 0; i < 2; i++) {
        CHECK(report.measured_vertices[i] > 0 && report.angle_error_max_degrees[i] <= 1.0);
        CHECK(report.angle_error_rms_degrees[i] <= report.angle_error_max_degrees[i]);
    }

    /* Every vertex back on the cylinder: on the reference, which lies between the cylinder and
     * its chords (the sagitta of the widest cell). */
    sagitta = CYLINDER_RADIUS * (1.0 - cos(0.5 * 1.5 * CYLINDER_SPAN_DEGREES / (double)reference.columns * PI / 180.0));
    CHECK_STATUS(lml_base_mesh_positions(session, NULL, 0, &needed), LML_STATUS_BUFFER_TOO_SMALL);
    CHECK(needed == 3 * net->n);
    xyz = malloc(3 * net->n * sizeof(double));
    if (xyz != NULL) {
        CHECK_STATUS(lml_base_mesh_positions(session, xyz, 3 * net->n - 1, &needed), LML_STATUS_BUFFER_TOO_SMALL);
        CHECK_STATUS(lml_base_mesh_positions(session, xyz, 3 * net->n, NULL), LML_STATUS_INVALID_ARGUMENT);
        CHECK_STATUS(lml_base_mesh_positions(session, xyz, 3 * net->n, &needed), LML_STATUS_OK);
        for (v = 0; v < net->n; v++) {
            worst_radius = fmax(worst_radius, fabs(sqrt(xyz[3 * v] * xyz[3 * v] + xyz[3 * v + 1] * xyz[3 * v + 1]) - CYLINDER_RADIUS));
        }
        CHECK(worst_radius <= sagitta + 0.002);
        /* Geodesics from outside: binormals tangent to the cylinder. */
        CHECK(worst_geodesic_error(net, xyz, 0) <= 1.0 && worst_geodesic_error(net, xyz, 1) <= 1.0);
    }

    /* The nodes: every vertex inside a row and a column, torsion-free; the report's maximum is theirs. */
    CHECK_STATUS(lml_base_mesh_nodes(session, NULL, 0, &node_count), LML_STATUS_BUFFER_TOO_SMALL);
    nodes = malloc((node_count + 1) * sizeof(LmlBaseMeshNode));
    if (nodes != NULL) {
        CHECK_STATUS(lml_base_mesh_nodes(session, nodes, node_count - 1, &needed), LML_STATUS_BUFFER_TOO_SMALL);
        CHECK_STATUS(lml_base_mesh_nodes(session, nodes, node_count, &needed), LML_STATUS_OK);
        for (i = 0; i < node_count; i++) {
            const LmlBaseMeshNode *node = nodes + i;
            size_t line, at;
            CHECK(node->vertex < net->n && node->defined <= 1);
            if (node->vertex >= net->n) {
                continue;
            }
            CHECK(place(net, node->vertex, 0, &line, &at) && place(net, node->vertex, 1, &line, &at));
            if (node->defined) {
                defined++;
                worst_node = fmax(worst_node, node->ruling_angle_degrees);
                CHECK(fabs(norm(node->axis) - 1.0) < 1e-9);
            } else {
                CHECK(node->ruling_angle_degrees == 0.0 && norm(node->axis) == 0.0);
            }
        }
        CHECK(defined == report.node_count && worst_node == report.node_ruling_angle_max_degrees);
        CHECK(worst_node <= 0.5);
        /* The perturbed net started far from torsion-free. */
        CHECK(initial.node_ruling_angle_max_degrees > 10.0 * worst_node && initial.node_ruling_angle_max_degrees > 1.0);
        printf("  base mesh: %lu vertices, %lu iterations; families within %.3f / %.3f deg; node ruling angles %.2f -> %.3f deg "
               "(%lu nodes); |r - R| <= %.4f\n",
               (unsigned long)net->n, (unsigned long)report.iterations, report.angle_error_max_degrees[0],
               report.angle_error_max_degrees[1], initial.node_ruling_angle_max_degrees, worst_node, (unsigned long)defined, worst_radius);
        check_strips(session, net, nodes, node_count);
    }
    lml_base_mesh_free(session);
    lml_base_mesh_free(NULL);
    free(nodes);
    free(xyz);
    free(net);
    cylinder_free(&reference);
}
