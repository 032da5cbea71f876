/* row.c: the program around lesson 01 (see row.h). */
#include "row.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "harness/ascii.h"
#include "harness/compare.h"
#include "harness/file.h"
#include "pictures.h"
#include "harness/steps.h"
#include "harness/trace.h"
#include "world.h"

enum { FLAG_SCENE_OUT, FLAG_YBUFFER_OUT, FLAG_ORDER, FLAG_SEGMENTS, FLAG_COUNT };

static const LessonFlag FLAGS[FLAG_COUNT] = {
    [FLAG_SCENE_OUT] = {"--scene-out", "FILE.png", "also draw the world from above (width x 500)"},
    [FLAG_YBUFFER_OUT] = {"--ybuffer-out", "FILE.png", "also write the y-buffer as a grey strip"},
    [FLAG_ORDER] = {"--order", "PERM", "draw the segments in this order, e.g. 312 or 3,1,2"},
    [FLAG_SEGMENTS] = {"--segments", "FILE", "draw FILE's segments, a line 'x0 y0 x1 y1 r g b' each"},
};

static const LessonCli CLI = {
    .program = "01_ybuffer",
    .purpose = "draw segments of a 2-D world seen from above into one row of pixels, "
               "keeping the nearest (largest) y per column",
    .groups = CLI_TRACE | CLI_ASCII | CLI_COMPARE | CLI_STEPS,
    .extra = FLAGS,
    .n_extra = FLAG_COUNT,
    .defaults = {.out = "out/01_ybuffer.png", .width = 800, .height = 16},
};

/* What --trace and --ascii show: the y-buffer keeps y, and larger is nearer. */
static const DepthRule Y_RULE = {"y-buffer", "y", "segment", LARGER_IS_NEARER};

/* Two outputs with one name would overwrite each other; none may replace an
 * input (--segments, --compare). The diff picture of --compare is an output. */
static bool check_outputs(const Options *opt, Error *err)
{
    enum { OUTPUTS = 4, PATHS = 6 };
    char diff[PATH_TEXT_MAX];
    bool has_diff = opt->compare && compare_diff_path(opt->out, diff, sizeof diff);
    const char *name[PATHS] = {"--out", "--scene-out", "--ybuffer-out",
                               "the diff picture of --out", "--segments", "--compare"};
    const char *path[PATHS] = {opt->out, opt->extra[FLAG_SCENE_OUT], opt->extra[FLAG_YBUFFER_OUT],
                               has_diff ? diff : NULL, opt->extra[FLAG_SEGMENTS], opt->compare};
    if (is_stdout_name(opt->out))
        path[0] = NULL; /* standard output: no file */
    for (int i = 1; i < PATHS; i++)
        if (is_stdout_name(path[i]))
            return error_set(err, "%s: '-' (standard output) is for --out only; name a file",
                             name[i]);
    for (int i = 0; i < OUTPUTS; i++)
        for (int j = i + 1; j < PATHS; j++) {
            if (!path[i] || !path[j])
                continue;
            if (same_file(path[i], path[j]))
                return error_set(err, "%s and %s both name %s", name[i], name[j], path[j]);
        }
    for (int i = 0; opt->steps_dir && i < PATHS; i++) {
        if (!path[i])
            continue;
        if (same_file(path[i], opt->steps_dir))
            return error_set(err, "%s and --steps both name %s", name[i], path[i]);
        if (is_step_picture(path[i], opt->steps_dir))
            return error_set(err, "%s names %s, where --steps writes its pictures", name[i],
                             path[i]);
    }
    return true;
}

/* Before anything is drawn: every output can be written (a failure while
 * running, status 1, with nothing made). */
static bool outputs_writable(const Options *opt, Error *err)
{
    char diff[PATH_TEXT_MAX];
    bool has_diff = opt->compare && compare_diff_path(opt->out, diff, sizeof diff);
    const char *path[] = {opt->out, opt->extra[FLAG_SCENE_OUT], opt->extra[FLAG_YBUFFER_OUT],
                          has_diff ? diff : NULL};
    for (size_t i = 0; i < sizeof path / sizeof path[0]; i++)
        if (path[i] && !output_check(path[i], err))
            return false;
    return !opt->steps_dir || output_dir_check(opt->steps_dir, err);
}

static bool load_segments(const Options *opt, Segment **segs, int *count, Error *err)
{
    const char *file = opt->extra[FLAG_SEGMENTS];
    return file ? read_segments(file, segs, count, err) : default_segments(segs, count, err);
}

static bool write_outputs(const YBuffer *yb, const Segment *segs, int count, const Options *opt,
                          Error *err)
{
    Image im;
    bool ok = render_picture(yb, segs, opt->height, &im, err);
    if (ok) {
        ok = write_picture(&im, opt->out, err);
        image_free(&im);
    }
    const char *ybuffer_out = opt->extra[FLAG_YBUFFER_OUT];
    GreyScale scale = grey_scale_of(segs, count, yb->width);
    if (ok && ybuffer_out && (ok = ybuffer_picture(yb, scale, opt->height, &im, err))) {
        ok = write_picture(&im, ybuffer_out, err);
        image_free(&im);
    }
    const char *scene_out = opt->extra[FLAG_SCENE_OUT];
    if (ok && scene_out && (ok = scene_picture(segs, count, yb, &im, err))) {
        ok = write_picture(&im, scene_out, err);
        image_free(&im);
    }
    return ok;
}

/* --trace, --ascii and --compare, once the picture is written (common/harness/trace.h,
 * ascii.h, compare.h). Returns EXIT_OK, EXIT_IMAGES_DIFFER or EXIT_RUN_FAILED. */
static int report_tools(const YBuffer *yb, const Segment *segs, const Options *opt, Error *err)
{
    if (opt->trace_set) {
        int x = opt->trace_x, owner = yb->owner[x];
        char where[32];
        snprintf(where, sizeof where, "column %d", x);
        trace_print(stdout, &yb->trace, &Y_RULE, where, owner == NO_SEGMENT ? NO_FACE : owner + 1,
                    y_as_stored(yb->y[x]));
    }
    if (opt->ascii) {
        float row[ASCII_MAX_WIDTH];
        for (int x = 0; x < yb->width; x++)
            row[x] = yb->owner[x] == NO_SEGMENT ? NAN : (float)yb->y[x];
        ascii_print(stdout, row, yb->width, 1, &Y_RULE);
    }
    if (!opt->compare)
        return EXIT_OK;
    Image im;
    if (!render_picture(yb, segs, opt->height, &im, err))
        return EXIT_RUN_FAILED;
    int status = compare_picture(stdout, &im, opt->compare, opt->out, err);
    image_free(&im);
    return status;
}

static void print_written(const Options *opt, int count)
{
    printf("wrote %s", opt->out);
    if (opt->extra[FLAG_YBUFFER_OUT])
        printf(", %s", opt->extra[FLAG_YBUFFER_OUT]);
    if (opt->extra[FLAG_SCENE_OUT])
        printf(", %s", opt->extra[FLAG_SCENE_OUT]);
    printf("\n");
    if (opt->steps_dir)
        printf("wrote steps 0 to %d into %s (step_NNNN.png, step_NNNN_depth.png)\n", count,
               opt->steps_dir);
}


int row_load(Row *row, int argc, char **argv)
{
    signals_begin(CLI.program); /* a signal from now on prints one line */
    memset(row, 0, sizeof *row);
    Options *opt = &row->opt;
    int status = cli_parse(&CLI, argc, argv, opt);
    if (status != CLI_CONTINUE)
        return status;
    Error *err = &row->err;
    if (!check_outputs(opt, err))
        status = EXIT_USAGE;
    else if (!load_segments(opt, &row->segs, &row->count, err) || !outputs_writable(opt, err))
        status = EXIT_RUN_FAILED;
    else if (!(row->order = malloc(((size_t)row->count + 1) * sizeof *row->order)))
        status = EXIT_RUN_FAILED, error_set(err, "out of memory for %d segments", row->count);
    else if (!parse_order(opt->extra[FLAG_ORDER], row->count, row->order, err))
        status = EXIT_USAGE;
    else if (!ybuffer_init(&row->yb, opt->width, err))
        status = EXIT_RUN_FAILED;
    else if (opt->steps_dir && row->count > STEPS_MAX_FACES)
        status = EXIT_RUN_FAILED,
        error_set(err, "--steps: there are %d segments; --steps writes two pictures "
                       "per segment and takes at most %d", row->count, STEPS_MAX_FACES);
    else
        status = ROW_GO;
    if (status == ROW_GO && opt->trace_set)
        ybuffer_trace_column(&row->yb, opt->trace_x);
    if (status == ROW_GO)
        output_set_begin(); /* every file of the run is published by row_end, or none */
    row->status = status == ROW_GO ? EXIT_OK : status;
    return status == ROW_GO ? ROW_GO : row_end(row);
}

bool row_step(Row *row, int step)
{
    if (!row->opt.steps_dir)
        return true;
    GreyScale scale = grey_scale_of(row->segs, row->count, row->yb.width);
    if (write_step_pictures(&row->yb, row->segs, scale, row->opt.height, row->opt.steps_dir,
                            step, &row->err))
        return true;
    row->status = EXIT_RUN_FAILED;
    return false;
}

bool row_write(Row *row)
{
    if (write_outputs(&row->yb, row->segs, row->count, &row->opt, &row->err))
        return true;
    row->status = EXIT_RUN_FAILED;
    return false;
}

/* The summary goes to standard output, or to standard error when the
 * picture went there (--out -). */
bool row_report(Row *row)
{
    bool to_stderr = is_stdout_name(row->opt.out);
    int saved = to_stderr ? stdout_to_stderr_begin() : -1;
    print_summary(stdout, &row->yb, row->segs, row->count, row->order);
    print_written(&row->opt, row->count);
    row->status = report_tools(&row->yb, row->segs, &row->opt, &row->err);
    if (to_stderr)
        stdout_to_stderr_end(saved);
    return row->status != EXIT_RUN_FAILED;
}

int row_end(Row *row)
{
    /* Lost output on standard output fails the run, and then no file is
     * published either: all or nothing. */
    if (row->status != EXIT_RUN_FAILED && row->status != EXIT_USAGE &&
        !stdout_flush(&row->err))
        row->status = EXIT_RUN_FAILED;
    if (row->status == EXIT_RUN_FAILED || row->status == EXIT_USAGE)
        output_set_abort();
    else if (!output_set_publish(&row->err))
        row->status = EXIT_RUN_FAILED;
    int status = row->status;
    if (status == EXIT_USAGE || status == EXIT_RUN_FAILED)
        error_report(CLI.program, &row->err, status);
    ybuffer_free(&row->yb);
    free(row->order);
    free(row->segs);
    return status;
}
