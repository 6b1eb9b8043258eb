#include "check.h"
#include "harness.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

/* A unit square of two triangles, counter-clockwise seen from +z. */
static const double square_xyz[] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
static const uint32_t square_triangles[] = {0, 1, 2, 0, 2, 3};

/* A non-NULL pointer that is not a handle: constructors must overwrite it with NULL on failure. */
static LmlMesh *poisoned(void)
{
    static int marker;
    return (LmlMesh *)(void *)&marker;
}

/* Expects lml_mesh_new to fail with `expected`, reset *out to NULL and name `part`. */
static void expect_invalid(const double *xyz, size_t nv, const uint32_t *tris, size_t nt, LmlStatus expected,
                           const char *part, int line)
{
    LmlMesh *mesh = poisoned();
    check_status(lml_mesh_new(xyz, nv, tris, nt, &mesh), expected, __FILE__, line, "lml_mesh_new");
    check(mesh == NULL, __FILE__, line, "out reset to NULL");
    check_message(part, __FILE__, line);
    lml_mesh_free(mesh);
}

static void lifecycle_and_accessors(void)
{
    LmlMesh *mesh = NULL;
    double xyz[12];
    uint32_t tris[6];
    size_t count = 0, needed = 0;

    CHECK_STATUS(lml_mesh_new(square_xyz, 4, square_triangles, 2, &mesh), LML_STATUS_OK);
    CHECK(mesh != NULL);
    CHECK(lml_debug_live_handles() == 1);
    CHECK_STATUS(lml_mesh_vertex_count(mesh, &count), LML_STATUS_OK);
    CHECK(count == 4);
    CHECK_STATUS(lml_mesh_triangle_count(mesh, &count), LML_STATUS_OK);
    CHECK(count == 2);

    /* Two-call pattern: ask, then fill. */
    CHECK_STATUS(lml_mesh_positions(mesh, NULL, 0, &needed), LML_STATUS_BUFFER_TOO_SMALL);
    CHECK(needed == 12);
    CHECK_MESSAGE("12");
    needed = 0;
    CHECK_STATUS(lml_mesh_positions(mesh, xyz, 11, &needed), LML_STATUS_BUFFER_TOO_SMALL);
    CHECK(needed == 12);
    CHECK_STATUS(lml_mesh_positions(mesh, xyz, 12, &needed), LML_STATUS_OK);
    CHECK(memcmp(xyz, square_xyz, sizeof xyz) == 0);
    CHECK_STATUS(lml_mesh_triangles(mesh, tris, 5, &needed), LML_STATUS_BUFFER_TOO_SMALL);
    CHECK(needed == 6);
    CHECK_STATUS(lml_mesh_triangles(mesh, tris, 6, &needed), LML_STATUS_OK);
    CHECK(memcmp(tris, square_triangles, sizeof tris) == 0);

    /* NULL arguments of the accessors. */
    CHECK_STATUS(lml_mesh_vertex_count(NULL, &count), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("mesh");
    CHECK_STATUS(lml_mesh_vertex_count(mesh, NULL), LML_STATUS_INVALID_ARGUMENT);
    CHECK_STATUS(lml_mesh_triangle_count(mesh, NULL), LML_STATUS_INVALID_ARGUMENT);
    CHECK_STATUS(lml_mesh_positions(mesh, xyz, 12, NULL), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("needed");
    CHECK_STATUS(lml_mesh_triangles(NULL, tris, 6, &needed), LML_STATUS_INVALID_ARGUMENT);

    lml_mesh_free(mesh);
    lml_mesh_free(NULL);
    CHECK(lml_debug_live_handles() == 0);
}

static void invalid_arrays(void)
{
    const double nan_xyz[] = {0, 0, 0, 1, 0, 0, 1, 1, NAN, 0, 1, 0};
    const double inf_xyz[] = {0, 0, 0, INFINITY, 0, 0, 1, 1, 0, 0, 1, 0};
    const uint32_t out_of_range[] = {0, 1, 2, 0, 2, 7};
    const uint32_t repeated[] = {0, 1, 1, 0, 2, 3};
    /* Three triangles on the edge (0, 1). */
    const double fan_xyz[] = {0, 0, 0, 1, 0, 0, 0.5, 1, 0, 0.5, -1, 0, 0.5, 0, 1};
    const uint32_t fan[] = {0, 1, 2, 1, 0, 3, 0, 1, 4};
    /* A closed tetrahedron: valid, but not a disk. */
    const double tet_xyz[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
    const uint32_t tet[] = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
    /* Two separate triangles: not one disk. */
    const double pair_xyz[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 5, 0, 0, 6, 0, 0, 5, 1, 0};
    const uint32_t pair[] = {0, 1, 2, 3, 4, 5};

    expect_invalid(NULL, 4, square_triangles, 2, LML_STATUS_INVALID_ARGUMENT, "xyz", __LINE__);
    expect_invalid(square_xyz, 4, NULL, 2, LML_STATUS_INVALID_ARGUMENT, "triangles", __LINE__);
    expect_invalid(square_xyz, SIZE_MAX, square_triangles, 2, LML_STATUS_INVALID_ARGUMENT, "vertex_count", __LINE__);
    expect_invalid(square_xyz, 0, square_triangles, 2, LML_STATUS_INVALID_MESH, "no vertices", __LINE__);
    expect_invalid(square_xyz, 4, square_triangles, 0, LML_STATUS_INVALID_MESH, "no faces", __LINE__);
    expect_invalid(nan_xyz, 4, square_triangles, 2, LML_STATUS_INVALID_MESH, "vertex 2", __LINE__);
    expect_invalid(inf_xyz, 4, square_triangles, 2, LML_STATUS_INVALID_MESH, "vertex 1", __LINE__);
    expect_invalid(square_xyz, 4, out_of_range, 2, LML_STATUS_INVALID_MESH, "vertex 7", __LINE__);
    expect_invalid(square_xyz, 4, repeated, 2, LML_STATUS_INVALID_MESH, "face 0", __LINE__);
    expect_invalid(fan_xyz, 5, fan, 3, LML_STATUS_INVALID_MESH, "non-manifold", __LINE__);
    expect_invalid(tet_xyz, 4, tet, 4, LML_STATUS_NOT_A_DISK, "disk", __LINE__);
    expect_invalid(pair_xyz, 6, pair, 2, LML_STATUS_NOT_A_DISK, "components", __LINE__);
    CHECK_STATUS(lml_mesh_new(square_xyz, 4, square_triangles, 2, NULL), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("out");
}

/* Writes `text` to `dir`/`name`; returns 0 on failure. */
static int write_file(const char *dir, const char *name, const char *text, char *path, size_t capacity)
{
    FILE *file;
    int ok;
    if (snprintf(path, capacity, "%s/%s", dir, name) >= (int)capacity) {
        return 0;
    }
    file = fopen(path, "w");
    if (file == NULL) {
        return 0;
    }
    ok = fputs(text, file) >= 0;
    return fclose(file) == 0 && ok;
}

static void obj_files(const char *dir)
{
    char path[4096];
    LmlMesh *mesh = poisoned();
    size_t count = 0;

    CHECK(write_file(dir, "lml_square.obj", "# a square\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n", path, sizeof path));
    CHECK_STATUS(lml_mesh_read_obj(path, &mesh), LML_STATUS_OK);
    CHECK_STATUS(lml_mesh_triangle_count(mesh, &count), LML_STATUS_OK);
    CHECK(count == 2);
    lml_mesh_free(mesh);

    CHECK(write_file(dir, "lml_bad.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 9\n", path, sizeof path));
    mesh = poisoned();
    CHECK_STATUS(lml_mesh_read_obj(path, &mesh), LML_STATUS_INVALID_MESH);
    CHECK(mesh == NULL);
    CHECK_MESSAGE("line 4");

    CHECK_STATUS(lml_mesh_read_obj("/nonexistent/lamella/mesh.obj", &mesh), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("/nonexistent/lamella/mesh.obj");
    CHECK_STATUS(lml_mesh_read_obj(NULL, &mesh), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("path");
    CHECK_STATUS(lml_mesh_read_obj("\xff\xfe.obj", &mesh), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("UTF-8");
}

void test_mesh(const char *scratch_dir)
{
    lifecycle_and_accessors();
    invalid_arrays();
    obj_files(scratch_dir);
}
