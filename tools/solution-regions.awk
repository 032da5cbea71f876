# solution-regions.awk: the solution regions of a lesson's source files.
#
# A region marks the code a lesson teaches, for make handout to take out:
#
#     /* SOLUTION BEGIN: a hint for the student (may go on over
#      * several lines) */
#     ...the code the student is to write...
#     /* SOLUTION STUB
#     ...what the handout has in its place, so that it still compiles...
#     */
#     /* SOLUTION END */
#
# The stub is optional; its lines are code of their own and cannot contain a
# /* comment */ (a // comment is fine). Markdown files mark regions with
# <!-- SOLUTION BEGIN: hint -->, <!-- SOLUTION STUB ... -->, <!-- SOLUTION END -->.
# Markers stand alone on their lines; regions do not nest.
#
# Run with -v mode=...:
#   strip    prints the file as the student gets it: each region replaced by
#            a TODO(student): comment with its hint, then its stub
#   clean    prints the file as the teacher reads it, without the markers
#            and the stubs (make diff compares lessons this way); with
#            -v into=DIR, each file into DIR/<its name> instead
#   regions  prints "FILE:LINE<TAB>hint" for each region
#   lines    prints "FILE:LINE<TAB>code" for each line only the solution has:
#            a line of a region of code (a region of a page only hides a quote
#            of the code), not of its markers or stub, that says something (see
#            significant) and is not also a line outside the regions (or in a
#            stub) of any of the files read. "code" is the line as code_of
#            gives it: the form make handout looks for in the handout.
#   exprs    prints "FILE:LINE<TAB>expr" for each solution expression: a
#            solution line, and the expression it computes (what follows its
#            "return" or its "="), with all white space taken out, when it is
#            at least MIN_EXPR characters long, has a name in it that is not a
#            keyword, and is not in the code outside the regions (or a stub).
#            make handout looks for these anywhere in the handout, prose and
#            comments included, with white space taken out there too.
#   find     with -v lines=LIST, a list that mode=lines printed: reads the
#            files named as plain text, without regions, and prints
#            "FILE:LINE<TAB>WHERE<TAB>code" for each line whose code is a
#            line of the list (WHERE: where the list found it). make handout
#            and the book's student edition look for leaks with it.
# A malformed marker is reported as "FILE:LINE: ..." on stderr, exit status 1.

function trim(s) {
    sub(/^[ \t\r]+/, "", s)
    sub(/[ \t\r]+$/, "", s)
    return s
}

# The code of a line: trimmed, without a trailing /* ... */ or // comment and
# without a final ";" (so that a function's header and its declaration in a
# header file are the same line).
function code_of(s,    i) {
    s = trim(s)
    i = index(s, "/*")
    if (i > 1) s = substr(s, 1, i - 1)
    i = index(s, "//")
    if (i > 1) s = substr(s, 1, i - 1)
    s = trim(s)
    sub(/;$/, "", s)
    return s
}

# Worth looking for: at least MIN_CODE characters, not a comment, and a name
# in it that is not a keyword of C. ("} else {" or "return false;" is in every
# file; it gives nothing away.)
function significant(c,    words, n, i) {
    if (length(c) < MIN_CODE || c ~ /^(\/\*|\*|\/\/|<!--)/) return 0
    n = split(c, words, /[^A-Za-z0-9_]+/)
    for (i = 1; i <= n; i++)
        if (words[i] ~ /^[A-Za-z_]/ && !(words[i] in KEYWORD)) return 1
    return 0
}

function fail(msg) { fail_at(FNR, msg) }

function fail_at(n, msg) {
    printf "%s:%d: %s\n", FILENAME, n, msg > "/dev/stderr"
    failed = 1
    exit 1
}

function starts_with(s, p) {
    return substr(s, 1, length(p)) == p
}

# The hint text of a BEGIN marker line, or of a line that continues it.
function hint_part(s,    i) {
    s = trim(s)
    if (starts_with(s, OPEN " SOLUTION BEGIN:"))
        s = substr(s, length(OPEN " SOLUTION BEGIN:") + 1)
    else if (OPEN == "/*")
        sub(/^\*[ \t]?/, "", s) # " * more hint" continuation lines
    i = index(s, CLOSE)
    if (i > 0) {
        if (trim(substr(s, i + length(CLOSE))) != "")
            fail("nothing may follow the end of a SOLUTION BEGIN marker on its line")
        s = substr(s, 1, i - 1)
    }
    return trim(s)
}

# The TODO(student) comment, wrapped to fit in WIDTH columns.
function print_todo(indent, hint,    n, words, i, line, first, limit) {
    n = split(hint, words, /[ \t]+/)
    limit = WIDTH - length(indent)
    first = 1
    line = (OPEN == "/*") ? "/* TODO(student):" : "> **TODO(student):**"
    for (i = 1; i <= n; i++) {
        if (words[i] == "") continue
        if (length(line) + 1 + length(words[i]) > limit - 3 && !first_word_on(line)) {
            print indent line
            line = (OPEN == "/*") ? " *" : ">"
        }
        line = line " " words[i]
    }
    print indent line ((OPEN == "/*") ? " */" : "")
}

function first_word_on(line) {
    return line == " *" || line == ">" || line == "/* TODO(student):" || line == "> **TODO(student):**"
}

# A line of the file as the teacher reads it (mode=clean): on stdout, or into
# DIR/<the file's name> with -v into=DIR.
function clean(line) {
    if (into == "") print line
    else print line > out
}

BEGIN {
    if (mode == "find")
        while ((getline l < lines) > 0) {
            tab = index(l, "\t")
            where[substr(l, tab + 1)] = substr(l, 1, tab - 1)
        }
}

mode == "find" {
    c = code_of($0)
    if (c in where) printf "%s:%d\t%s\t%s\n", FILENAME, FNR, where[c], c
    next
}

FNR == 1 {
    if (state != "") {
        printf "%s:%d: the SOLUTION region begun here has no SOLUTION END\n", prev_file, begin_line > "/dev/stderr"
        failed = 1
        exit 1
    }
    prev_file = FILENAME
    if (into != "") {
        if (out != "") close(out)
        out = FILENAME
        sub(/.*\//, "", out)
        out = into "/" out
        printf "" > out
    }
    if (FILENAME ~ /\.md$/) { OPEN = "<!--"; CLOSE = "-->" }
    else { OPEN = "/*"; CLOSE = "*/" }
    state = ""
}

{
    line = $0
    t = trim(line)

    if (state == "hint") { # the BEGIN marker goes on over this line
        hint = hint " " hint_part(line)
        if (index(t, CLOSE) > 0) state = "code"
        next
    }
    if (state == "stub") {
        if (t == CLOSE) { state = "code"; next }
        if (index(line, "SOLUTION ") > 0 && t ~ /SOLUTION (BEGIN|STUB|END)/)
            fail("a SOLUTION marker inside a stub: is the stub's closing " CLOSE " missing?")
        if (mode == "strip") stub[++nstub] = line
        outside[code_of(line)] = 1 # the stub is in the handout: its lines give nothing away
        outside_text = outside_text squeeze(line) "\n"
        next
    }

    if (starts_with(t, OPEN " SOLUTION")) {
        if (starts_with(t, OPEN " SOLUTION BEGIN:")) {
            if (state != "") fail("SOLUTION BEGIN inside another region (regions do not nest)")
            state = "hint"
            indent = line
            sub(/[^ \t].*$/, "", indent)
            begin_line = FNR
            nstub = 0
            had_stub = 0
            hint = hint_part(line)
            if (index(t, CLOSE) > 0) state = "code"
            next
        }
        if (t == OPEN " SOLUTION STUB") {
            if (state != "code") fail("SOLUTION STUB outside a solution region")
            if (had_stub) fail("a second SOLUTION STUB in one region")
            had_stub = 1
            state = "stub"
            next
        }
        if (t == OPEN " SOLUTION END " CLOSE) {
            if (state != "code") fail("SOLUTION END without a SOLUTION BEGIN before it")
            state = ""
            if (hint == "") fail_at(begin_line, "a SOLUTION BEGIN marker without a hint")
            if (mode == "regions") printf "%s:%d\t%s\n", FILENAME, begin_line, hint
            if (mode == "strip") {
                print_todo(indent, hint)
                for (i = 1; i <= nstub; i++) print stub[i]
            }
            next
        }
        fail("malformed SOLUTION marker (the forms are: " OPEN " SOLUTION BEGIN: hint " CLOSE \
             ", " OPEN " SOLUTION STUB, " OPEN " SOLUTION END " CLOSE ")")
    }

    if (state == "code") {
        if (mode == "clean") clean(line)
        c = code_of(line)
        # Solution lines are those of the code; a page's region only hides a quote.
        if (OPEN == "/*" && significant(c)) { sol_code[++nsol] = c; sol_where[nsol] = FILENAME ":" FNR }
        next
    }
    if (mode == "strip") print line
    if (mode == "clean") clean(line)
    outside[code_of(line)] = 1
    if (OPEN == "/*" && t !~ /^(\/\*|\*|\/\/)/) outside_text = outside_text squeeze(code_of(line)) "\n"
}

# A line without any white space: how expressions are compared.
function squeeze(s) {
    gsub(/[ \t\r\n]+/, "", s)
    return s
}

# What a solution line computes: after its "return", or after its "=" (not
# "==", "<=", ">=", "!="), or the whole line.
function expr_of(c,    i, rest) {
    if (c ~ /^return[ \t(]/) return substr(c, 7)
    for (i = 1; i <= length(c); i++) {
        if (substr(c, i, 1) != "=") continue
        if (substr(c, i + 1, 1) == "=" || substr(c, i - 1, 1) ~ /[=<>!+\-*\/]/) { i++; continue }
        rest = substr(c, i + 1)
        return rest
    }
    return c
}

function print_exprs(    i, seen, k, cand, n, e) {
    for (i = 1; i <= nsol; i++) {
        n = 0
        cand[++n] = squeeze(sol_code[i])
        cand[++n] = squeeze(expr_of(sol_code[i]))
        for (k = 1; k <= n; k++) {
            e = cand[k]
            if (length(e) < MIN_EXPR || !significant(e) || (e in seen)) continue
            seen[e] = 1
            if (index(outside_text, e) == 0) printf "%s\t%s\n", sol_where[i], e
        }
    }
}

# The solution lines of all the files, once all are read: a line that is
# outside the regions in any of them is not one that only the solution has.
function print_lines(    i) {
    for (i = 1; i <= nsol; i++)
        if (!(sol_code[i] in outside))
            printf "%s\t%s\n", sol_where[i], sol_code[i]
}

BEGIN {
    MIN_CODE = 8
    MIN_EXPR = 8
    split("auto bool break case char const continue default do double else enum extern " \
          "false float for goto if inline int long register restrict return short signed " \
          "sizeof static struct switch true typedef union unsigned void volatile while NULL",
          kw, " ")
    for (i in kw) KEYWORD[kw[i]] = 1
    WIDTH = 80
    state = ""
    prev_file = ""
}

END {
    if (failed) exit 1
    if (state != "") {
        printf "%s:%d: the SOLUTION region begun here has no SOLUTION END\n", FILENAME, begin_line > "/dev/stderr"
        exit 1
    }
    if (mode == "lines") print_lines()
    if (mode == "exprs") print_exprs()
}
