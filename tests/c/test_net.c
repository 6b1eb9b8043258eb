/* A net of two families through the C ABI (paper Sec. 4.1): on the cylinder, the geodesic net
 * of circles (levels of the height) and rulings (levels of the angle around the axis), started
 * off both (turned heights), stepped to convergence; every invalid input. */
#include "check.h"
#include "harness.h"

#include <math.h>
#include <stdlib.h>

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
    lml_net_free(net);
    lml_net_free(NULL);
    free(fields);
    free(values);
}
