#include "check.h"
#include "harness.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static LmlField *poisoned(void)
{
    static int marker;
    return (LmlField *)(void *)&marker;
}

static void params_defaults(void)
{
    LmlFieldParams params;
    memset(&params, 0, sizeof params);

    CHECK_STATUS(lml_field_params_default(LML_FAMILY_PSEUDO_GEODESIC, 60.0, &params), LML_STATUS_OK);
    CHECK(params.family == LML_FAMILY_PSEUDO_GEODESIC);
    CHECK(params.theta_degrees == 60.0);
    /* The library's defaults: the paper's Table 2 weights after a warm-up, except lambda_grad, held at
     * 1e-5 in the final stage since f79d56e (src/field/params.rs). */
    CHECK(params.weights.fair == 1e-3 && params.weights.grad == 1e-5 && params.weights.angle == 30.0);
    CHECK(params.warm_up == 1);
    CHECK(params.gradient_target == 0.0);
    CHECK(params.relative_tolerance > 0.0 && params.relative_tolerance < 1.0);

    CHECK_STATUS(lml_field_params_default(LML_FAMILY_GEODESIC, -5.0, &params), LML_STATUS_OK);
    CHECK(params.theta_degrees == 90.0);
    CHECK_STATUS(lml_field_params_default(LML_FAMILY_ASYMPTOTIC, 33.0, &params), LML_STATUS_OK);
    CHECK(params.theta_degrees == 0.0);

    CHECK_STATUS(lml_field_params_default(7, 60.0, &params), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("family");
    CHECK_STATUS(lml_field_params_default(LML_FAMILY_PSEUDO_GEODESIC, NAN, &params), LML_STATUS_INVALID_ARGUMENT);
    CHECK_MESSAGE("theta");
    CHECK_STATUS(lml_field_params_default(LML_FAMILY_PSEUDO_GEODESIC, 200.0, &params), LML_STATUS_INVALID_ARGUMENT);
    CHECK_STATUS(lml_field_params_default(LML_FAMILY_PSEUDO_GEODESIC, 60.0, NULL), LML_STATUS_INVALID_ARGUMENT);
}

/* Expects lml_field_new to fail with `expected`, reset *out to NULL and name `part`. */
static void expect_refused(const LmlMesh *mesh, const double *values, size_t n, const LmlFieldParams *params,
                           LmlStatus expected, const char *part, int line)
{
    LmlField *field = poisoned();
    check_status(lml_field_new(mesh, values, n, params, &field), expected, __FILE__, line, "lml_field_new");
    check(field == NULL, __FILE__, line, "out reset to NULL");
    check_message(part, __FILE__, line);
    lml_field_free(field);
}

void test_field_inputs(const Cylinder *c)
{
    LmlMesh *mesh = NULL;
    LmlFieldParams params, bad;
    double *values = malloc(c->vertex_count * sizeof(double));
    size_t i;

    params_defaults();
    CHECK(values != NULL);
    if (values == NULL) {
        return;
    }
    CHECK_STATUS(lml_mesh_new(c->xyz, c->vertex_count, c->triangles, c->triangle_count, &mesh), LML_STATUS_OK);
    CHECK_STATUS(lml_field_params_default(LML_FAMILY_PSEUDO_GEODESIC, 60.0, &params), LML_STATUS_OK);

    expect_refused(NULL, c->field, c->vertex_count, &params, LML_STATUS_INVALID_ARGUMENT, "mesh", __LINE__);
    expect_refused(mesh, NULL, c->vertex_count, &params, LML_STATUS_INVALID_ARGUMENT, "initial_field", __LINE__);
    expect_refused(mesh, c->field, c->vertex_count, NULL, LML_STATUS_INVALID_ARGUMENT, "params", __LINE__);
    expect_refused(mesh, c->field, 0, &params, LML_STATUS_INVALID_ARGUMENT, "0 values", __LINE__);
    expect_refused(mesh, c->field, c->vertex_count - 1, &params, LML_STATUS_INVALID_ARGUMENT, "vertices", __LINE__);

    memcpy(values, c->field, c->vertex_count * sizeof(double));
    values[5] = NAN;
    expect_refused(mesh, values, c->vertex_count, &params, LML_STATUS_INVALID_ARGUMENT, "vertex 5", __LINE__);
    /* One huge value is named as such, not reported as a constant field. */
    values[5] = 1e300;
    expect_refused(mesh, values, c->vertex_count, &params, LML_STATUS_INVALID_ARGUMENT, "1e300 at vertex 5 is out of range", __LINE__);
    values[5] = -INFINITY;
    expect_refused(mesh, values, c->vertex_count, &params, LML_STATUS_INVALID_ARGUMENT, "vertex 5", __LINE__);
    for (i = 0; i < c->vertex_count; i++) {
        values[i] = 3.0;
    }
    expect_refused(mesh, values, c->vertex_count, &params, LML_STATUS_SINGULAR_FIELD, "constant", __LINE__);

    bad = params;
    bad.family = 99;
    expect_refused(mesh, c->field, c->vertex_count, &bad, LML_STATUS_INVALID_ARGUMENT, "family", __LINE__);
    bad = params;
    bad.theta_degrees = 181.0;
    expect_refused(mesh, c->field, c->vertex_count, &bad, LML_STATUS_INVALID_ARGUMENT, "theta", __LINE__);
    bad = params;
    bad.weights.fair = -1.0;
    expect_refused(mesh, c->field, c->vertex_count, &bad, LML_STATUS_INVALID_ARGUMENT, "weights.fair", __LINE__);
    bad = params;
    bad.weights.angle = NAN;
    expect_refused(mesh, c->field, c->vertex_count, &bad, LML_STATUS_INVALID_ARGUMENT, "weights.angle", __LINE__);
    bad = params;
    bad.warm_up = 2;
    expect_refused(mesh, c->field, c->vertex_count, &bad, LML_STATUS_INVALID_ARGUMENT, "warm_up", __LINE__);
    bad = params;
    bad.gradient_target = -1.0;
    expect_refused(mesh, c->field, c->vertex_count, &bad, LML_STATUS_INVALID_ARGUMENT, "gradient_target", __LINE__);
    bad = params;
    bad.relative_tolerance = INFINITY;
    expect_refused(mesh, c->field, c->vertex_count, &bad, LML_STATUS_INVALID_ARGUMENT, "relative_tolerance", __LINE__);
    CHECK_STATUS(lml_field_new(mesh, c->field, c->vertex_count, &params, NULL), LML_STATUS_INVALID_ARGUMENT);

    /* NULL handles in every field function. */
    {
        LmlReport report;
        LmlWeights weights = {1e-3, 1e-4, 30.0};
        double value;
        uint32_t index;
        uint8_t byte;
        size_t needed;
        CHECK_STATUS(lml_field_step(NULL, 1, &report), LML_STATUS_INVALID_ARGUMENT);
        CHECK_MESSAGE("field");
        CHECK_STATUS(lml_field_solve(NULL, 1, &report), LML_STATUS_INVALID_ARGUMENT);
        CHECK_STATUS(lml_field_report(NULL, &report), LML_STATUS_INVALID_ARGUMENT);
        CHECK_STATUS(lml_field_set_weights(NULL, weights), LML_STATUS_INVALID_ARGUMENT);
        CHECK_STATUS(lml_field_values(NULL, &value, 1, &needed), LML_STATUS_INVALID_ARGUMENT);
        CHECK_STATUS(lml_field_binormals(NULL, &value, 1, &needed), LML_STATUS_INVALID_ARGUMENT);
        CHECK_STATUS(lml_field_side_vectors(NULL, &value, 1, &needed), LML_STATUS_INVALID_ARGUMENT);
        CHECK_STATUS(lml_field_singular_vertices(NULL, &index, 1, &needed), LML_STATUS_INVALID_ARGUMENT);
        CHECK_STATUS(lml_field_save(NULL, &byte, 1, &needed), LML_STATUS_INVALID_ARGUMENT);
        lml_field_free(NULL);
    }

    /* A session created with warm_up = 0 starts in the final stage; its life ends early. */
    {
        LmlField *field = NULL;
        LmlReport report;
        LmlWeights negative = {1e-3, -1.0, 30.0};
        bad = params;
        bad.warm_up = 0;
        CHECK_STATUS(lml_field_new(mesh, c->field, c->vertex_count, &bad, &field), LML_STATUS_OK);
        CHECK_STATUS(lml_field_report(field, &report), LML_STATUS_OK);
        CHECK(report.iterations == 0 && report.stage == 0 && report.converged == 0);
        CHECK_STATUS(lml_field_report(field, NULL), LML_STATUS_INVALID_ARGUMENT);
        CHECK_STATUS(lml_field_set_weights(field, negative), LML_STATUS_INVALID_ARGUMENT);
        CHECK_MESSAGE("weights.grad");
        lml_field_free(field);
    }
    lml_mesh_free(mesh);
    free(values);
}
