-- book.lua: one page of the series made ready to join the others in one
-- document, for the book's EPUB and PDF (tools/site/build.sh). Metadata:
-- page, the page's path in the tree (docs/02_zbuffer.md, README.md).
--
-- Every identifier gets the page's name in front (02_zbuffer--running-it),
-- and the page's title is named after it, so that ids stay apart across pages;
-- a link to a page, or to a heading of one, goes there inside the document;
-- a picture's path is taken from the top of the tree; a link to any other
-- file of the tree (a diff, a lesson's file), which a book cannot hold,
-- keeps its text, and is no longer a link.

local page, dir, stem

local function stem_of(path)
  local name = path:match("([^/]+)%.md$") or path
  return name == "README" and "introduction" or name
end

local function join(base, rel) -- rel from directory base, normalised
  local parts = {}
  for p in (base == "" and rel or base .. "/" .. rel):gmatch("[^/]+") do
    if p == ".." then table.remove(parts) elseif p ~= "." then table.insert(parts, p) end
  end
  return table.concat(parts, "/")
end

local function Meta(meta)
  page = pandoc.utils.stringify(meta.page)
  dir = page:match("^(.*)/[^/]*$") or ""
  stem = stem_of(page)
end

local function prefixed(id)
  return id ~= "" and stem .. "--" .. id or id
end

local function retarget(el)
  if el.identifier then el.identifier = prefixed(el.identifier) end
  return el
end

local function Image(el)
  if not el.src:match("^%a[%w+.-]*:") then el.src = join(dir, el.src) end
  return el
end

local function Link(el)
  local t = el.target
  if t:match("^%a[%w+.-]*:") then return el end
  if t:sub(1, 1) == "#" then el.target = "#" .. prefixed(t:sub(2)); return el end
  local path, frag = t:match("^([^#]*)#?(.*)$")
  local full = join(dir, path)
  if full:match("%.md$") then
    local s = stem_of(full)
    el.target = "#" .. s .. (frag ~= "" and "--" .. frag or "")
    if full:match("^lessons/") then -- a lesson's own README: not in the book
      return el.content
    end
    return el
  end
  return el.content -- a file of the tree: its text stays
end

-- The page's title, its first heading, is named after the page itself.
local function Pandoc(doc)
  for _, b in ipairs(doc.blocks) do
    if b.t == "Header" then
      b.identifier = stem
      break
    end
  end
  return doc
end

-- The page's name first (Meta), then its elements, then its title.
return {
  {Meta = Meta},
  {Header = retarget, Div = retarget, Span = retarget, CodeBlock = retarget, Table = retarget,
   Image = Image, Link = Link},
  {Pandoc = Pandoc},
}
