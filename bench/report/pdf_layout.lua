-- Pandoc Lua filter for bench/make_pdf.sh (issues 26, 36): the seed's one page per section.
--  * Every level-2 section but the first starts a new page: the introduction and section 1 share
--    page 1, and each later section is measured against its own page.
--  * An image without a width is placed at 200 pixels per inch of its PNG, so a plot's size on
--    paper is the size bench/report/plots.gp gave it, and its 21 pt gnuplot font prints at 10 pt.
--    An image wider than the text runs off the margin, which check_report_pdf.sh catches.
--  * An image alone in its paragraph is centred; a paragraph that starts with "**Plot.**" (the
--    caption under a plot) is set a size smaller.

local PPI = 200
local seen_section = false

function Header(el)
  if el.level == 2 then
    if seen_section then
      return { pandoc.RawBlock("latex", "\\clearpage"), el }
    end
    seen_section = true
  end
end

-- The width of a PNG in pixels (its IHDR chunk), or nil.
local function png_width(path)
  local candidates = { path }
  for _, dir in ipairs(PANDOC_STATE.resource_path or {}) do
    table.insert(candidates, dir .. "/" .. path)
  end
  for _, candidate in ipairs(candidates) do
    local f = io.open(candidate, "rb")
    if f then
      local header = f:read(24)
      f:close()
      if header and #header == 24 and header:sub(2, 4) == "PNG" then
        local a, b, c, d = header:byte(17, 20)
        return ((a * 256 + b) * 256 + c) * 256 + d
      end
    end
  end
  return nil
end

function Image(el)
  if el.attributes.width == nil then
    local px = png_width(el.src)
    if px then
      el.attributes.width = string.format("%.3fin", px / PPI)
    else
      el.attributes.width = "52%"
    end
  end
  return el
end

function Para(el)
  if #el.content == 1 and el.content[1].t == "Image" then
    return { pandoc.RawBlock("latex", "{\\centering"), el, pandoc.RawBlock("latex", "\\par}") }
  end
  local first = el.content[1]
  if first and first.t == "Strong" and pandoc.utils.stringify(first) == "Plot." then
    return { pandoc.RawBlock("latex", "{\\small"), el, pandoc.RawBlock("latex", "\\par}") }
  end
end
