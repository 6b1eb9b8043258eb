/* The paper's validation surface for the harness: a patch of a circular cylinder
 * (R = 10, 150 degrees, height 15), triangulated by a jittered grid, with a smooth initial
 * field whose level sets are not yet pseudo-geodesics. */
#ifndef LAMELLA_CYLINDER_H
#define LAMELLA_CYLINDER_H

#include <stddef.h>
#include <stdint.h>

#define CYLINDER_RADIUS 10.0
#define CYLINDER_SPAN_DEGREES 150.0
#define CYLINDER_HEIGHT 15.0

typedef struct {
    unsigned columns;     /* grid cells around the axis */
    unsigned rows;        /* grid cells along the axis */
    size_t vertex_count;
    size_t triangle_count;
    double *xyz;          /* 3 * vertex_count */
    uint32_t *triangles;  /* 3 * triangle_count, normals pointing away from the axis */
    double *field;        /* vertex_count initial field values */
} Cylinder;

/* Generates the patch with `columns` x `rows` cells; returns 0 on allocation failure. */
int cylinder_generate(Cylinder *cylinder, unsigned columns, unsigned rows, uint64_t seed);

/* Frees the arrays. */
void cylinder_free(Cylinder *cylinder);

/* The signed angle in degrees between the discrete binormal of a polyline at `p` (paper Eq. 1:
 * (p - prev) x (next - p), normalised) and the unit surface normal `n` at `p`, signed as in
 * Eq. 8 by the side vector u = n x t (t the sum of the unit edges): acos(sign(b.u) b.n). */
double binormal_angle(const double *prev, const double *p, const double *next, const double *n);

/* binormal_angle with the cylinder's radial normal at `p`. */
double cylinder_binormal_angle(const double *prev, const double *p, const double *next);

#endif
