/* test_file.c: a file is written whole or not at all (common/harness/file.c).
 *
 * The tests run as any user, root included, so none relies on file
 * permissions to make a write fail: they use a missing directory, /dev/full,
 * a directory in the way, a file size limit, or atomic_abort. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <dirent.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "harness/file.h"
#include "harness/image_io.h"
#include "test_support.h"

/* ---- helpers ---- */

static void write_plain(const char *path, const char *text)
{
    FILE *fp = fopen(path, "wb");
    assert_non_null(fp);
    fputs(text, fp);
    assert_int_equal(fclose(fp), 0);
}

/* The file's bytes must be exactly `text`. */
static void assert_file_holds(const char *path, const char *text)
{
    char buf[256];
    FILE *fp = fopen(path, "rb");
    if (!fp)
        fail_msg("%s is missing", path);
    size_t n = fread(buf, 1, sizeof buf - 1, fp);
    fclose(fp);
    buf[n] = '\0';
    if (n != strlen(text) || memcmp(buf, text, n) != 0)
        fail_msg("%s holds \"%s\", expected \"%s\"", path, buf, text);
}

/* The directory must hold exactly one entry, `only`: no temporary file left. */
static void assert_dir_holds_only(const char *dir, const char *only)
{
    DIR *d = opendir(dir);
    assert_non_null(d);
    int count = 0;
    char names[1024] = "";
    struct dirent *e;
    while ((e = readdir(d)) != NULL) {
        if (strcmp(e->d_name, ".") == 0 || strcmp(e->d_name, "..") == 0)
            continue;
        count++;
        strncat(names, " ", sizeof names - strlen(names) - 1);
        strncat(names, e->d_name, sizeof names - strlen(names) - 1);
    }
    closedir(d);
    if (count != 1 || strcmp(names + 1, only) != 0)
        fail_msg("%s holds:%s; expected only %s (a leftover is a temporary file)",
                 dir, names, only);
}

static void assert_error(const Error *err, const char *fmt, const char *path)
{
    char want[ERROR_MSG_MAX];
    snprintf(want, sizeof want, fmt, path);
    assert_string_equal(err->msg, want);
}

/* ---- atomic writes that succeed ---- */

static void commit_writes_every_byte_and_leaves_only_the_target(void **state)
{
    (void)state;
    const char *dir = test_dir("atomic_ok");
    const char *path = path_join(dir, "out.bin");
    AtomicFile f;
    Error err;
    assert_true(atomic_open(&f, path, &err));
    atomic_write(&f, "hello, ", 7);
    atomic_write(&f, "world", 5);
    assert_true(atomic_commit(&f, &err));
    assert_file_holds(path, "hello, world");
    assert_dir_holds_only(dir, "out.bin");
}

static void commit_replaces_an_existing_file(void **state)
{
    (void)state;
    const char *dir = test_dir("atomic_replace");
    const char *path = path_join(dir, "out.txt");
    write_plain(path, "old bytes");
    AtomicFile f;
    Error err;
    assert_true(atomic_open(&f, path, &err));
    assert_file_holds(path, "old bytes"); /* untouched until commit */
    atomic_write(&f, "new", 3);
    assert_true(atomic_commit(&f, &err));
    assert_file_holds(path, "new");
    assert_dir_holds_only(dir, "out.txt");
}

static void new_file_gets_the_usual_permissions(void **state)
{
    (void)state;
    /* fopen would create 0666 & ~umask; mkstemp alone would give 0600. */
    const char *path = path_join(test_dir("atomic_mode"), "out.txt");
    mode_t old = umask(022);
    AtomicFile f;
    Error err;
    bool opened = atomic_open(&f, path, &err);
    atomic_write(&f, "x", 1);
    bool committed = opened && atomic_commit(&f, &err);
    umask(old);
    assert_true(committed);
    struct stat st;
    assert_int_equal(stat(path, &st), 0);
    assert_int_equal(st.st_mode & 0777, 0644);
}

static void replaced_file_keeps_its_permissions(void **state)
{
    (void)state;
    const char *path = path_join(test_dir("atomic_keep_mode"), "private.txt");
    write_plain(path, "old");
    assert_int_equal(chmod(path, 0600), 0);
    AtomicFile f;
    Error err;
    assert_true(atomic_open(&f, path, &err));
    atomic_write(&f, "new", 3);
    assert_true(atomic_commit(&f, &err));
    struct stat st;
    assert_int_equal(stat(path, &st), 0);
    assert_int_equal(st.st_mode & 0777, 0600);
}

static void symbolic_link_is_written_through_and_stays_a_link(void **state)
{
    (void)state;
    /* As with "--out /dev/stdout > picture.png": the link's file gets the
     * bytes; renaming over the link itself would replace it by a file. */
    const char *dir = test_dir("atomic_symlink");
    char real[512], link_path[512];
    snprintf(real, sizeof real, "%s/real.txt", dir);
    snprintf(link_path, sizeof link_path, "%s/link.txt", dir);
    write_plain(real, "old");
    assert_int_equal(symlink("real.txt", link_path), 0);
    AtomicFile f;
    Error err;
    assert_true(atomic_open(&f, link_path, &err));
    atomic_write(&f, "new", 3);
    assert_true(atomic_commit(&f, &err));
    struct stat st;
    assert_int_equal(lstat(link_path, &st), 0);
    assert_true(S_ISLNK(st.st_mode));
    assert_file_holds(real, "new");
    assert_file_holds(link_path, "new");
}

static void file_in_the_current_directory_works(void **state)
{
    (void)state;
    /* A bare name has no '/': the temporary file goes in ".". */
    const char *dir = test_dir("atomic_bare_name");
    char cwd[4096];
    assert_non_null(getcwd(cwd, sizeof cwd));
    assert_int_equal(chdir(dir), 0);
    AtomicFile f;
    Error err;
    bool opened = atomic_open(&f, "bare.txt", &err);
    atomic_write(&f, "ok", 2);
    bool committed = opened && atomic_commit(&f, &err);
    assert_int_equal(chdir(cwd), 0);
    assert_true(committed);
    assert_file_holds(path_join(dir, "bare.txt"), "ok");
    assert_dir_holds_only(dir, "bare.txt");
}

/* ---- atomic writes that fail ---- */

static void missing_directory_fails_naming_the_path(void **state)
{
    (void)state;
    const char *dir = test_dir("atomic_missing_dir");
    const char *path = path_join(dir, "no/such/dir/x.png");
    AtomicFile f;
    Error err;
    assert_false(atomic_open(&f, path, &err));
    assert_error(&err, "cannot write %s: No such file or directory", path);
    assert_null(f.fp);
    atomic_abort(&f); /* harmless after a failed open */
    assert_false(file_exists(path_join(dir, "no")));
}

static void dev_full_fails_cleanly_and_stays_a_device(void **state)
{
    (void)state;
    /* /dev/full accepts the open and refuses every write: "No space left on
     * device", as a full disk would. It must not be replaced by a file. */
    AtomicFile f;
    Error err;
    assert_true(atomic_open(&f, "/dev/full", &err));
    atomic_write(&f, "some bytes", 10);
    assert_false(atomic_commit(&f, &err));
    assert_string_equal(err.msg, "cannot write /dev/full: No space left on device");

    Image im;
    assert_true(image_init(&im, 8, 8, &err));
    assert_false(image_write_png(&im, "/dev/full", &err));
    assert_string_equal(err.msg, "cannot write /dev/full: No space left on device");
    assert_false(write_pfm((const float[1]){1.0f}, 1, 1, "/dev/full", &err));
    assert_string_equal(err.msg, "cannot write /dev/full: No space left on device");
    image_free(&im);

    struct stat st;
    assert_int_equal(lstat("/dev/full", &st), 0);
    assert_true(S_ISCHR(st.st_mode));
}

static void directory_in_the_way_fails_and_is_kept(void **state)
{
    (void)state;
    const char *dir = test_dir("atomic_dir_target");
    const char *target = path_join(dir, "out.png");
    assert_int_equal(mkdir(target, 0777), 0);
    write_plain(path_join(target, "inside.txt"), "kept");
    AtomicFile f;
    Error err;
    assert_false(atomic_open(&f, target, &err));
    assert_error(&err, "cannot write %s: Is a directory", target);
    assert_file_holds(path_join(target, "inside.txt"), "kept");
    assert_dir_holds_only(dir, "out.png");
}

static void abort_keeps_the_existing_file_and_removes_the_temporary(void **state)
{
    (void)state;
    const char *dir = test_dir("atomic_abort");
    const char *path = path_join(dir, "out.txt");
    write_plain(path, "old bytes");
    AtomicFile f;
    Error err;
    assert_true(atomic_open(&f, path, &err));
    atomic_write(&f, "half of the new", 15);
    atomic_abort(&f);
    assert_file_holds(path, "old bytes");
    assert_dir_holds_only(dir, "out.txt");
}

#define SIZE_LIMIT 1024 /* bytes: far less than the write below */
#define WRITE_SIZE 8192

static void failed_write_keeps_the_existing_file(void **state)
{
    (void)state;
    /* A real write failure without permissions: a file size limit makes the
     * kernel refuse bytes past SIZE_LIMIT with EFBIG ("File too large"). No
     * output may happen while the limit holds, so assertions come after. */
    const char *dir = test_dir("atomic_write_fails");
    const char *path = path_join(dir, "out.txt");
    write_plain(path, "old bytes");
    static char big[WRITE_SIZE];
    memset(big, 'x', sizeof big);

    struct rlimit old_limit, limit;
    assert_int_equal(getrlimit(RLIMIT_FSIZE, &old_limit), 0);
    limit = old_limit;
    limit.rlim_cur = SIZE_LIMIT;
    void (*old_handler)(int) = signal(SIGXFSZ, SIG_IGN); /* else it kills us */
    assert_int_equal(setrlimit(RLIMIT_FSIZE, &limit), 0);

    AtomicFile f;
    Error err;
    bool opened = atomic_open(&f, path, &err);
    if (opened)
        atomic_write(&f, big, sizeof big);
    bool committed = opened && atomic_commit(&f, &err);

    setrlimit(RLIMIT_FSIZE, &old_limit);
    signal(SIGXFSZ, old_handler);
    assert_true(opened);
    assert_false(committed);
    assert_error(&err, "cannot write %s: File too large", path);
    assert_file_holds(path, "old bytes");
    assert_dir_holds_only(dir, "out.txt");
}

/* ---- read_file ---- */

static void read_file_returns_all_bytes_nuls_included(void **state)
{
    (void)state;
    const char *path = path_join(test_dir("read_file"), "data.bin");
    FILE *fp = fopen(path, "wb");
    assert_non_null(fp);
    assert_int_equal(fwrite("a\0b", 1, 3, fp), 3);
    fclose(fp);
    char *data;
    size_t len;
    Error err;
    assert_true(read_file(path, 3, &data, &len, &err)); /* exactly the limit */
    assert_int_equal(len, 3);
    assert_memory_equal(data, "a\0b", 4); /* and a NUL after the end */
    free(data);

    assert_false(read_file(path, 2, &data, &len, &err));
    assert_error(&err, "cannot read %s: it is larger than 2 bytes", path);
    assert_null(data);
}

static void read_file_of_an_empty_file_is_an_empty_string(void **state)
{
    (void)state;
    const char *path = path_join(test_dir("read_empty"), "empty.txt");
    write_plain(path, "");
    char *data;
    size_t len;
    Error err;
    assert_true(read_file(path, 100, &data, &len, &err));
    assert_int_equal(len, 0);
    assert_string_equal(data, "");
    free(data);
}

static void read_file_errors_name_the_path(void **state)
{
    (void)state;
    const char *dir = test_dir("read_errors");
    const char *missing = path_join(dir, "missing.obj");
    char *data;
    size_t len;
    Error err;
    assert_false(read_file(missing, 100, &data, &len, &err));
    assert_error(&err, "cannot read %s: No such file or directory", missing);
    assert_false(read_file(dir, 100, &data, &len, &err));
    assert_error(&err, "cannot read %s: Is a directory", dir);
}

/* ---- same_file, make_dirs ---- */

static void same_file_compares_device_and_inode(void **state)
{
    (void)state;
    const char *dir = test_dir("same_file");
    char a[512], b[512], c[512], a_dotted[512];
    snprintf(a, sizeof a, "%s/a.png", dir);
    snprintf(b, sizeof b, "%s/b.png", dir);
    snprintf(c, sizeof c, "%s/c.png", dir);
    snprintf(a_dotted, sizeof a_dotted, "%s/./a.png", dir);
    write_plain(a, "a");
    write_plain(c, "a"); /* same bytes, another file */
    assert_int_equal(link(a, b), 0); /* another name, same file */
    assert_true(same_file(a, a));
    assert_true(same_file(a, a_dotted));
    assert_true(same_file(a, b));
    assert_false(same_file(a, c));
    assert_false(same_file(a, path_join(dir, "missing.png")));
}

static void make_dirs_creates_parents_and_accepts_existing(void **state)
{
    (void)state;
    const char *dir = test_dir("make_dirs");
    const char *deep = path_join(dir, "x/y/z");
    Error err;
    assert_true(make_dirs(deep, &err));
    struct stat st;
    assert_int_equal(stat(deep, &st), 0);
    assert_true(S_ISDIR(st.st_mode));
    assert_true(make_dirs(deep, &err)); /* like mkdir -p: already there is fine */

    const char *file = path_join(dir, "file");
    write_plain(file, "");
    assert_false(make_dirs(path_join(file, "sub"), &err));
    assert_error(&err, "cannot create directory %s: a file of that name exists", file);
}

/* ---- identity, before the files exist ---- */

static void same_file_resolves_names_of_files_to_come(void **state)
{
    (void)state;
    const char *dir = test_dir("file_identity");
    char a[512], dotted[512], up[512], link_path[512], other[512];
    snprintf(a, sizeof a, "%s/a.png", dir);             /* does not exist */
    snprintf(dotted, sizeof dotted, "%s/./a.png", dir);
    snprintf(up, sizeof up, "%s/new/deeper/../../a.png", dir); /* new/ does not exist either */
    snprintf(link_path, sizeof link_path, "%s/l.png", dir);
    snprintf(other, sizeof other, "%s/b.png", dir);
    assert_int_equal(symlink("a.png", link_path), 0); /* dangling */
    assert_true(same_file(a, dotted));
    assert_true(same_file(a, up));
    assert_true(same_file(a, link_path));
    assert_false(same_file(a, other));
    char step[512], steps_dir[512];
    snprintf(steps_dir, sizeof steps_dir, "%s/st", dir);
    snprintf(step, sizeof step, "%s/st/../st/step_0012_depth.png", dir);
    assert_true(is_step_picture(step, steps_dir));
    snprintf(step, sizeof step, "%s/st/step_12.png", dir);
    assert_false(is_step_picture(step, steps_dir));
}

/* ---- outputs checked before anything is written ---- */

static void output_check_creates_nothing(void **state)
{
    (void)state;
    const char *dir = test_dir("output_check");
    Error err;
    assert_true(output_check(path_join(dir, "x/y/out.png"), &err));
    assert_true(output_check("-", &err));
    assert_false(output_check(path_join(dir, "x/y/"), &err));
    const char *ro = path_join(dir, "ro.txt");
    write_plain(ro, "old");
    assert_int_equal(chmod(ro, 0444), 0);
    assert_false(output_check(ro, &err));
    assert_error(&err, "cannot write %s: Permission denied", ro);
    AtomicFile f;
    assert_false(atomic_open(&f, ro, &err));
    assert_file_holds(ro, "old");
    assert_dir_holds_only(dir, "ro.txt"); /* neither x/ nor a temporary file */
    const char *fifo = path_join(dir, "p");
    assert_int_equal(mkfifo(fifo, 0666), 0);
    assert_false(output_check(fifo, &err));
    assert_error(&err, "cannot write %s: a pipe that nobody reads", fifo);
    char *data;
    size_t len;
    assert_false(read_file(fifo, 100, &data, &len, &err));
    assert_error(&err, "cannot read %s: not a regular file (a pipe)", fifo);
}

/* A name of 250 bytes is legal; ".NAME.XXXXXX" would not be: the temporary
 * name is shortened, the file gets its whole name. */
static void longest_names_can_be_written(void **state)
{
    (void)state;
    const char *dir = test_dir("atomic_long_name");
    char name[251];
    memset(name, 'n', 250);
    name[250] = '\0';
    const char *path = path_join(dir, name);
    AtomicFile f;
    Error err;
    assert_true(atomic_open(&f, path, &err));
    atomic_write(&f, "x", 1);
    assert_true(atomic_commit(&f, &err));
    assert_dir_holds_only(dir, name);
}

/* ---- a run's outputs: all published, or none ---- */

static void output_set_publishes_all_or_none(void **state)
{
    (void)state;
    const char *dir = test_dir("output_set");
    char a[512], b[512];
    snprintf(a, sizeof a, "%s/new/a.txt", dir);
    snprintf(b, sizeof b, "%s/b.txt", dir);
    write_plain(b, "old");
    Error err;
    AtomicFile f;
    output_set_begin();
    assert_true(make_dirs(path_join(dir, "new"), &err));
    assert_true(atomic_open(&f, a, &err));
    atomic_write(&f, "a", 1);
    assert_true(atomic_commit(&f, &err));
    assert_true(atomic_open(&f, b, &err));
    atomic_write(&f, "b", 1);
    assert_true(atomic_commit(&f, &err));
    assert_file_holds(b, "old"); /* not yet */
    output_set_abort();
    assert_dir_holds_only(dir, "b.txt"); /* new/ was made for the set: gone too */
    assert_file_holds(b, "old");

    output_set_begin();
    assert_true(atomic_open(&f, b, &err));
    atomic_write(&f, "b", 1);
    assert_true(atomic_commit(&f, &err));
    assert_true(output_set_publish(&err));
    assert_file_holds(b, "b");
    assert_dir_holds_only(dir, "b.txt");
}

/* A signal while a temporary file exists removes it; the status is 128 + the
 * signal. Run in a child, which sends the signal to itself. */
static void signals_remove_temporary_files(void **state)
{
    (void)state;
    const int sigs[] = {SIGINT, SIGTERM, SIGHUP};
    for (size_t i = 0; i < sizeof sigs / sizeof sigs[0]; i++) {
        const char *dir = test_dir("atomic_signal");
        char path[512];
        snprintf(path, sizeof path, "%s/out.bin", dir);
        fflush(stdout);
        pid_t pid = fork();
        assert_true(pid >= 0);
        if (pid == 0) {
            signal(sigs[i], SIG_DFL);
            AtomicFile f;
            Error err;
            output_set_begin();
            if (!atomic_open(&f, path, &err))
                _exit(3);
            atomic_write(&f, "x", 1);
            raise(sigs[i]);
            _exit(4); /* not reached */
        }
        int status;
        assert_int_equal(waitpid(pid, &status, 0), pid);
        assert_true(WIFEXITED(status));
        assert_int_equal(WEXITSTATUS(status), 128 + sigs[i]);
        DIR *d = opendir(dir);
        assert_non_null(d);
        struct dirent *e;
        while ((e = readdir(d)) != NULL)
            if (strcmp(e->d_name, ".") != 0 && strcmp(e->d_name, "..") != 0)
                fail_msg("signal %d left %s", sigs[i], e->d_name);
        closedir(d);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(commit_writes_every_byte_and_leaves_only_the_target),
        cmocka_unit_test(commit_replaces_an_existing_file),
        cmocka_unit_test(new_file_gets_the_usual_permissions),
        cmocka_unit_test(replaced_file_keeps_its_permissions),
        cmocka_unit_test(symbolic_link_is_written_through_and_stays_a_link),
        cmocka_unit_test(file_in_the_current_directory_works),
        cmocka_unit_test(missing_directory_fails_naming_the_path),
        cmocka_unit_test(dev_full_fails_cleanly_and_stays_a_device),
        cmocka_unit_test(directory_in_the_way_fails_and_is_kept),
        cmocka_unit_test(abort_keeps_the_existing_file_and_removes_the_temporary),
        cmocka_unit_test(failed_write_keeps_the_existing_file),
        cmocka_unit_test(read_file_returns_all_bytes_nuls_included),
        cmocka_unit_test(read_file_of_an_empty_file_is_an_empty_string),
        cmocka_unit_test(read_file_errors_name_the_path),
        cmocka_unit_test(same_file_compares_device_and_inode),
        cmocka_unit_test(make_dirs_creates_parents_and_accepts_existing),
        cmocka_unit_test(same_file_resolves_names_of_files_to_come),
        cmocka_unit_test(output_check_creates_nothing),
        cmocka_unit_test(longest_names_can_be_written),
        cmocka_unit_test(output_set_publishes_all_or_none),
        cmocka_unit_test(signals_remove_temporary_files),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
