-- links.lua: the pandoc filter of the book (tools/site/build.sh).
--
-- Links: a link to a page of the series (X.md, README.md) goes to the page
-- the book makes of it (X.html, index.html), its #fragment kept; every
-- other link stays as it is, since the book keeps the tree's layout
-- (docs/, docs/images/, lessons/NN/ ...) and copies what the pages link to.
--
-- Search: each section of the page (its title, and every heading of level
-- 2 with the text under it) goes to the file named by the metadata field
-- search_out, as one JSON object a line: {"page", "title", "id", "text"}.

local function html_of(target)
  if target:match("^%a[%w+.-]*:") then -- http:, https:, mailto: ...
    return target
  end
  local path, fragment = target:match("^([^#]*)(#?.*)$")
  if path:match("README%.md$") then
    return path:gsub("README%.md$", "index.html") .. fragment
  end
  if path:match("%.md$") then
    return path:gsub("%.md$", ".html") .. fragment
  end
  return target
end

-- A file of a lesson or of common/ named in code (`lessons/02_zbuffer/main.c`,
-- `common/target.h`) links to that file when the book holds it (in the
-- directory the metadata field site_dir names, where build.sh copies them
-- first; the student edition holds only the files the lessons inherit), and
-- a lesson's own directory (`lessons/02_zbuffer/`) to its page: so the
-- pages' lists of the files to read open them.
local function up_from(page) -- the way up from a page of the site to its top
  return (page:gsub("[^/]*$", ""):gsub("[^/]+/", "../"))
end

local site_dir, up = nil, ""

local function exists(path)
  local f = io.open(path, "r")
  if f then f:close() end
  return f ~= nil
end

function Code(el)
  if not site_dir then
    return nil
  end
  local t = el.text
  if (t:match("^lessons/%d%d_[%w_]+/[%w_/]*%.[ch]$") or t:match("^common/[%w_/]*%.[ch]$"))
     and exists(site_dir .. "/" .. t) then
    return pandoc.Link({el}, up .. t)
  end
  if t:match("^lessons/%d%d_[%w_]+/$") and exists(t .. "README.md") then
    return pandoc.Link({el}, up .. t .. "index.html")
  end
  return nil
end

function Link(el)
  el.target = html_of(el.target)
  -- A link does not hold another (code already linked, above).
  local content = pandoc.List()
  for _, x in ipairs(el.content) do
    if x.t == "Link" then content:extend(x.content) else content:insert(x) end
  end
  el.content = content
  return el
end

-- Run it here: after a sh or console block, each command of it that runs a
-- lesson (build/bin/NN_name and its arguments, no shell around it) gets a
-- Run button and an editable command line (site.js, worker.js).
local function escape_html(s)
  return (s:gsub("&", "&amp;"):gsub("<", "&lt;"):gsub(">", "&gt;"):gsub('"', "&quot;"))
end

-- The page runs only the lessons. A file that another program of the page
-- makes (build/tools/make_obj knot out/knot.obj), one that no lesson command
-- before it names, is not there in the page: a lesson command that reads it
-- gets no Run button.
local named, made_outside = {}, {}

local function lesson_commands(block)
  local console = block.classes:includes("console")
  if not (console or block.classes:includes("sh")) then
    return {}
  end
  local found = {}
  for line in (block.text:gsub("%s*\\\n%s*", " ") .. "\n"):gmatch("([^\n]*)\n") do
    local cmd = line
    if console then
      cmd = line:match("^%$ (.*)$")
    end
    if cmd then
      cmd = cmd:gsub("%s+#.*$", ""):gsub("%s+$", "")
      local lesson = cmd:match("^build/bin/(%d%d_[%w_]+)")
      local outside = false
      for word in cmd:gmatch("%S+") do
        if lesson then
          outside = outside or made_outside[word] or false
          named[word] = true
        elseif cmd:match("^build/") and word:find("/") and not word:match("^build/")
               and not word:match("^%-") and not named[word] then
          made_outside[word] = true
        end
      end
      if lesson and not outside and not cmd:find("[|&;<>()$`\\'\"*?]") then
        table.insert(found, {lesson = lesson, cmd = cmd})
      end
    end
  end
  return found
end

-- A live figure: a comment <!-- figure: KIND NN_name [ARGS] --> on a page
-- (invisible on GitHub) becomes a figure that runs the lesson in the page
-- (site.js). steps: its picture after each face, on a slider, and what
-- --trace prints for any pixel clicked. flags: a choice for each argument
-- --flag=a|b|c, and the picture (or the one show=--flag writes) and summary
-- of the lesson run with them. It is the lesson's own output, so it cannot
-- disagree with the C code.
function RawBlock(el)
  if el.format ~= "html" then
    return nil
  end
  local kind, lesson, args = el.text:match("^<!%-%- figure: (%a+) (%d%d_[%w_]+)(.-)%s*%-%->%s*$")
  if not kind then
    return nil
  end
  local title = kind == "steps" and
    'The depth test, face by face: press the button to draw the scene in the page, move ' ..
    'the slider to see the picture after each face, and click a pixel to see every ' ..
    'fragment that reached it, as --trace prints it.' or
    'Try it: choose the flags, and the lesson runs in the page with them; the picture and ' ..
    'the summary are its own.'
  local button = kind == "steps" and "Draw it face by face" or "Draw it"
  return pandoc.RawBlock("html", string.format(
    '<div class="figure-live" data-kind="%s" data-lesson="%s" data-args="%s">' ..
    '<p class="figure-title">%s</p>' ..
    '<div class="figure-choices"></div>' ..
    '<button type="button" class="figure-start">%s</button>' ..
    '<div class="figure-body" hidden><input class="figure-slider" type="range" min="0" ' ..
    'value="0" aria-label="After how many faces"><span class="figure-step"></span>' ..
    '<pre class="figure-trace">Click a pixel of the picture.</pre></div></div>',
    kind, lesson, escape_html((args:gsub("^%s+", ""))), title, button))
end

local said_one_thread = false -- lesson 10's note, once a page

function CodeBlock(block)
  local cmds = lesson_commands(block)
  if #cmds == 0 then
    return nil
  end
  local html = {}
  for _, c in ipairs(cmds) do
    if c.lesson == "10_fast_raster" and not said_one_thread then
      said_one_thread = true
      table.insert(html, '<p class="run-note">In the page, lesson 10 runs on one thread ' ..
        'with plain C blocks (no x86 SIMD) and says so; a command asking for more threads ' ..
        'is refused here. Its speed is measured natively, by make bench ' ..
        '(<a href="performance.html">performance</a>).</p>')
    end
    table.insert(html, string.format(
      '<div class="run" data-lesson="%s"><div class="run-bar">' ..
      '<button type="button" class="run-button">Run</button>' ..
      '<input class="run-cmd" type="text" value="%s" spellcheck="false" ' ..
      'aria-label="A command to run here, in the page"></div>' ..
      '<div class="run-result" hidden><pre class="run-out"></pre>' ..
      '<div class="run-pictures"></div></div></div>',
      c.lesson, escape_html(c.cmd)))
  end
  return {block, pandoc.RawBlock("html", table.concat(html, "\n"))}
end

local function json_string(s)
  s = s:gsub('[%c"\\]', function(c)
    if c == '"' then return '\\"' end
    if c == "\\" then return "\\\\" end
    if c == "\n" then return "\\n" end
    if c == "\t" then return "\\t" end
    return string.format("\\u%04x", c:byte())
  end)
  return '"' .. s .. '"'
end

-- A block as plain text, list items and table cells apart.
local function plain_text(block)
  local ok, text = pcall(pandoc.write, pandoc.Pandoc({block}), "plain")
  if not ok then
    return pandoc.utils.stringify(block)
  end
  return (text:gsub("%s+", " "))
end

function Pandoc(doc)
  local out_path = doc.meta.search_out and pandoc.utils.stringify(doc.meta.search_out)
  local page = doc.meta.page_url and pandoc.utils.stringify(doc.meta.page_url) or ""
  if not out_path or out_path == "" then
    return doc
  end
  local sections, current = {}, nil
  local function start(title, id)
    current = {title = title, id = id, text = {}}
    table.insert(sections, current)
  end
  for _, block in ipairs(doc.blocks) do
    if block.t == "Header" and block.level <= 2 then
      start(pandoc.utils.stringify(block.content), block.identifier)
    elseif current == nil then
      start(page, "")
    end
    if block.t ~= "Header" and block.t ~= "CodeBlock" and block.t ~= "RawBlock" then
      table.insert(current.text, plain_text(block))
    end
  end
  local f = assert(io.open(out_path, "w"))
  for _, s in ipairs(sections) do
    f:write("{\"page\":", json_string(page), ",\"title\":", json_string(s.title),
            ",\"id\":", json_string(s.id), ",\"text\":",
            json_string(table.concat(s.text, " ")), "}\n")
  end
  f:close()
  return doc
end

-- The metadata first (site_dir, and the page's way up), then the page.
return {
  {Meta = function(meta)
    site_dir = meta.site_dir and pandoc.utils.stringify(meta.site_dir) or nil
    up = up_from(meta.page_url and pandoc.utils.stringify(meta.page_url) or "")
  end},
  {Code = Code, Link = Link, RawBlock = RawBlock, CodeBlock = CodeBlock, Pandoc = Pandoc},
}
