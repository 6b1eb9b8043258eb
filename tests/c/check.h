/* Minimal check helpers of the C ABI harness: count passes and failures, print every
 * failure with its location and the library's last error message. */
#ifndef LAMELLA_CHECK_H
#define LAMELLA_CHECK_H

#include "lamella.h"

#include <stddef.h>

/* Records one check; prints `what` (and the library's last error message) when it fails. */
void check(int ok, const char *file, int line, const char *what);

/* Records that `status` equals `expected` (and that status was seen, for the coverage check). */
void check_status(LmlStatus status, LmlStatus expected, const char *file, int line, const char *call);

/* Records that the last error message contains `part`. */
void check_message(const char *part, const char *file, int line);

/* Whether every LmlStatus value was produced by some checked call; prints the missing ones. */
int every_status_seen(void);

/* Writes the status codes seen so far to `path`, one per line; whether that succeeded. */
int save_seen_statuses(const char *path);

/* Marks the status codes listed in `path` (as written by save_seen_statuses) as seen; whether the
 * file was read whole. */
int load_seen_statuses(const char *path);

/* Counts the occurrences of `needle` in `text`. */
size_t occurrences(const char *text, const char *needle);

/* Prints "N passed, M failed" and returns the process exit code. */
int check_summary(void);

#define CHECK(cond) check((cond) != 0, __FILE__, __LINE__, #cond)
#define CHECK_STATUS(call, expected) check_status((call), (expected), __FILE__, __LINE__, #call)
#define CHECK_MESSAGE(part) check_message((part), __FILE__, __LINE__)

#endif
