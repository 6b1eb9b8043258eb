/* C ABI harness of Lamella: exercises every function of include/lamella.h, provokes every
 * status code and runs a real solve. Usage: harness [scratch-directory]. Prints a final line
 * "N passed, M failed" and exits non-zero on failure. */
#include "check.h"
#include "harness.h"

#include <stdio.h>

int main(int argc, char **argv)
{
    const char *scratch = argc > 1 ? argv[1] : ".";
    Cylinder cylinder, small;
    LmlField *field;
    LmlCurves *curves;

    /* 26 x 15 cells: about 1 length unit each, 432 vertices (small enough for valgrind). */
    /* The search probes a dozen starts with real solves: 16 x 10 cells, 187 vertices. */
    if (!cylinder_generate(&cylinder, 26, 15, 7) || !cylinder_generate(&small, 16, 10, 11)) {
        printf("out of memory\n");
        return 1;
    }
    test_basics();
    test_mesh(scratch);
    test_field_inputs(&cylinder);
    test_threads(&cylinder);
    test_guides(&cylinder);
    test_search(&small);
    test_net(&small);
    test_reshape(&small);
    test_shading();
    field = test_solve(&cylinder);
    CHECK(field != NULL);
    if (field != NULL) {
        test_session(field);
        /* The rest of the pipeline: field -> curves -> strips -> unrolled strips. */
        curves = test_curves(field, &cylinder);
        test_fabrication(curves);
        test_view(curves);
        test_strips(field, curves);
    }
    lml_field_free(field);
    cylinder_free(&cylinder);
    cylinder_free(&small);
    /* Every handle created above (including those of the threads test) has been freed. */
    CHECK(lml_debug_live_handles() == 0);
    CHECK(every_status_seen());
    return check_summary();
}
