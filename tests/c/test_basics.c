#include "check.h"
#include "harness.h"

#include <stdio.h>
#include <string.h>

void test_basics(void)
{
    const char *version = lml_version();
    CHECK(version != NULL && strlen(version) >= 5 && strchr(version, '.') != NULL);
    CHECK(lml_abi_version() == LML_ABI_VERSION);
    CHECK(lml_debug_live_handles() == 0);

    CHECK(strcmp(lml_status_name(LML_STATUS_NOT_A_DISK), "LML_STATUS_NOT_A_DISK") == 0);
    CHECK(strcmp(lml_status_name(LML_STATUS_OK), "LML_STATUS_OK") == 0);
    CHECK(strcmp(lml_status_name(12345), "LML_STATUS_UNKNOWN") == 0);

    /* A panic inside the library comes back as a status, never as an unwind into C. */
    printf("  (a panic message from lml_debug_trigger_panic on stderr is expected)\n");
    fflush(stdout);
    CHECK_STATUS(lml_debug_trigger_panic(), LML_STATUS_INTERNAL_ERROR);
    CHECK_MESSAGE("panic");
    /* The message is per call: a successful call clears it. */
    CHECK(lml_abi_version() == LML_ABI_VERSION);
    {
        LmlFieldParams params;
        CHECK_STATUS(lml_field_params_default(LML_FAMILY_GEODESIC, 0.0, &params), LML_STATUS_OK);
        CHECK(lml_last_error_message() != NULL && lml_last_error_message()[0] == '\0');
    }
}
