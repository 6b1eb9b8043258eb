#include "cylinder.h"

#include <math.h>
#include <stdlib.h>

#define PI 3.14159265358979323846

/* xorshift64*: a deterministic jitter in [-0.5, 0.5). */
static double jitter(uint64_t *state)
{
    *state ^= *state >> 12;
    *state ^= *state << 25;
    *state ^= *state >> 27;
    return (double)((*state * 2685821657736338717ull) >> 11) / 9007199254740992.0 - 0.5;
}

int cylinder_generate(Cylinder *c, unsigned columns, unsigned rows, uint64_t seed)
{
    const double arc = CYLINDER_RADIUS * CYLINDER_SPAN_DEGREES * PI / 180.0;
    const double ds = arc / columns, dz = CYLINDER_HEIGHT / rows;
    uint64_t state = seed * 0x9E3779B97F4A7C15ull + 1;
    size_t t = 0;
    unsigned i, j;

    c->columns = columns;
    c->rows = rows;
    c->vertex_count = (size_t)(columns + 1) * (rows + 1);
    c->triangle_count = (size_t)2 * columns * rows;
    c->xyz = malloc(3 * c->vertex_count * sizeof(double));
    c->triangles = malloc(3 * c->triangle_count * sizeof(uint32_t));
    c->field = malloc(c->vertex_count * sizeof(double));
    if (!c->xyz || !c->triangles || !c->field) {
        cylinder_free(c);
        return 0;
    }
    for (j = 0; j <= rows; j++) {
        for (i = 0; i <= columns; i++) {
            size_t v = (size_t)j * (columns + 1) + i;
            /* Interior grid points move by up to a quarter cell; the boundary stays straight. */
            double s = ds * (i + ((i > 0 && i < columns) ? 0.5 * jitter(&state) : 0.0));
            double z = dz * (j + ((j > 0 && j < rows) ? 0.5 * jitter(&state) : 0.0));
            double phi = s / CYLINDER_RADIUS;
            c->xyz[3 * v] = CYLINDER_RADIUS * cos(phi);
            c->xyz[3 * v + 1] = CYLINDER_RADIUS * sin(phi);
            c->xyz[3 * v + 2] = z;
            c->field[v] = z + 0.8 * sin(s / 9.0) + 0.3 * cos(z / 5.0);
        }
    }
    for (j = 0; j < rows; j++) {
        for (i = 0; i < columns; i++) {
            uint32_t a = j * (columns + 1) + i, b = a + 1, d = a + columns + 1, e = d + 1;
            /* Counter-clockwise in the development (s, z): normals point away from the axis.
             * The diagonal alternates to avoid a directional bias. */
            uint32_t tri[6];
            if ((i + j) % 2 == 0) {
                tri[0] = a; tri[1] = b; tri[2] = e; tri[3] = a; tri[4] = e; tri[5] = d;
            } else {
                tri[0] = a; tri[1] = b; tri[2] = d; tri[3] = b; tri[4] = e; tri[5] = d;
            }
            for (t = 0; t < 6; t++) {
                c->triangles[6 * ((size_t)j * columns + i) + t] = tri[t];
            }
        }
    }
    return 1;
}

void cylinder_free(Cylinder *c)
{
    free(c->xyz);
    free(c->triangles);
    free(c->field);
    c->xyz = NULL;
    c->triangles = NULL;
    c->field = NULL;
}

double binormal_angle(const double *prev, const double *p, const double *next, const double *n)
{
    double e0[3], e1[3], t[3], b[3], u[3], l0, l1, lb, bn, bu;
    int k;
    for (k = 0; k < 3; k++) {
        e0[k] = p[k] - prev[k];
        e1[k] = next[k] - p[k];
    }
    l0 = sqrt(e0[0] * e0[0] + e0[1] * e0[1] + e0[2] * e0[2]);
    l1 = sqrt(e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2]);
    for (k = 0; k < 3; k++) {
        t[k] = e0[k] / l0 + e1[k] / l1;
    }
    b[0] = e0[1] * e1[2] - e0[2] * e1[1];
    b[1] = e0[2] * e1[0] - e0[0] * e1[2];
    b[2] = e0[0] * e1[1] - e0[1] * e1[0];
    lb = sqrt(b[0] * b[0] + b[1] * b[1] + b[2] * b[2]);
    u[0] = n[1] * t[2] - n[2] * t[1];
    u[1] = n[2] * t[0] - n[0] * t[2];
    u[2] = n[0] * t[1] - n[1] * t[0];
    bn = (b[0] * n[0] + b[1] * n[1] + b[2] * n[2]) / lb;
    bu = b[0] * u[0] + b[1] * u[1] + b[2] * u[2];
    return acos(fmin(1.0, fmax(-1.0, bu < 0.0 ? -bn : bn))) * 180.0 / PI;
}

double cylinder_binormal_angle(const double *prev, const double *p, const double *next)
{
    double r = sqrt(p[0] * p[0] + p[1] * p[1]);
    double n[3];
    n[0] = p[0] / r;
    n[1] = p[1] / r;
    n[2] = 0.0;
    return binormal_angle(prev, p, next, n);
}
