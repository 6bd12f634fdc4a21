-- pandoc Lua filter for the slides: a fenced code block of class "include" is replaced by the Markdown file
-- it names, looked up along pandoc's resource path (the slides folder, then the build tree's slides folder,
-- where scripts/build-slides.sh writes the sweeps' tables). In a repository browser the block shows the path.
-- A file that is not there stops the build with its name, rather than leaving a hole in a deck.
function CodeBlock(block)
  if not block.classes:includes('include') then
    return nil
  end
  local name = block.text:gsub('^%s+', ''):gsub('%s+$', '')
  for _, dir in ipairs(PANDOC_STATE.resource_path) do
    local file = io.open(dir .. '/' .. name, 'r')
    if file then
      local text = file:read('a')
      file:close()
      -- In a div of class "sweep", which the deck style keeps from wrapping numbers like 4.6e-07.
      return pandoc.Div(pandoc.read(text, 'markdown').blocks, pandoc.Attr('', {'sweep'}))
    end
  end
  error('include: cannot find ' .. name .. ' (looked in ' .. table.concat(PANDOC_STATE.resource_path, ', ') .. ')')
end
