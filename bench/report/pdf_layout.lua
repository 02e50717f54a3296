-- Pandoc Lua filter for bench/make_pdf.sh (issue 26): every level-2 section of REPORT.md starts a
-- new page, so each of the seed's five sections is measured against its one-page budget, and
-- every image is drawn at a fixed share of the text width (the stills are 640 px wide).
function Header(el)
  if el.level == 2 then
    return { pandoc.RawBlock("latex", "\\clearpage"), el }
  end
end

function Image(el)
  if el.attributes.width == nil then
    el.attributes.width = "52%"
  end
  return el
end
