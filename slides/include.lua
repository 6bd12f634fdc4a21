-- pandoc Lua filter for the slides: a fenced code block of class "include" is replaced by the Markdown file
-- it names, looked up along pandoc's resource path (the slides folder, then the build tree's slides folder,
-- where scripts/build-slides.sh writes the sweeps' tables). In a repository browser the block shows the path.
-- A file that is not there stops the build with its name, rather than leaving a hole in a deck.
--
-- With columns="a,b,c" a pipe table in the file keeps only the columns of those names, in that order, so that a
-- sweep with twenty measures shows the three a slide is about; a name the table lacks stops the build too.
-- With rows="column=value" it keeps only the rows that have that value in that column (one node set of two), and
-- with caption="off" it drops the table's caption (a second table from the same kind of sweep on one slide).
-- A caption's clause about a column left out ("; ceiling: ...") is left out with it.

local function split_row(line)
  local cells = {}
  for cell in line:gmatch('|([^|]*)') do cells[#cells + 1] = cell:gsub('^%s+', ''):gsub('%s+$', '') end
  if line:match('|%s*$') then cells[#cells] = nil end  -- the text after the closing bar
  return cells
end

local function keep_rows(text, column, value, name)
  local out, index, seen = {}, nil, 0
  for line in (text .. '\n'):gmatch('(.-)\n') do
    if line:match('^|') then
      local cells = split_row(line)
      if not index then
        for i, cell in ipairs(cells) do if cell == column then index = i end end
        if not index then error('include: ' .. name .. ' has no column "' .. column .. '" to pick rows by') end
        out[#out + 1] = line
      elseif line:match('^|%s*:?%-') or cells[index] == value then
        out[#out + 1] = line
        if not line:match('^|%s*:?%-') then seen = seen + 1 end
      end
    else
      out[#out + 1] = line
    end
  end
  if seen == 0 then error('include: ' .. name .. ' has no row with ' .. column .. '=' .. value) end
  return table.concat(out, '\n')
end

local function drop_caption(text)
  local out = {}
  for line in (text .. '\n'):gmatch('(.-)\n') do
    if not line:match('^: ') then out[#out + 1] = line end
  end
  return table.concat(out, '\n')
end

-- A caption explains some columns in clauses "; column: what it is": a clause about a column the slide leaves out
-- goes with it, so that the caption does not describe what is not shown (nor take a line the slide lacks).
local function caption_without(line, dropped)
  local clauses = {}
  for clause in (line:sub(3) .. '; '):gmatch('(.-); ') do clauses[#clauses + 1] = clause end
  local kept = {}
  for _, clause in ipairs(clauses) do
    local column = clause:match('^([%w_]+):')
    if not (column and dropped[column]) then kept[#kept + 1] = clause end
  end
  local caption = table.concat(kept, '; ')
  if not caption:match('%.$') then caption = caption .. '.' end
  return ': ' .. caption
end

local function keep_columns(text, wanted, name)
  local out, picks, dropped = {}, nil, {}
  for line in (text .. '\n'):gmatch('(.-)\n') do
    if line:match('^: ') then
      out[#out + 1] = caption_without(line, dropped)
    elseif line:match('^|') then
      local cells = split_row(line)
      if not picks then
        picks = {}
        for _, cell in ipairs(cells) do dropped[cell] = true end
        for _, want in ipairs(wanted) do dropped[want] = nil end
        for _, want in ipairs(wanted) do
          local found = nil
          for i, cell in ipairs(cells) do if cell == want then found = i end end
          if not found then
            error('include: ' .. name .. ' has no column "' .. want .. '" (it has: ' .. table.concat(cells, ', ') .. ')')
          end
          picks[#picks + 1] = found
        end
      end
      local kept = {}
      for _, i in ipairs(picks) do kept[#kept + 1] = cells[i] or '' end
      out[#out + 1] = '| ' .. table.concat(kept, ' | ') .. ' |'
    else
      out[#out + 1] = line
    end
  end
  return table.concat(out, '\n')
end

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
      local rows = block.attributes['rows']
      if rows then
        local column, value = rows:match('^([^=]+)=(.+)$')
        if not column then error('include: rows="' .. rows .. '" needs column=value') end
        text = keep_rows(text, column, value, name)
      end
      if block.attributes['caption'] == 'off' then text = drop_caption(text) end
      local columns = block.attributes['columns']
      if columns then
        local wanted = {}
        for column in columns:gmatch('[^,]+') do wanted[#wanted + 1] = column:gsub('^%s+', ''):gsub('%s+$', '') end
        text = keep_columns(text, wanted, name)
      end
      -- In a div of class "sweep", which the deck style keeps from wrapping numbers like 4.6e-07.
      return pandoc.Div(pandoc.read(text, 'markdown').blocks, pandoc.Attr('', {'sweep'}))
    end
  end
  error('include: cannot find ' .. name .. ' (looked in ' .. table.concat(PANDOC_STATE.resource_path, ', ') .. ')')
end
