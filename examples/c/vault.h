/* A parabolic vault, z = h (1 - (x / a)^2) over [-a, a] x [0, length]: a developable roof
 * surface for the examples, as flat arrays in the layout of lml_mesh_new. */
#ifndef LAMELLA_EXAMPLE_VAULT_H
#define LAMELLA_EXAMPLE_VAULT_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct {
    size_t vertex_count;
    size_t triangle_count;
    double *xyz;         /* 3 * vertex_count */
    uint32_t *triangles; /* 3 * triangle_count, normals pointing up */
} Vault;

/* Half-span 6, rise 4, length 12, `cells` x `cells` grid; returns 0 on allocation failure. */
int vault_generate(Vault *vault, unsigned cells);

void vault_free(Vault *vault);

#ifdef __cplusplus
}
#endif

#endif
