/* A 3-web of three families through the C ABI (paper Sec. 4.2): on the hyperbolic paraboloid
 * z = xy/5, the AAG web (its rulings and geodesic diagonals) started from the default start of the
 * asymptotic net, stepped to convergence; Eq. 18 checked from the three fields read back; the
 * strips of the three families on the web's even-pace levels, the web of triangles and the Kagome
 * pattern of triangles and hexagons, their polylines and nodes, the nodes against the strips'
 * centre lines; a saved session restored and stepped in step with the original; every invalid
 * input refused with a message naming it. */
#include "check.h"
#include "harness.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Levels asked of the first two families, the strips' width, the iteration cap. */
#define WEB_LEVELS 6
#define STRIP_WIDTH 0.25
#define WEB_BUDGET 300
/* The largest |F + G + H| at a vertex of the converged web, as a fraction of the largest field's
 * range (the bound; the fields keep their scale, see FIELD_SCALE_KEPT). */
#define EQ18_TOLERANCE 1e-6
/* The converged fields' largest range is at least this fraction of G's range at the start: they
 * do not shrink toward constants (where Eq. 18 would hold trivially). */
#define FIELD_SCALE_KEPT 0.2

/* The centre lines of one family's strips. */
typedef struct {
    size_t count;
    size_t *offsets;
    double *centres;
} CentreLines;

/* max - min of `n` values. */
static double field_range(const double *values, size_t n)
{
    double low = INFINITY, high = -INFINITY;
    size_t v;
    for (v = 0; v < n; v++) {
        low = fmin(low, values[v]);
        high = fmax(high, values[v]);
    }
    return high - low;
}

/* The centre lines of `strips`; whether they were read. */
static int read_centres(const LmlStrips *strips, CentreLines *lines)
{
    size_t needed = 0, offsets = 0, doubles = 0;
    memset(lines, 0, sizeof *lines);
    CHECK_STATUS(lml_strips_count(strips, &lines->count), LML_STATUS_OK);
    CHECK_STATUS(lml_strips_point_offsets(strips, NULL, 0, &offsets), LML_STATUS_BUFFER_TOO_SMALL);
    CHECK_STATUS(lml_strips_centres(strips, NULL, 0, &doubles), lines->count > 0 ? LML_STATUS_BUFFER_TOO_SMALL : LML_STATUS_OK);
    lines->offsets = allocate(offsets, sizeof(size_t));
    lines->centres = allocate(doubles, sizeof(double));
    if (lines->offsets == NULL || lines->centres == NULL) {
        return 0;
    }
    CHECK_STATUS(lml_strips_point_offsets(strips, lines->offsets, offsets, &needed), LML_STATUS_OK);
    CHECK_STATUS(lml_strips_centres(strips, lines->centres, doubles, &needed), LML_STATUS_OK);
    return 1;
}

/* The point at arc length `arc` along strip `s`'s centre line (clamped to its ends). */
static void point_at_arc_length(const CentreLines *lines, size_t s, double arc, double *out)
{
    size_t first = lines->offsets[s], last = lines->offsets[s + 1], i;
    double left = arc > 0.0 ? arc : 0.0;
    for (i = first; i + 1 < last; i++) {
        const double *a = lines->centres + 3 * i, *b = lines->centres + 3 * (i + 1);
        double length = distance(a, b);
        if (left <= length && length > 0.0) {
            double t = left / length;
            int c;
            for (c = 0; c < 3; c++) {
                out[c] = a[c] + t * (b[c] - a[c]);
            }
            return;
        }
        left -= length;
    }
    memcpy(out, lines->centres + 3 * (last - 1), 3 * sizeof(double));
}

static int finite3(const double *v)
{
    return isfinite(v[0]) && isfinite(v[1]) && isfinite(v[2]);
}

/* The structure shared by both kinds of web, judged from the arrays: vertices crossings of two or
 * three families (exactly `families` when it is not 0), levels and face indices in range,
 * polylines along one level each, nodes where two strips cross, at their arc lengths. Returns the
 * number of vertices where three families meet. */
static size_t check_web(const WebArrays *a, const size_t level_count[3], const CentreLines lines[3], double mean_edge, int families)
{
    size_t v, f, p, i, triple = 0, worst_node = 0;
    double worst = 0.0;
    for (v = 0; v < a->vertex_count; v++) {
        int k, through = 0;
        CHECK(finite3(a->xyz + 3 * v));
        for (k = 0; k < 3; k++) {
            int64_t level = a->levels[3 * v + k];
            CHECK(level >= -1 && level < (int64_t)level_count[k]);
            through += level >= 0;
        }
        CHECK(families == 0 ? (through == 2 || through == 3) : through == families);
        triple += through == 3;
    }
    for (f = 0, i = 0; f < a->face_count; f++) {
        size_t corner;
        CHECK(i + a->face_sizes[f] <= a->face_index_count);
        for (corner = 0; corner < a->face_sizes[f] && i < a->face_index_count; corner++, i++) {
            CHECK(a->faces[i] < a->vertex_count);
        }
    }
    CHECK(i == a->face_index_count);
    for (v = 0; v < 3; v++) {
        for (p = 0, i = 0; p < a->polyline_count[v]; p++) {
            size_t end = i + a->polyline_sizes[v][p];
            CHECK(a->polyline_sizes[v][p] >= 2 && end <= a->polyline_index_count[v] && a->polyline_levels[v][p] < level_count[v]);
            for (; i < end && i < a->polyline_index_count[v]; i++) {
                uint32_t w = a->polyline_vertices[v][i];
                CHECK(w < a->vertex_count);
                if (w < a->vertex_count) {
                    CHECK(a->levels[3 * w + v] == (int64_t)a->polyline_levels[v][p]);
                }
            }
        }
        CHECK(i == a->polyline_index_count[v]);
    }
    for (i = 0; i < a->node_count; i++) {
        const LmlWebNode *node = a->nodes + i;
        const LmlNode *n = &node->node;
        double axis = sqrt(n->axis[0] * n->axis[0] + n->axis[1] * n->axis[1] + n->axis[2] * n->axis[2]);
        int side;
        CHECK(node->families[0] < node->families[1] && node->families[1] <= 2 && node->reserved == 0);
        CHECK(n->vertex < a->vertex_count);
        if (node->families[1] > 2 || n->vertex >= a->vertex_count) {
            continue;
        }
        CHECK(memcmp(n->position, a->xyz + 3 * n->vertex, sizeof n->position) == 0);
        CHECK(finite3(n->position) && finite3(n->axis) && fabs(axis - 1.0) < 1e-9);
        CHECK(n->ruling_angle_degrees >= 0.0 && n->ruling_angle_degrees <= 90.0);
        for (side = 0; side < 2; side++) {
            uint32_t k = node->families[side];
            double on_strip[3], off;
            CHECK(a->levels[3 * n->vertex + k] >= 0);
            CHECK(n->strips[side] < lines[k].count);
            CHECK(isfinite(n->arc_lengths[side]) && isfinite(n->conical_curvature[side]) && isfinite(n->darboux_angle_degrees[side]) &&
                  isfinite(n->binormal_offset[side]));
            if (n->strips[side] >= lines[k].count) {
                continue;
            }
            point_at_arc_length(lines + k, (size_t)n->strips[side], n->arc_lengths[side], on_strip);
            off = distance(on_strip, n->position) / mean_edge;
            CHECK(off <= 2.0);
            if (off > worst) {
                worst = off;
                worst_node = i;
            }
        }
    }
    printf("  web: %lu vertices (%lu triple), %lu faces, %lu nodes, the farthest (node %lu) %.2f mean edges from its strip's arc length\n",
           (unsigned long)a->vertex_count, (unsigned long)triple, (unsigned long)a->face_count, (unsigned long)a->node_count,
           (unsigned long)worst_node, worst);
    return triple;
}

/* The levels of family `k` of `net` (count_f = count_h = WEB_LEVELS), their number in `*count`. */
static double *levels_of(const LmlNet *net, int kagome, uint32_t k, size_t *count)
{
    size_t needed = 0;
    double *levels;
    *count = 0;
    CHECK_STATUS(lml_web_levels(net, WEB_LEVELS, WEB_LEVELS, (uint32_t)kagome, k, NULL, 0, count), LML_STATUS_BUFFER_TOO_SMALL);
    levels = allocate(*count, sizeof(double));
    if (levels != NULL) {
        CHECK_STATUS(lml_web_levels(net, WEB_LEVELS, WEB_LEVELS, (uint32_t)kagome, k, levels, *count, &needed), LML_STATUS_OK);
    }
    return levels;
}

/* Strips of family `k` at θ `theta` on the web's levels, or NULL. */
static LmlStrips *web_strips(const LmlNet *net, uint32_t k, int kagome, double theta, double spacing)
{
    LmlCurves *curves = NULL;
    LmlStrips *strips = NULL;
    LmlStripParams params;
    LmlStatus status;
    size_t count = 0, needed = 0, c;
    double *levels;
    CHECK_STATUS(lml_curves_new_from_web(net, k, WEB_LEVELS, WEB_LEVELS, (uint32_t)kagome, spacing, &curves), LML_STATUS_OK);
    CHECK_STATUS(lml_strip_params_default(theta, STRIP_WIDTH, &params), LML_STATUS_OK);
    /* A few rounds suffice here (the nodes are checked, not the strips' angles), and keep the
     * test quick under valgrind. */
    params.binormal_rounds = 2;
    params.iterations_per_round = 8;
    params.final_iterations = 15;
    params.polish_iterations = 10;
    if (curves == NULL) {
        return NULL;
    }
    /* Every curve lies on one of the family's levels. */
    levels = levels_of(net, kagome, k, &count);
    CHECK_STATUS(lml_curves_levels(curves, NULL, 0, &needed), LML_STATUS_BUFFER_TOO_SMALL);
    if (levels != NULL) {
        double *curve_levels = allocate(needed, sizeof(double));
        if (curve_levels != NULL) {
            size_t curve_count = needed;
            CHECK_STATUS(lml_curves_levels(curves, curve_levels, curve_count, &needed), LML_STATUS_OK);
            for (c = 0; c < curve_count; c++) {
                size_t l;
                int found = 0;
                for (l = 0; l < count; l++) {
                    found |= curve_levels[c] == levels[l];
                }
                CHECK(found);
            }
        }
        free(curve_levels);
    }
    free(levels);
    status = lml_strips_new(curves, &params, &strips);
    CHECK(status == LML_STATUS_OK || status == LML_STATUS_NO_ACCEPTABLE_FAMILY);
    lml_curves_free(curves);
    return strips;
}

/* The web of triangles and the Kagome pattern of the converged AAG web (on `mesh`); the web of
 * triangles then optimised (test_base_mesh_web). */
static void check_strip_webs(const LmlNet *net, const LmlMesh *mesh, double mean_edge)
{
    const double thetas[3] = {0.0, 0.0, 90.0};
    LmlStrips *strips[3] = {NULL, NULL, NULL}, *kagome_strips = NULL;
    LmlStripWeb *web = NULL, *kagome = NULL;
    CentreLines lines[3], kagome_lines[3];
    WebArrays a;
    size_t level_count[3], kagome_count[3], f, triangles = 0, hexagons = 0, triple;
    uint32_t k;
    double *levels;

    memset(lines, 0, sizeof lines);
    memset(kagome_lines, 0, sizeof kagome_lines);
    memset(&a, 0, sizeof a);
    for (k = 0; k < 3; k++) {
        levels = levels_of(net, 0, k, &level_count[k]);
        /* Increasing levels, one pace in the first two families. */
        for (f = 1; levels != NULL && f < level_count[k]; f++) {
            CHECK(levels[f] > levels[f - 1]);
        }
        free(levels);
        levels = levels_of(net, 1, k, &kagome_count[k]);
        free(levels);
        strips[k] = web_strips(net, k, 0, thetas[k], mean_edge);
        if (strips[k] == NULL || !read_centres(strips[k], lines + k)) {
            goto done;
        }
    }
    printf("  web levels: %lu, %lu, %lu (Kagome: third family %lu); strips %lu, %lu, %lu\n", (unsigned long)level_count[0],
           (unsigned long)level_count[1], (unsigned long)level_count[2], (unsigned long)kagome_count[2], (unsigned long)lines[0].count,
           (unsigned long)lines[1].count, (unsigned long)lines[2].count);
    CHECK(level_count[0] >= WEB_LEVELS && level_count[1] >= WEB_LEVELS && level_count[2] >= WEB_LEVELS);
    CHECK(kagome_count[0] == level_count[0] && kagome_count[1] == level_count[1] && kagome_count[2] >= WEB_LEVELS);

    /* Invalid inputs of the web. */
    CHECK_STATUS(lml_strip_web_new(net, WEB_LEVELS, WEB_LEVELS, 0, strips[0], NULL, strips[2], &web), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("strips_h");
    CHECK(web == NULL);
    CHECK_STATUS(lml_strip_web_new(NULL, WEB_LEVELS, WEB_LEVELS, 0, strips[0], strips[1], strips[2], &web), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("net");
    CHECK_STATUS(lml_strip_web_new(net, WEB_LEVELS, WEB_LEVELS, 0, strips[0], strips[1], strips[2], NULL), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("out");
    CHECK_STATUS(lml_strip_web_new(net, WEB_LEVELS, WEB_LEVELS, 2, strips[0], strips[1], strips[2], &web), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("kagome");
    CHECK_STATUS(lml_strip_web_new(net, 0, WEB_LEVELS, 0, strips[0], strips[1], strips[2], &web), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("count_f");
    /* Strips of another family, and strips for other counts of levels, lie on no level of the web. */
    CHECK_STATUS(lml_strip_web_new(net, WEB_LEVELS, WEB_LEVELS, 0, strips[2], strips[1], strips[0], &web), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("strips_f");
    CHECK_STATUS(lml_strip_web_new(net, WEB_LEVELS + 1, WEB_LEVELS + 1, 0, strips[0], strips[1], strips[2], &web), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("lml_curves_new_from_web");
    CHECK(web == NULL);

    /* The web of triangles: its edges run along the three families. */
    CHECK_STATUS(lml_strip_web_new(net, WEB_LEVELS, WEB_LEVELS, 0, strips[0], strips[1], strips[2], &web), LML_STATUS_OK);
    if (web == NULL || !read_web(web, &a)) {
        goto done;
    }
    CHECK(a.face_index_count == 3 * a.face_count && a.face_count >= 40);
    for (f = 0; f < a.face_count; f++) {
        CHECK(a.face_sizes[f] == 3);
    }
    triple = check_web(&a, level_count, lines, mean_edge, 0);
    CHECK(triple >= 10 && a.node_count >= 2 * triple);
    CHECK(a.polyline_count[0] >= 3 && a.polyline_count[1] >= 3 && a.polyline_count[2] >= 3);
    /* Accessors' invalid inputs. */
    CHECK_STATUS(lml_strip_web_polyline_sizes(web, 3, NULL, 0, &f), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("family");
    CHECK_STATUS(lml_strip_web_polyline_levels(web, 3, NULL, 0, &f), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("family");
    CHECK_STATUS(lml_strip_web_polyline_vertices(NULL, 0, NULL, 0, &f), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("web");
    CHECK_STATUS(lml_strip_web_vertices(web, NULL, 0, NULL), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("needed");
    CHECK_STATUS(lml_strip_web_nodes(web, a.nodes, a.node_count - 1, &f), LML_STATUS_BUFFER_TOO_SMALL);
    CHECK(f == a.node_count);
    test_base_mesh_web(mesh, web, &a);
    free_web_arrays(&a);

    /* The Kagome pattern: the third family shifted by half a pace, every crossing of two families. */
    kagome_strips = web_strips(net, 2, 1, 90.0, mean_edge);
    if (kagome_strips == NULL || !read_centres(kagome_strips, kagome_lines + 2)) {
        goto done;
    }
    kagome_lines[0] = lines[0];
    kagome_lines[1] = lines[1];
    /* The web's third strips lie between the Kagome pattern's levels. */
    CHECK_STATUS(lml_strip_web_new(net, WEB_LEVELS, WEB_LEVELS, 1, strips[0], strips[1], strips[2], &kagome), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("strips_g");
    CHECK_STATUS(lml_strip_web_new(net, WEB_LEVELS, WEB_LEVELS, 1, strips[0], strips[1], kagome_strips, &kagome), LML_STATUS_OK);
    if (kagome != NULL && read_web(kagome, &a)) {
        for (f = 0; f < a.face_count; f++) {
            CHECK(a.face_sizes[f] == 3 || a.face_sizes[f] == 6);
            triangles += a.face_sizes[f] == 3;
            hexagons += a.face_sizes[f] == 6;
        }
        CHECK(a.face_index_count == 3 * triangles + 6 * hexagons);
        printf("  Kagome: %lu triangles, %lu hexagons\n", (unsigned long)triangles, (unsigned long)hexagons);
        CHECK(hexagons >= 5 && triangles >= hexagons);
        CHECK(check_web(&a, kagome_count, kagome_lines, mean_edge, 2) == 0);
        CHECK(a.node_count * 2 >= a.vertex_count);
    }

done:
    free(kagome_lines[2].offsets);
    free(kagome_lines[2].centres);
    free_web_arrays(&a);
    lml_strip_web_free(web);
    lml_strip_web_free(kagome);
    lml_strip_web_free(NULL);
    lml_strips_free(kagome_strips);
    for (k = 0; k < 3; k++) {
        lml_strips_free(strips[k]);
        free(lines[k].offsets);
        free(lines[k].centres);
    }
}

/* Every invalid input of the web's session functions, with a net of two families `net` where a
 * web is needed. */
static void refuse_invalid(const LmlMesh *mesh, const LmlNet *web, const LmlNet *net, const double *fields, size_t n)
{
    const double aag[3] = {0.0, 0.0, 90.0}, wide[3] = {0.0, 0.0, 200.0};
    LmlNet *out = NULL;
    LmlCurves *curves = NULL;
    LmlWebReport report;
    uint32_t count = 0;
    size_t needed = 0;
    double value;

    CHECK_STATUS(lml_web_new(NULL, aag, fields, n, 30.0, NAN, &out), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("mesh");
    CHECK(out == NULL);
    CHECK_STATUS(lml_web_new(mesh, NULL, fields, n, 30.0, NAN, &out), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("thetas");
    CHECK_STATUS(lml_web_new(mesh, wide, fields, n, 30.0, NAN, &out), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("thetas[2]");
    CHECK_STATUS(lml_web_new(mesh, aag, fields, n - 1, 30.0, NAN, &out), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("argument `n`");
    CHECK_STATUS(lml_web_new(mesh, aag, NULL, n, 30.0, NAN, &out), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("initial_fields");
    CHECK_STATUS(lml_web_new(mesh, aag, fields, n, 95.0, NAN, &out), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("min_intersection_degrees");
    CHECK_STATUS(lml_web_new(mesh, aag, fields, n, 30.0, 0.0, &out), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("intersection_degrees");
    CHECK_STATUS(lml_web_new(mesh, aag, fields, n, 30.0, NAN, NULL), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("out");
    CHECK(out == NULL);

    CHECK_STATUS(lml_net_family_count(web, &count), LML_STATUS_OK);
    CHECK(count == 3);
    CHECK_STATUS(lml_net_family_count(net, &count), LML_STATUS_OK);
    CHECK(count == 2);
    CHECK_STATUS(lml_net_family_count(web, NULL), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("count");
    CHECK_STATUS(lml_net_family_count(NULL, &count), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("net");

    CHECK_STATUS(lml_net_field(web, 3, NULL, 0, &needed), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("argument `k`");
    CHECK_STATUS(lml_net_field(net, 2, NULL, 0, &needed), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("argument `k`");
    CHECK_STATUS(lml_net_field(web, 2, NULL, 0, &needed), LML_STATUS_BUFFER_TOO_SMALL);
    CHECK(needed == n);

    CHECK_STATUS(lml_net_web_report(net, &report), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("net of two families");
    CHECK_STATUS(lml_net_web_report(web, NULL), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("report");
    CHECK_STATUS(lml_net_web_report(NULL, &report), LML_STATUS_INVALID_ARGUMENT);

    CHECK_STATUS(lml_web_levels(net, WEB_LEVELS, WEB_LEVELS, 0, 0, NULL, 0, &needed), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("net of two families");
    CHECK_STATUS(lml_web_levels(web, WEB_LEVELS, WEB_LEVELS, 2, 0, NULL, 0, &needed), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("kagome");
    CHECK_STATUS(lml_web_levels(web, 0, WEB_LEVELS, 0, 0, NULL, 0, &needed), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("count_f");
    CHECK_STATUS(lml_web_levels(web, WEB_LEVELS, LML_MAX_LEVELS + 1, 0, 0, NULL, 0, &needed), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("count_h");
    CHECK_STATUS(lml_web_levels(web, WEB_LEVELS, WEB_LEVELS, 0, 3, NULL, 0, &needed), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("argument `k`");
    CHECK_STATUS(lml_web_levels(web, WEB_LEVELS, WEB_LEVELS, 0, 0, &value, 1, NULL), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("needed");
    CHECK_STATUS(lml_web_levels(NULL, WEB_LEVELS, WEB_LEVELS, 0, 0, NULL, 0, &needed), LML_STATUS_INVALID_ARGUMENT);

    CHECK_STATUS(lml_curves_new_from_web(web, 3, WEB_LEVELS, WEB_LEVELS, 0, 0.0, &curves), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("argument `k`");
    CHECK(curves == NULL);
    CHECK_STATUS(lml_curves_new_from_web(net, 0, WEB_LEVELS, WEB_LEVELS, 0, 0.0, &curves), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("net of two families");
    CHECK_STATUS(lml_curves_new_from_web(web, 0, WEB_LEVELS, 0, 0, 0.0, &curves), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("count_h");
    CHECK_STATUS(lml_curves_new_from_web(web, 0, WEB_LEVELS, WEB_LEVELS, 2, 0.0, &curves), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("kagome");
    CHECK_STATUS(lml_curves_new_from_web(web, 0, WEB_LEVELS, WEB_LEVELS, 0, -1.0, &curves), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("spacing");
    CHECK_STATUS(lml_curves_new_from_web(web, 0, WEB_LEVELS, WEB_LEVELS, 0, 0.0, NULL), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("out");
    CHECK(curves == NULL);
}

void test_web(void)
{
    static Hypar h;
    const double aag[3] = {0.0, 0.0, 90.0};
    LmlMesh *mesh = NULL;
    LmlNet *web = NULL, *net = NULL;
    LmlNetReport report;
    LmlWebReport web_report;
    LmlStatus status = LML_STATUS_MORE;
    size_t n, v, needed = 0;
    unsigned steps = 0, k;
    double *fields, *values[3] = {NULL, NULL, NULL}, range = 0.0, worst = 0.0, start_range = 0.0;

    hypar_generate(&h);
    n = h.n;
    fields = allocate(2 * n, sizeof(double));
    CHECK_STATUS(lml_mesh_new(h.xyz, h.n, h.triangles, h.m, &mesh), LML_STATUS_OK);
    if (fields == NULL || mesh == NULL) {
        free(fields);
        lml_mesh_free(mesh);
        return;
    }
    /* The web starts from the asymptotic net's default start (its F and H). */
    CHECK_STATUS(lml_net_start(mesh, 0.0, 0.0, 30.0, fields, 2 * n, &needed), LML_STATUS_OK);
    CHECK_STATUS(lml_web_new(mesh, aag, fields, n, 30.0, NAN, &web), LML_STATUS_OK);
    CHECK_STATUS(lml_net_new(mesh, 0.0, 0.0, fields, n, 30.0, NAN, &net), LML_STATUS_OK);
    if (web == NULL || net == NULL) {
        goto done;
    }
    refuse_invalid(mesh, web, net, fields, n);
    lml_net_free(net);
    net = NULL;

    /* Before any step G = -F - H, and the third family starts at a tenth of its weight. */
    CHECK_STATUS(lml_net_web_report(web, &web_report), LML_STATUS_OK);
    CHECK(web_report.residual_max <= 1e-12 && web_report.third_family_factor < 1.0);
    values[2] = net_field(web, 2, n);
    start_range = values[2] == NULL ? 0.0 : field_range(values[2], n);
    free(values[2]);
    values[2] = NULL;
    status = lml_net_step(web, 10, &report);
    steps++;
    check_net_save_and_restore(web, n);
    while (status == LML_STATUS_MORE && steps * 10 < WEB_BUDGET) {
        status = lml_net_step(web, 10, &report);
        steps++;
    }
    CHECK(status == LML_STATUS_CONVERGED);
    CHECK_STATUS(lml_net_web_report(web, &web_report), LML_STATUS_OK);
    printf("  AAG web: %s after %lu iterations; rulings %.2f/%.2f deg RMS, geodesics %.2f deg RMS (%.2f max), "
           "|F+G+H| %.3g max, %.3g RMS of the range; third family at %.1f and %.1f deg on average (min %.1f, %.1f)\n",
           lml_status_name(status), (unsigned long)report.iterations, report.angle_error_rms_degrees[0], report.angle_error_rms_degrees[1],
           web_report.angle_error_rms_degrees, web_report.angle_error_max_degrees, web_report.residual_max, web_report.residual_rms,
           web_report.mean_intersection_degrees[0], web_report.mean_intersection_degrees[1], web_report.min_intersection_degrees[0],
           web_report.min_intersection_degrees[1]);
    CHECK(web_report.third_family_factor == 1.0);
    CHECK(web_report.residual_max <= EQ18_TOLERANCE && web_report.residual_rms <= web_report.residual_max);
    CHECK(isfinite(web_report.angle_error_rms_degrees) && isfinite(web_report.angle_error_max_degrees) && isfinite(web_report.residual_rms));
    for (k = 0; k < 2; k++) {
        CHECK(isfinite(web_report.min_intersection_degrees[k]) && isfinite(web_report.mean_intersection_degrees[k]));
        CHECK(web_report.faces_below_min[k] <= h.m);
    }
    CHECK(web_report.angle_error_rms_degrees < 5.0 && report.angle_error_rms_degrees[0] < 5.0 && report.angle_error_rms_degrees[1] < 5.0);
    CHECK(web_report.mean_intersection_degrees[0] > 30.0 && web_report.mean_intersection_degrees[1] > 30.0);

    /* Eq. 18 from the three fields read back, against the largest field range. */
    for (k = 0; k < 3; k++) {
        values[k] = net_field(web, k, n);
        if (values[k] == NULL) {
            CHECK(!"field read");
            goto done;
        }
        range = fmax(range, field_range(values[k], n));
    }
    for (v = 0; v < n; v++) {
        worst = fmax(worst, fabs(values[0][v] + values[1][v] + values[2][v]));
    }
    CHECK(worst <= EQ18_TOLERANCE * range);
    CHECK(range >= FIELD_SCALE_KEPT * start_range);
    printf("  |F+G+H| recomputed: %.3g of the range (report: %.3g); the largest field range %.3g (G's at the start %.3g)\n", worst / range,
           web_report.residual_max, range, start_range);
    CHECK(fabs(worst / range - web_report.residual_max) <= 1e-3 * web_report.residual_max + 1e-15);

    check_strip_webs(web, mesh, h.mean_edge);

done:
    for (k = 0; k < 3; k++) {
        free(values[k]);
    }
    lml_net_free(web);
    lml_net_free(net);
    lml_mesh_free(mesh);
    free(fields);
}
