/* A net of two families through the C ABI (paper Sec. 4.1): on the cylinder, the geodesic net
 * of circles (levels of the height) and rulings (levels of the angle around the axis), started
 * off both (turned heights), stepped to convergence; strips on both families, their quad net
 * and nodes; a saved session restored and stepped in step with the original; every invalid
 * input. */
#include "check.h"
#include "harness.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define NET_BUDGET 200
#define PI 3.14159265358979323846

/* The mean over the triangles of the angle in degrees between the gradient of the piecewise
 * linear `field` and the cylinder's axis (z), from the triangle's own geometry. */
static double mean_axis_angle(const Cylinder *c, const double *field)
{
    double sum = 0.0;
    size_t t, counted = 0;
    for (t = 0; t < c->triangle_count; t++) {
        const uint32_t *f = c->triangles + 3 * t;
        const double *p0 = c->xyz + 3 * f[0], *p1 = c->xyz + 3 * f[1], *p2 = c->xyz + 3 * f[2];
        double e1[3], e2[3], g[3], a11 = 0.0, a12 = 0.0, a22 = 0.0, d1, d2, det, a, b, norm;
        int k;
        for (k = 0; k < 3; k++) {
            e1[k] = p1[k] - p0[k];
            e2[k] = p2[k] - p0[k];
            a11 += e1[k] * e1[k];
            a12 += e1[k] * e2[k];
            a22 += e2[k] * e2[k];
        }
        /* g in the triangle's plane with g.e1 = f1 - f0 and g.e2 = f2 - f0. */
        d1 = field[f[1]] - field[f[0]];
        d2 = field[f[2]] - field[f[0]];
        det = a11 * a22 - a12 * a12;
        a = (d1 * a22 - d2 * a12) / det;
        b = (d2 * a11 - d1 * a12) / det;
        for (k = 0; k < 3; k++) {
            g[k] = a * e1[k] + b * e2[k];
        }
        norm = sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
        if (norm > 0.0) {
            sum += acos(fmin(1.0, fabs(g[2]) / norm)) * 180.0 / PI;
            counted++;
        }
    }
    return counted > 0 ? sum / (double)counted : 90.0;
}

/* The gridshell as built from the converged geodesic net: strips on six levels of each field,
 * the net of their levels and its nodes. Circle strips are tangent bands whose rulings run along
 * the axis; ruling strips are tangent planes whose rulings run around it: every node lies on the
 * cylinder, at a crossing of a row and a column, with rulings at right angles on average. */
static void check_strip_net(const LmlNet *net)
{
    LmlCurves *curves[2] = {NULL, NULL};
    LmlStrips *strips[2] = {NULL, NULL};
    LmlStripNet *grid = NULL;
    LmlStripParams params;
    LmlStripMetrics *metrics[2] = {NULL, NULL};
    LmlNode *nodes = NULL;
    LmlStatus status;
    uint32_t *ij = NULL, *quads = NULL;
    double *xyz = NULL, mean_angle = 0.0, worst_conical = 0.0, worst_darboux = 0.0;
    size_t k, q, i, needed = 0, count[2] = {0, 0}, vertex_count = 0, quad_count = 0, node_count = 0, defined = 0;

    CHECK_STATUS(lml_curves_new_from_net(net, 2, 6, 0.8, &curves[0]), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("k");
    CHECK(curves[0] == NULL);
    CHECK_STATUS(lml_curves_new_from_net(NULL, 0, 6, 0.8, &curves[0]), LML_STATUS_INVALID_ARGUMENT);
    CHECK_STATUS(lml_strip_params_default(90.0, 0.3, &params), LML_STATUS_OK);
    for (k = 0; k < 2; k++) {
        CHECK_STATUS(lml_curves_new_from_net(net, (uint32_t)k, 6, 0.8, &curves[k]), LML_STATUS_OK);
        status = lml_strips_new(curves[k], &params, &strips[k]);
        CHECK(status == LML_STATUS_OK || status == LML_STATUS_NO_ACCEPTABLE_FAMILY);
        if (strips[k] == NULL) {
            goto done;
        }
        CHECK_STATUS(lml_strips_count(strips[k], &count[k]), LML_STATUS_OK);
        metrics[k] = malloc((count[k] + 1) * sizeof(LmlStripMetrics));
        if (metrics[k] == NULL) {
            CHECK(!"out of memory");
            goto done;
        }
        CHECK_STATUS(lml_strips_metrics(strips[k], metrics[k], count[k], &needed), LML_STATUS_OK);
    }
    CHECK(count[0] >= 4 && count[1] >= 4);

    CHECK_STATUS(lml_strip_net_new(NULL, strips[0], strips[1], &grid), LML_STATUS_INVALID_ARGUMENT);
    CHECK_STATUS(lml_strip_net_new(net, strips[0], NULL, &grid), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("strips_g");
    CHECK(grid == NULL);
    CHECK_STATUS(lml_strip_net_new(net, strips[0], strips[1], NULL), LML_STATUS_INVALID_ARGUMENT);
    CHECK_STATUS(lml_strip_net_new(net, strips[0], strips[1], &grid), LML_STATUS_OK);
    if (grid == NULL) {
        goto done;
    }
    CHECK_STATUS(lml_strip_net_vertices(grid, NULL, 0, &vertex_count), LML_STATUS_BUFFER_TOO_SMALL);
    CHECK_STATUS(lml_strip_net_quads(grid, NULL, 0, &quad_count), LML_STATUS_BUFFER_TOO_SMALL);
    CHECK_STATUS(lml_strip_net_nodes(grid, NULL, 0, &node_count), LML_STATUS_BUFFER_TOO_SMALL);
    vertex_count /= 3;
    quad_count /= 4;
    /* Every circle carrying a strip crosses every ruling carrying one, at a node. */
    CHECK(vertex_count == count[0] * count[1] && quad_count == (count[0] - 1) * (count[1] - 1));
    CHECK(node_count == vertex_count);
    xyz = malloc(3 * vertex_count * sizeof(double) + 1);
    ij = malloc(2 * vertex_count * sizeof(uint32_t) + 1);
    quads = malloc(4 * quad_count * sizeof(uint32_t) + 1);
    nodes = malloc(node_count * sizeof(LmlNode) + 1);
    if (xyz == NULL || ij == NULL || quads == NULL || nodes == NULL) {
        CHECK(!"out of memory");
        goto done;
    }
    CHECK_STATUS(lml_strip_net_vertices(grid, xyz, 3 * vertex_count, &needed), LML_STATUS_OK);
    CHECK_STATUS(lml_strip_net_levels(grid, ij, 2 * vertex_count, &needed), LML_STATUS_OK);
    CHECK_STATUS(lml_strip_net_quads(grid, quads, 4 * quad_count, &needed), LML_STATUS_OK);
    CHECK_STATUS(lml_strip_net_nodes(grid, nodes, node_count - 1, &needed), LML_STATUS_BUFFER_TOO_SMALL);
    CHECK_STATUS(lml_strip_net_nodes(grid, nodes, node_count, &needed), LML_STATUS_OK);
    for (i = 0; i < vertex_count; i++) {
        const double *p = xyz + 3 * i;
        /* On a flat triangle: inside the cylinder by at most the sagitta of a cell's diagonal (2.2). */
        CHECK(fabs(sqrt(p[0] * p[0] + p[1] * p[1]) - CYLINDER_RADIUS) < 0.08);
    }
    /* Each quad walks (i, j), (i, j + 1), (i + 1, j + 1), (i + 1, j). */
    for (q = 0; q < quad_count; q++) {
        const uint32_t *v = quads + 4 * q;
        uint32_t a = v[0], b = v[1], c = v[2], d = v[3];
        CHECK(a < vertex_count && b < vertex_count && c < vertex_count && d < vertex_count);
        if (a < vertex_count && b < vertex_count && c < vertex_count && d < vertex_count) {
            CHECK(ij[2 * b] == ij[2 * a] && ij[2 * b + 1] == ij[2 * a + 1] + 1);
            CHECK(ij[2 * c] == ij[2 * a] + 1 && ij[2 * c + 1] == ij[2 * a + 1] + 1);
            CHECK(ij[2 * d] == ij[2 * a] + 1 && ij[2 * d + 1] == ij[2 * a + 1]);
        }
    }
    /* The rulings of the strips on the straight rulings are poorly determined (no curvature): single
     * nodes come out between 49 and 90 degrees, their mean near 90. */
    for (i = 0; i < node_count; i++) {
        const LmlNode *node = nodes + i;
        double axis = sqrt(node->axis[0] * node->axis[0] + node->axis[1] * node->axis[1] + node->axis[2] * node->axis[2]);
        CHECK(node->vertex < vertex_count && node->strips[0] < count[0] && node->strips[1] < count[1]);
        if (node->vertex >= vertex_count || node->strips[0] >= count[0] || node->strips[1] >= count[1]) {
            continue;
        }
        CHECK(memcmp(node->position, xyz + 3 * node->vertex, sizeof node->position) == 0);
        for (k = 0; k < 2; k++) {
            CHECK(node->arc_lengths[k] >= 0.0 && node->arc_lengths[k] <= metrics[k][node->strips[k]].length + 1e-9);
        }
        CHECK(fabs(axis - 1.0) < 1e-9);
        CHECK(node->ruling_angle_degrees > 45.0 && node->ruling_angle_degrees <= 90.0);
        mean_angle += node->ruling_angle_degrees / (double)node_count;
        /* Sec. 5.1 on the first family, horizontal circles: torsion 0, so k = 0 and the binormal
         * is the ruling of the rectifying developable (the cylinder's own). */
        if (node->diagnostics_defined[0]) {
            defined++;
            worst_conical = fmax(worst_conical, fabs(node->conical_curvature[0]));
            worst_darboux = fmax(worst_darboux, node->darboux_angle_degrees[0]);
            CHECK(fabs(node->darboux_angle_degrees[0] - atan(fabs(node->conical_curvature[0])) * 180.0 / PI) < 1e-9);
            CHECK(node->binormal_offset[0] >= 0.0);
        }
        for (k = 0; k < 2; k++) {
            CHECK(node->singular_point_near[k] <= 1 && node->diagnostics_defined[k] <= 1);
            CHECK(node->diagnostics_defined[k] || (node->conical_curvature[k] == 0.0 && node->binormal_offset[k] == 0.0));
        }
    }
    CHECK(mean_angle > 80.0);
    printf("  nodes on the circles: k within %.2g, binormal-ruling angle within %.2g deg (%lu of %lu defined)\n", worst_conical,
           worst_darboux, (unsigned long)defined, (unsigned long)node_count);
    CHECK(defined * 2 >= node_count && worst_conical < 0.1 && worst_darboux < 6.0);

done:
    lml_strip_net_free(grid);
    lml_strip_net_free(NULL);
    for (k = 0; k < 2; k++) {
        lml_strips_free(strips[k]);
        lml_curves_free(curves[k]);
        free(metrics[k]);
    }
    free(xyz);
    free(ij);
    free(quads);
    free(nodes);
}

double *net_field(const LmlNet *net, unsigned k, size_t n)
{
    size_t needed = 0;
    double *values = malloc(n * sizeof(double));
    if (values != NULL && lml_net_field(net, k, values, n, &needed) != LML_STATUS_OK) {
        free(values);
        values = NULL;
    }
    return values;
}

void check_net_save_and_restore(LmlNet *net, size_t n)
{
    size_t size = 0, needed = 0;
    unsigned char *bytes;
    LmlNet *restored = NULL;
    LmlNetReport a, b;
    LmlWebReport web_a, web_b;
    uint32_t k, count = 0, restored_count = 0;

    CHECK_STATUS(lml_net_family_count(net, &count), LML_STATUS_OK);
    CHECK_STATUS(lml_net_save(net, NULL, 0, &size), LML_STATUS_BUFFER_TOO_SMALL);
    CHECK(size > 8);
    CHECK_STATUS(lml_net_save(NULL, NULL, 0, &size), LML_STATUS_INVALID_ARGUMENT);
    bytes = malloc(size);
    if (bytes == NULL) {
        CHECK(!"out of memory");
        return;
    }
    CHECK_STATUS(lml_net_save(net, bytes, size, &needed), LML_STATUS_OK);
    CHECK(needed == size && memcmp(bytes, "LMLN", 4) == 0);
    CHECK_STATUS(lml_net_load(bytes, size, &restored), LML_STATUS_OK);
    if (restored != NULL) {
        LmlStatus original = lml_net_step(net, 5, &a);
        CHECK_STATUS(lml_net_family_count(restored, &restored_count), LML_STATUS_OK);
        CHECK(restored_count == count);
        CHECK_STATUS(lml_net_step(restored, 5, &b), original);
        CHECK(a.iterations == b.iterations && memcmp(&a, &b, sizeof a) == 0);
        if (count == 3) {
            CHECK_STATUS(lml_net_web_report(net, &web_a), LML_STATUS_OK);
            CHECK_STATUS(lml_net_web_report(restored, &web_b), LML_STATUS_OK);
            CHECK(memcmp(&web_a, &web_b, sizeof web_a) == 0);
        }
        for (k = 0; k < count; k++) {
            double *mine = net_field(net, k, n), *theirs = net_field(restored, k, n);
            CHECK(mine != NULL && theirs != NULL && memcmp(mine, theirs, n * sizeof(double)) == 0);
            free(mine);
            free(theirs);
        }
        lml_net_free(restored);
    }
    restored = NULL;
    CHECK_STATUS(lml_net_load(bytes, size - 1, &restored), LML_STATUS_CORRUPT_DATA);
    CHECK(restored == NULL);
    bytes[3] = 'R'; /* "LMLR": a reshape session's magic */
    CHECK_STATUS(lml_net_load(bytes, size, &restored), LML_STATUS_CORRUPT_DATA);
    CHECK_MESSAGE("net session");
    CHECK_STATUS(lml_net_load(NULL, 5, &restored), LML_STATUS_INVALID_ARGUMENT);
    CHECK_STATUS(lml_net_load(bytes, size, NULL), LML_STATUS_INVALID_ARGUMENT);
    free(bytes);
}

void test_net(const Cylinder *c)
{
    LmlMesh *mesh = NULL;
    LmlNet *net = NULL;
    LmlNetReport report;
    LmlStatus status = LML_STATUS_MORE;
    size_t n = c->vertex_count, v, needed = 0;
    unsigned steps = 0;
    double *fields = malloc(2 * n * sizeof(double));
    double *values = malloc(n * sizeof(double));
    if (fields == NULL || values == NULL) {
        CHECK(!"out of memory");
        free(fields);
        free(values);
        return;
    }
    /* Heights along the axis and around it, each turned by 10 degrees toward the other. */
    for (v = 0; v < n; v++) {
        const double *p = c->xyz + 3 * v;
        double arc = CYLINDER_RADIUS * atan2(p[1], p[0]);
        fields[v] = p[2] + 0.18 * arc;
        fields[n + v] = arc - 0.18 * p[2];
    }
    CHECK_STATUS(lml_mesh_new(c->xyz, c->vertex_count, c->triangles, c->triangle_count, &mesh), LML_STATUS_OK);

    /* Invalid inputs, each refused with the session left NULL. */
    CHECK_STATUS(lml_net_new(NULL, 90.0, 90.0, fields, n, 30.0, NAN, &net), LML_STATUS_INVALID_ARGUMENT);
    CHECK(net == NULL);
    CHECK_STATUS(lml_net_new(mesh, 90.0, 90.0, fields, n - 1, 30.0, NAN, &net), LML_STATUS_INVALID_ARGUMENT);
    CHECK_STATUS(lml_net_new(mesh, 200.0, 90.0, fields, n, 30.0, NAN, &net), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("theta");
    CHECK_STATUS(lml_net_new(mesh, 90.0, 90.0, fields, n, 95.0, NAN, &net), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("min_intersection_degrees");
    CHECK_STATUS(lml_net_new(mesh, 90.0, 90.0, fields, n, 30.0, 180.0, &net), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("intersection_degrees");
    CHECK_STATUS(lml_net_new(mesh, 90.0, 90.0, NULL, n, 30.0, NAN, &net), LML_STATUS_INVALID_ARGUMENT);
    CHECK(net == NULL);

    /* The default start: both geodesic families from the start search, sized by the two-call pattern. */
    CHECK_STATUS(lml_net_start(mesh, 90.0, 90.0, 30.0, NULL, 0, &needed), LML_STATUS_BUFFER_TOO_SMALL);
    CHECK(needed == 2 * n);
    CHECK_STATUS(lml_net_start(mesh, 90.0, 200.0, 30.0, fields, 2 * n, &needed), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("theta");
    CHECK_STATUS(lml_net_start(NULL, 90.0, 90.0, 30.0, fields, 2 * n, &needed), LML_STATUS_INVALID_ARGUMENT);
    CHECK_STATUS(lml_net_start(mesh, 90.0, 90.0, 30.0, fields, 2 * n, &needed), LML_STATUS_OK);
    CHECK_STATUS(lml_net_new(mesh, 90.0, 90.0, fields, n, 30.0, NAN, &net), LML_STATUS_OK);
    if (net != NULL) {
        /* The started families cross: the start search kept the second across the first. */
        CHECK_STATUS(lml_net_report(net, &report), LML_STATUS_OK);
        CHECK(report.iterations == 0 && report.mean_intersection_degrees >= 45.0);
    }
    lml_net_free(net);
    net = NULL;

    /* Heights along the axis and around it, each turned by 10 degrees toward the other. */
    for (v = 0; v < n; v++) {
        const double *p = c->xyz + 3 * v;
        double arc = CYLINDER_RADIUS * atan2(p[1], p[0]);
        fields[v] = p[2] + 0.18 * arc;
        fields[n + v] = arc - 0.18 * p[2];
    }
    CHECK_STATUS(lml_net_new(mesh, 90.0, 90.0, fields, n, 30.0, 90.0, &net), LML_STATUS_OK);
    lml_mesh_free(mesh);
    if (net == NULL) {
        free(fields);
        free(values);
        return;
    }
    CHECK_STATUS(lml_net_report(net, &report), LML_STATUS_OK);
    CHECK(report.iterations == 0);
    CHECK_STATUS(lml_net_report(net, NULL), LML_STATUS_INVALID_ARGUMENT);
    CHECK_STATUS(lml_net_step(NULL, 1, &report), LML_STATUS_INVALID_ARGUMENT);
    check_net_save_and_restore(net, n);
    while (status == LML_STATUS_MORE && steps * 10 < NET_BUDGET) {
        status = lml_net_step(net, 10, &report);
        steps++;
    }
    CHECK(status == LML_STATUS_CONVERGED);
    /* Circles and rulings are geodesics of the cylinder, and they cross at right angles. */
    CHECK(report.angle_error_rms_degrees[0] < 1.0 && report.angle_error_rms_degrees[1] < 1.0);
    CHECK(report.min_intersection_degrees >= 30.0 && report.mean_intersection_degrees > 80.0);
    CHECK(report.faces_below_min == 0);

    /* The first field's level sets are circles: its values vary along the axis only. */
    CHECK_STATUS(lml_net_field(net, 0, NULL, 0, &needed), LML_STATUS_BUFFER_TOO_SMALL);
    CHECK(needed == n);
    CHECK_STATUS(lml_net_field(net, 0, values, n - 1, &needed), LML_STATUS_BUFFER_TOO_SMALL);
    CHECK_STATUS(lml_net_field(net, 2, values, n, &needed), LML_STATUS_INVALID_ARGUMENT);
    CHECK_STATUS(lml_net_field(net, 0, values, n, &needed), LML_STATUS_OK);
    /* The first field's level sets are circles: its gradient runs along the axis (z). */
    CHECK(mean_axis_angle(c, values) < 3.0);
    CHECK_STATUS(lml_net_field(net, 1, values, n, &needed), LML_STATUS_OK);
    /* The second's are rulings: its gradient is square to the axis. */
    CHECK(fabs(90.0 - mean_axis_angle(c, values)) < 3.0);
    check_strip_net(net);
    lml_net_free(net);
    lml_net_free(NULL);
    free(fields);
    free(values);
}
