/* C ABI harness of Lamella: exercises every function of include/lamella.h, provokes every
 * status code and runs real solves. Usage:
 *   harness [scratch-directory [part]]
 *       runs every test group, or one part of them: "starts" (meshes, parameters, threads, guides,
 *       constant slope, the start search, surface optimisation, 3-webs) or "pipeline" (nets, base meshes, shading, then field, session, curves,
 *       fabrication, viewer and strips on one solve). A part writes the statuses it provoked to
 *       scratch-directory/statuses, so that scripts/test-c-abi.sh can run both parts side by side
 *       under valgrind (valgrind runs one process on one core) and check them together with
 *   harness --every-status-seen FILE...
 *       which checks that the parts together provoked every status code.
 * Prints a final line "N passed, M failed" and exits non-zero on failure. */
#include "check.h"
#include "harness.h"

#include <stdio.h>
#include <string.h>

static void run_starts(const char *scratch, const Cylinder *cylinder, const Cylinder *small)
{
    test_basics();
    test_mesh(scratch);
    test_field_inputs(cylinder);
    test_threads(cylinder);
    test_guides(cylinder);
    test_slope(cylinder);
    test_search(small);
    test_reshape(small);
    test_alternation(small);
    test_web();
}

static void run_pipeline(const Cylinder *cylinder, const Cylinder *small)
{
    LmlField *field;
    LmlCurves *curves;

    test_net(small);
    test_base_mesh();
    test_shading();
    field = test_solve(cylinder);
    CHECK(field != NULL);
    if (field != NULL) {
        test_session(field);
        /* The rest of the pipeline: field -> curves -> strips -> unrolled strips. */
        curves = test_curves(field, cylinder);
        test_fabrication(curves);
        test_view(curves);
        test_strips(field, curves);
    }
    lml_field_free(field);
}

/* The union of the statuses the parts saved must hold every status code. */
static int every_status_seen_in(int count, char **paths)
{
    int i;
    for (i = 0; i < count; i++) {
        CHECK(load_seen_statuses(paths[i]));
    }
    CHECK(every_status_seen());
    return check_summary();
}

int main(int argc, char **argv)
{
    const char *scratch = argc > 1 ? argv[1] : ".";
    const char *part = argc > 2 ? argv[2] : "all";
    int all = strcmp(part, "all") == 0;
    char statuses[4096];
    Cylinder cylinder, small;

    if (argc > 1 && strcmp(argv[1], "--every-status-seen") == 0) {
        return every_status_seen_in(argc - 2, argv + 2);
    }
    if (!all && strcmp(part, "starts") != 0 && strcmp(part, "pipeline") != 0) {
        printf("unknown part \"%s\" (all, starts or pipeline)\n", part);
        return 2;
    }
    /* 26 x 15 cells: about 1 length unit each, 432 vertices (small enough for valgrind). */
    /* The search probes a dozen starts with real solves: 16 x 10 cells, 187 vertices. */
    if (!cylinder_generate(&cylinder, 26, 15, 7) || !cylinder_generate(&small, 16, 10, 11)) {
        printf("out of memory\n");
        return 1;
    }
    if (all || strcmp(part, "starts") == 0) {
        run_starts(scratch, &cylinder, &small);
    }
    if (all || strcmp(part, "pipeline") == 0) {
        run_pipeline(&cylinder, &small);
    }
    cylinder_free(&cylinder);
    cylinder_free(&small);
    /* Every handle created above (including those of the threads test) has been freed. */
    CHECK(lml_debug_live_handles() == 0);
    if (all) {
        CHECK(every_status_seen());
    } else if (snprintf(statuses, sizeof statuses, "%s/statuses", scratch) >= (int)sizeof statuses) {
        CHECK(!"scratch directory path too long");
    } else {
        CHECK(save_seen_statuses(statuses));
    }
    return check_summary();
}
