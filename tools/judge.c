/* judge.c: whether one test passed, from what it observed, by a program that
 * holds no student code (tests/support/observe.h says what is observed).
 *
 *   judge [--owner UID] REFERENCE RECORD OUTPUT_DIR
 *
 * REFERENCE is the record of the test run on the teacher's solution, made
 * beforehand (make grade with --record). RECORD is the record of the same test
 * run on the student's code, OUTPUT_DIR that run's $TEST_OUTPUT, where its
 * pictures are. The test passes when the two records agree, entry by entry:
 *   D (the checks that want equality)  the same count and the same hash
 *   B (a bound)        the student's value within the teacher's bound
 *   C (a number)       the student's value within the teacher's tolerance of
 *                      the teacher's expected value
 *   P (a picture)      the same picture as the teacher's run, or one within
 *                      what the check allows of tests/expected/<group>/<name>.png,
 *                      read from OUTPUT_DIR (a regular file, not a link; owned
 *                      by UID with --owner)
 *   F (a failure)      never: the teacher's run has none
 *   E (the end)        "passed", in both
 * Nothing else about the run counts, and the record is read as untrusted
 * input: a line too long, a field that does not parse or an entry the
 * teacher's run did not have is a failure, never a crash.
 *
 * Prints one line, "judge: passed: ..." or "judge: failed: <why>", and exits
 * 0 when the test passed, 1 when it failed, 2 when it could not judge (a
 * usage error, a reference that cannot be read). */
#include <errno.h>
#include <fcntl.h>
#include <inttypes.h>
#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "harness/file.h"
#include "harness/image_io.h"
#include "observe.h"

#define LINE_MAX_LEN 4096
#define PICTURE_FILE_MAX (64L << 20)
#define NAME_LEN 256

enum { PASSED = 0, FAILED = 1, CANNOT_JUDGE = 2 };

typedef struct {
    char kind;
    char site[NAME_LEN];
    /* D: checks folded; B: checks in a row */
    unsigned long count;
    /* B */
    char op;
    long actual, bound;
    /* P */
    char group[NAME_LEN], name[NAME_LEN];
    long max_differing;
    int tolerance, width, height;
    /* C */
    double value, expected, within;
    /* D and P */
    uint64_t hash;
    /* E */
    bool passed;
} Entry;

static uid_t owner = (uid_t)-1;
static const char *output_dir;

/* One line of a record, parsed; false if it is not one. */
static bool parse_entry(const char *line, Entry *e)
{
    memset(e, 0, sizeof *e);
    char word[16];
    int used = 0;
    e->kind = line[0];
    if (line[0] == '\0' || line[1] != ' ')
        return false;
    const char *rest = line + 2;
    switch (e->kind) {
    case 'D':
        return sscanf(rest, "%lu %16" SCNx64 "%n", &e->count, &e->hash, &used) == 2 &&
               rest[used] == '\0';
    case 'B':
        return sscanf(rest, "%255s %c %ld %ld %lu%n", e->site, &e->op, &e->actual, &e->bound,
                      &e->count, &used) == 5 &&
               rest[used] == '\0' && (e->op == '<' || e->op == '>') && e->count > 0;
    case 'P':
        return sscanf(rest, "%255s %255s %255s %ld %d %d %d %16" SCNx64 "%n", e->site, e->group,
                      e->name, &e->max_differing, &e->tolerance, &e->width, &e->height,
                      &e->hash, &used) == 8 &&
               rest[used] == '\0';
    case 'C':
        return sscanf(rest, "%255s %la %la %la%n", e->site, &e->value, &e->expected,
                      &e->within, &used) == 4 &&
               rest[used] == '\0';
    case 'F':
        return sscanf(rest, "%255s%n", e->site, &used) == 1 && rest[used] == '\0';
    case 'E':
        if (sscanf(rest, "%15s%n", word, &used) != 1 || rest[used] != '\0')
            return false;
        e->passed = strcmp(word, "passed") == 0;
        return e->passed || strcmp(word, "failed") == 0;
    default:
        return false;
    }
}

/* The next line of f without its newline; false at the end, or when the line
 * is too long (*bad is set then). */
static bool next_line(FILE *f, char *line, size_t size, bool *bad)
{
    if (!fgets(line, (int)size, f))
        return false;
    size_t n = strlen(line);
    if (n == 0 || line[n - 1] != '\n') {
        *bad = true;
        return false;
    }
    line[n - 1] = '\0';
    return true;
}

/* A name that stays inside OUTPUT_DIR: no '/', no "..", not empty. */
static bool plain_name(const char *s)
{
    return s[0] != '\0' && s[0] != '.' && !strchr(s, '/');
}

/* The picture the student's run wrote for entry e, read safely: a regular
 * file of OUTPUT_DIR, not a link, with one name (and the owner's). */
static bool read_actual(const Entry *e, Image *im, char *why, size_t why_size)
{
    char path[3 * NAME_LEN + LINE_MAX_LEN];
    if (!plain_name(e->group) || !plain_name(e->name)) {
        snprintf(why, why_size, "the picture's name %s/%s is not one a test uses", e->group,
                 e->name);
        return false;
    }
    snprintf(path, sizeof path, "%s/%s/%s.actual.png", output_dir, e->group, e->name);
    int fd = open(path, O_RDONLY | O_NOFOLLOW | O_CLOEXEC | O_NONBLOCK);
    if (fd < 0) {
        snprintf(why, why_size, "cannot read the picture %s: %s", path, strerror(errno));
        return false;
    }
    struct stat st;
    if (fstat(fd, &st) != 0 || !S_ISREG(st.st_mode) || st.st_nlink != 1 ||
        st.st_size > PICTURE_FILE_MAX || (owner != (uid_t)-1 && st.st_uid != owner)) {
        close(fd);
        snprintf(why, why_size, "%s is not a picture the test wrote", path);
        return false;
    }
    unsigned char *bytes = malloc((size_t)st.st_size + 1);
    size_t got = 0;
    while (bytes && got < (size_t)st.st_size) {
        ssize_t n = read(fd, bytes + got, (size_t)st.st_size - got);
        if (n <= 0)
            break;
        got += (size_t)n;
    }
    close(fd);
    Error err;
    bool ok = bytes && got == (size_t)st.st_size &&
              image_decode_png(im, bytes, got, path, e->width, e->height, &err);
    free(bytes);
    if (!ok) {
        snprintf(why, why_size, "cannot decode the picture %s", path);
        return false;
    }
    return true;
}

/* A picture entry: the student's (s) against the teacher's (r). */
static bool judge_picture(const Entry *r, const Entry *s, char *why, size_t why_size)
{
    if (strcmp(r->group, s->group) != 0 || strcmp(r->name, s->name) != 0) {
        snprintf(why, why_size, "%s: the picture %s/%s, where the teacher's run had %s/%s",
                 r->site, s->group, s->name, r->group, r->name);
        return false;
    }
    if (s->width == r->width && s->height == r->height && s->hash == r->hash)
        return true;
    Image actual, expected;
    if (!read_actual(s, &actual, why, why_size))
        return false;
    if (observe_picture_hash(actual.width, actual.height, actual.rgb) != s->hash) {
        image_free(&actual);
        snprintf(why, why_size, "%s: the picture on disk is not the one the test checked",
                 r->site);
        return false;
    }
    char path[3 * NAME_LEN];
    snprintf(path, sizeof path, "tests/expected/%s/%s.png", r->group, r->name);
    Error err;
    if (!image_read_png(&expected, path, &err)) {
        image_free(&actual);
        snprintf(why, why_size, "no expected picture: %.1000s", err.msg);
        return false;
    }
    bool ok = false;
    if (actual.width != expected.width || actual.height != expected.height) {
        snprintf(why, why_size, "%s: picture %s/%s is %dx%d, the expected picture is %dx%d",
                 r->site, r->group, r->name, actual.width, actual.height, expected.width,
                 expected.height);
    } else {
        ImageDiff d;
        if (!image_compare(&actual, &expected, r->tolerance, &d, NULL, &err))
            snprintf(why, why_size, "%s: %.1000s", r->site, err.msg);
        else if (d.differing <= r->max_differing)
            ok = true;
        else
            snprintf(why, why_size,
                     "%s: picture %s/%s: %ld pixels differ from the expected picture "
                     "(allowed: %ld, tolerance %d per channel), within x %d..%d, y %d..%d",
                     r->site, r->group, r->name, d.differing, r->max_differing, r->tolerance,
                     d.x0, d.x1, d.y0, d.y1);
    }
    image_free(&actual);
    image_free(&expected);
    return ok;
}

/* Entry s of the student's record against entry r of the teacher's. prev is
 * the site of the teacher's entry before, for words about a D line. */
static bool judge_entry(const Entry *r, const Entry *s, const char *prev, char *why,
                        size_t why_size)
{
    if (s->kind == 'F') {
        snprintf(why, why_size, "the test failed at %s", s->site);
        return false;
    }
    if (s->kind != r->kind || (r->kind != 'D' && r->kind != 'E' && strcmp(r->site, s->site) != 0)) {
        snprintf(why, why_size, "the test took another way than the teacher's solution's: "
                 "after %s it checked %s%s where that run checked %s%s",
                 prev, s->kind == 'D' || s->kind == 'E' ? "" : "at ", s->kind == 'D' ? "values"
                 : s->kind == 'E' ? "nothing more" : s->site,
                 r->kind == 'D' || r->kind == 'E' ? "" : "at ", r->kind == 'D' ? "values"
                 : r->kind == 'E' ? "nothing more" : r->site);
        return false;
    }
    switch (r->kind) {
    case 'D':
        if (s->count == r->count && s->hash == r->hash)
            return true;
        snprintf(why, why_size, "checks after %s found other values than the teacher's "
                 "solution's (%lu checks, the teacher's run %lu): the messages above say which",
                 prev, s->count, r->count);
        return false;
    case 'B':
        if (s->op == r->op && (r->op == '>' ? s->actual >= r->bound : s->actual <= r->bound))
            return true;
        snprintf(why, why_size, "%s: got %ld, wanted at %s %ld", r->site, s->actual,
                 r->op == '>' ? "least" : "most", r->bound);
        return false;
    case 'C':
        /* The teacher's expected value and tolerance; only the actual is the student's. */
        if (fabs(s->value - r->expected) <= r->within)
            return true;
        snprintf(why, why_size, "%s: got %.9g, wanted %.9g within %.3g", r->site, s->value,
                 r->expected, r->within);
        return false;
    case 'P':
        return judge_picture(r, s, why, why_size);
    case 'E':
        if (s->passed)
            return true;
        snprintf(why, why_size, "the test itself failed (its messages are above)");
        return false;
    default:
        snprintf(why, why_size, "the teacher's record has an entry F: it does not pass");
        return false;
    }
}

int main(int argc, char **argv)
{
    int a = 1;
    if (a + 1 < argc && strcmp(argv[a], "--owner") == 0) {
        char *end;
        long v = strtol(argv[a + 1], &end, 10);
        if (*end != '\0' || v < 0) {
            fprintf(stderr, "judge: error: --owner %s: want a user id\n", argv[a + 1]);
            return CANNOT_JUDGE;
        }
        owner = (uid_t)v;
        a += 2;
    }
    if (argc - a != 3) {
        fprintf(stderr, "usage: judge [--owner UID] REFERENCE RECORD OUTPUT_DIR\n");
        return CANNOT_JUDGE;
    }
    const char *reference_path = argv[a], *record_path = argv[a + 1];
    output_dir = argv[a + 2];

    FILE *ref = fopen(reference_path, "r");
    if (!ref) {
        printf("judge: cannot judge: no record of the teacher's solution for this test (%s)\n",
               reference_path);
        return CANNOT_JUDGE;
    }
    /* The teacher's record, whole, before anything is judged by it: entries
     * only, no failure, and the end of a run that passed. */
    {
        char line[LINE_MAX_LEN];
        Entry e = {0};
        bool bad = false, ok = true;
        while (ok && next_line(ref, line, sizeof line, &bad))
            ok = parse_entry(line, &e) && e.kind != 'F';
        if (!ok || bad || e.kind != 'E' || !e.passed) {
            fclose(ref);
            printf("judge: cannot judge: %s is not the record of a run that passed\n",
                   reference_path);
            return CANNOT_JUDGE;
        }
        rewind(ref);
    }
    /* The student's record: opened without following a link, read as input. */
    int fd = open(record_path, O_RDONLY | O_NOFOLLOW | O_CLOEXEC | O_NONBLOCK);
    FILE *rec = fd >= 0 ? fdopen(fd, "r") : NULL;
    if (!rec) {
        if (fd >= 0)
            close(fd);
        fclose(ref);
        printf("judge: failed: the test wrote no record (it did not start?)\n");
        return FAILED;
    }

    /* Both records in step. A B line stands for count checks: they are
     * taken one run at a time, so that runs split otherwise still align. */
    char line[LINE_MAX_LEN], why[2 * LINE_MAX_LEN] = "";
    char prev[NAME_LEN] = "the start";
    Entry want, got;
    unsigned long want_left = 0, got_left = 0;
    size_t checks = 0;
    int verdict = PASSED;
    /* After equality checks that differ (a D line), the records are read on
     * in step, only to name the first picture that differs: the hash of a
     * picture the test read is among those checks, and no message says so. */
    bool naming = false;
    char picture_why[2 * LINE_MAX_LEN];
    for (;;) {
        bool bad = false;
        if (want_left == 0) {
            if (!next_line(ref, line, sizeof line, &bad) || !parse_entry(line, &want) ||
                want.kind == 'F' || (want.kind == 'E' && !want.passed)) {
                printf("judge: cannot judge: %s is not the record of a run that passed\n",
                       reference_path);
                verdict = CANNOT_JUDGE;
                break;
            }
            want_left = want.kind == 'B' ? want.count : 1;
        }
        if (got_left == 0) {
            bool have = next_line(rec, line, sizeof line, &bad);
            bool parsed = have && parse_entry(line, &got);
            if (!parsed && naming)
                break; /* no picture to name: the words on the checks stand */
            if (!have) {
                snprintf(why, sizeof why, "%s after %s: the test did not finish (a crash, an "
                         "exit, a failed check?)",
                         bad ? "the record has a line that is not an entry" : "the record ends",
                         prev);
                verdict = FAILED;
                break;
            }
            if (!parsed) {
                snprintf(why, sizeof why, "the record has an entry that is not one (after %s)",
                         prev);
                verdict = FAILED;
                break;
            }
            got_left = got.kind == 'B' ? got.count : 1;
        }
        if (naming) {
            if (want.kind == 'E' || got.kind != want.kind)
                break;
            if (want.kind == 'P' && !judge_entry(&want, &got, prev, picture_why,
                                                 sizeof picture_why)) {
                size_t used = strlen(why);
                snprintf(why + used, sizeof why - used, "; the first picture that differs: %.1500s",
                         picture_why);
                break;
            }
        } else if (!judge_entry(&want, &got, prev, why, sizeof why)) {
            verdict = FAILED;
            if (want.kind != 'D' || got.kind != 'D')
                break;
            naming = true;
        }
        if (want.kind != 'D' && want.kind != 'E')
            snprintf(prev, sizeof prev, "%s", want.site);
        unsigned long step = want.kind == 'B' && got.kind == 'B'
                                 ? (want_left < got_left ? want_left : got_left) : 1;
        checks += want.kind == 'D' ? want.count : want.kind == 'E' ? 0 : step;
        want_left -= step;
        got_left -= step;
        if (want.kind == 'E' && !naming) {
            if (next_line(rec, line, sizeof line, &bad) || bad) {
                snprintf(why, sizeof why, "the record goes on past its end");
                verdict = FAILED;
            } else if (next_line(ref, line, sizeof line, &bad) || bad) {
                printf("judge: cannot judge: %s goes on past its end\n", reference_path);
                verdict = CANNOT_JUDGE;
            }
            break;
        }
    }
    fclose(ref);
    fclose(rec);
    if (verdict == FAILED)
        printf("judge: failed: %s\n", why);
    if (verdict != PASSED)
        return verdict;
    printf("judge: passed: %zu checks agree with the record of the teacher's solution\n", checks);
    return PASSED;
}
