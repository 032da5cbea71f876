# md-links.awk: the links of a Markdown page to files that are not there.
#
#   awk -v dir=DIR -v mode=fix|check [-v rows=1] -f tools/md-links.awk PAGE
#
# A link [words](path), an image ![alt](path) or an <img src="path"> whose
# path, read from DIR (the page's directory), names nothing:
#   fix    prints the page with such a link's words alone, and without such
#          an image; with rows=1, a table row that links lessons/... not there
#          goes whole (the README's table of lessons). make handout runs it
#          on every page of a handout: a later lesson's page, a diff that
#          shows the lesson's code, the teacher's guide are not there.
#   check  prints "PAGE:LINE: path" for each, and exits 1 if there is one.
# Code is left as it is: fenced blocks, and `spans`, whose links are examples.

function there(path,    p) {
    p = path
    sub(/#.*/, "", p)
    if (p == "" || p ~ /^[a-z]+:/)
        return 1
    if (!(p in known))
        known[p] = system("test -e \"" dir "/" p "\"") == 0
    return known[p]
}

function missing(path) {
    if (mode == "check")
        printf "%s:%d: %s\n", FILENAME, FNR, path
    found = 1
}

# Text outside code: each link to nothing by its words, each image of nothing out.
function fix(s,    out, rest, link, bang, words, path, tag, src) {
    out = ""
    rest = s
    while (match(rest, /!?\[[^]]*\]\([^)]*\)/)) {
        link = substr(rest, RSTART, RLENGTH)
        bang = substr(link, 1, 1) == "!"
        if (bang)
            link = substr(link, 2)
        words = substr(link, 2, index(link, "](") - 2)
        path = substr(link, index(link, "](") + 2)
        sub(/\)$/, "", path)
        out = out substr(rest, 1, RSTART - 1)
        if (there(path))
            out = out (bang ? "!" : "") link
        else {
            missing(path)
            out = out (bang ? "" : words)
        }
        rest = substr(rest, RSTART + RLENGTH)
    }
    s = out rest
    out = ""
    rest = s
    while (match(rest, /<img src="[^"]*"[^>]*>/)) {
        tag = substr(rest, RSTART, RLENGTH)
        src = tag
        sub(/^<img src="/, "", src)
        sub(/".*/, "", src)
        out = out substr(rest, 1, RSTART - 1)
        if (there(src))
            out = out tag
        else
            missing(src)
        rest = substr(rest, RSTART + RLENGTH)
    }
    return out rest
}

/^[ \t]*(```|~~~)/ {
    fence = !fence
    if (mode == "fix")
        print
    next
}
fence {
    if (mode == "fix")
        print
    next
}
rows && /^\| / && match($0, /\]\(lessons\/[^)]*\)/) {
    if (!there(substr($0, RSTART + 2, RLENGTH - 3))) {
        missing(substr($0, RSTART + 2, RLENGTH - 3))
        next
    }
}
{
    n = split($0, part, "`")
    line = ""
    for (i = 1; i <= n; i++)
        line = line (i > 1 ? "`" : "") (i % 2 == 1 ? fix(part[i]) : part[i])
    if (mode == "fix")
        print line
}
END {
    if (mode == "check")
        exit found
}
