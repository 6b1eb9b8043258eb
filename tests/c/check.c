#include "check.h"

#include <stdio.h>
#include <string.h>

static int passed;
static int failed;

/* Status codes run from -10 to 3; index = code + 10. */
#define STATUS_MIN (-10)
#define STATUS_MAX 3
static int seen[STATUS_MAX - STATUS_MIN + 1];

void check(int ok, const char *file, int line, const char *what)
{
    if (ok) {
        passed++;
        return;
    }
    failed++;
    printf("FAIL %s:%d: %s\n     last error: %s\n", file, line, what, lml_last_error_message());
}

void check_status(LmlStatus status, LmlStatus expected, const char *file, int line, const char *call)
{
    if (status == expected) {
        if (status >= STATUS_MIN && status <= STATUS_MAX) {
            seen[status - STATUS_MIN] = 1;
        }
        passed++;
        return;
    }
    failed++;
    printf("FAIL %s:%d: %s\n     returned %s, expected %s\n     last error: %s\n", file, line, call,
           lml_status_name(status), lml_status_name(expected), lml_last_error_message());
}

void check_message(const char *part, const char *file, int line)
{
    const char *message = lml_last_error_message();
    if (message != NULL && strstr(message, part) != NULL) {
        passed++;
        return;
    }
    failed++;
    printf("FAIL %s:%d: last error message \"%s\" does not mention \"%s\"\n", file, line,
           message ? message : "(NULL)", part);
}

int every_status_seen(void)
{
    int all = 1;
    int code;
    for (code = STATUS_MIN; code <= STATUS_MAX; code++) {
        if (!seen[code - STATUS_MIN]) {
            printf("status %s was never provoked\n", lml_status_name(code));
            all = 0;
        }
    }
    return all;
}

int save_seen_statuses(const char *path)
{
    FILE *file = fopen(path, "w");
    int code, ok;
    if (file == NULL) {
        return 0;
    }
    for (code = STATUS_MIN; code <= STATUS_MAX; code++) {
        if (seen[code - STATUS_MIN]) {
            fprintf(file, "%d\n", code);
        }
    }
    ok = !ferror(file);
    return fclose(file) == 0 && ok;
}

int load_seen_statuses(const char *path)
{
    FILE *file = fopen(path, "r");
    int code, ok = 1;
    if (file == NULL) {
        printf("cannot read %s\n", path);
        return 0;
    }
    while (fscanf(file, "%d", &code) == 1) {
        if (code < STATUS_MIN || code > STATUS_MAX) {
            printf("%s: %d is not a status code\n", path, code);
            ok = 0;
        } else {
            seen[code - STATUS_MIN] = 1;
        }
    }
    ok = ok && feof(file);
    fclose(file);
    return ok;
}

size_t occurrences(const char *text, const char *needle)
{
    size_t count = 0;
    const char *at = text;
    while ((at = strstr(at, needle)) != NULL) {
        count++;
        at += strlen(needle);
    }
    return count;
}

int check_summary(void)
{
    printf("%d passed, %d failed\n", passed, failed);
    return failed == 0 ? 0 : 1;
}
