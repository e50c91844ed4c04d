-- Test driver: a.mnt (open at start), a.cfg and b.mnt opened; b.cfg only on disk. Renames a variable of
-- a.cfg in a.mnt, changes b.cfg on disk, replaces b.mnt's v3 keywords; writes what it saw as JSON to
-- $MINT_PROBE_OUT, quits.
local out = {}
vim.o.hidden = true
local paths = { a = os.getenv("MINT_A"), a_cfg = os.getenv("MINT_A_CFG"), b = os.getenv("MINT_B") }
vim.cmd("edit " .. vim.fn.fnameescape(paths.a_cfg))
vim.cmd("edit " .. vim.fn.fnameescape(paths.b))
local bufs = {}
for name, path in pairs(paths) do
  bufs[name] = vim.fn.bufnr(path)
end

local versions = {} -- the version of each document's last diagnostics
local publish = vim.lsp.handlers["textDocument/publishDiagnostics"]
vim.lsp.handlers["textDocument/publishDiagnostics"] = function(err, result, ctx, config)
  versions[result.uri] = result.version
  return publish(err, result, ctx, config)
end

local function codes(buf)
  local found = {}
  for _, d in ipairs(vim.diagnostic.get(buf)) do
    table.insert(found, d.code or (d.user_data and d.user_data.lsp and d.user_data.lsp.code))
  end
  table.sort(found)
  return found
end

local function all_attached()
  for _, buf in pairs(bufs) do
    if next(vim.lsp.buf_get_clients(buf)) == nil then
      return false
    end
  end
  return true
end

local function up_to_date(buf)
  return versions[vim.uri_from_bufnr(buf)] == vim.lsp.util.buf_versions[buf]
end

local function probe()
  vim.wait(20000, function()
    return all_attached() and #codes(bufs.b) > 0
  end, 50)
  local clients = vim.lsp.get_active_clients()
  local client = clients[1]
  out.clients = #clients
  out.root = client.config.root_dir
  out.attached = {}
  for name, buf in pairs(bufs) do
    out.attached[name] = vim.tbl_keys(vim.lsp.buf_get_clients(buf))
  end
  out.before = { a = codes(bufs.a), b = codes(bufs.b) }

  -- Rename `stroke` (declared in a.cfg) where a.mnt uses it: both buffers change, neither is saved.
  local rename = {
    textDocument = { uri = vim.uri_from_bufnr(bufs.a) },
    position = { line = 1, character = 9 },
    newName = "maxStroke",
  }
  local renamed = client.request_sync("textDocument/rename", rename, 10000, bufs.a)
  assert(renamed and renamed.result, vim.inspect(renamed))
  vim.lsp.util.apply_workspace_edit(renamed.result, client.offset_encoding)
  vim.wait(10000, function()
    return up_to_date(bufs.a) and up_to_date(bufs.a_cfg)
  end, 50)
  out.renamed = {
    a = codes(bufs.a),
    a_cfg = codes(bufs.a_cfg),
    a_cfg_text = vim.api.nvim_buf_get_lines(bufs.a_cfg, 0, -1, false),
  }

  -- b.cfg, which no buffer holds, changes on disk (as another editor would save it).
  vim.wait(1500)
  vim.fn.writefile({ "DIM target = 3" }, os.getenv("MINT_B_CFG"))
  vim.wait(10000, function()
    return not vim.tbl_contains(codes(bufs.b), "E3001")
  end, 50)
  out.disk_changed = { b = codes(bufs.b) }

  -- The source actions of b.mnt, a v4 program whose only v3 word is HMSPEED.
  local start = { line = 0, character = 0 }
  local asked = {
    textDocument = { uri = vim.uri_from_bufnr(bufs.b) },
    range = { start = start, ["end"] = start },
    context = { diagnostics = {}, only = { "source" } },
  }
  out.actions = {}
  for _, action in ipairs(client.request_sync("textDocument/codeAction", asked, 10000, bufs.b).result or {}) do
    table.insert(out.actions, action.title)
    if action.title == "Replace v3 keywords" then
      local resolved = client.request_sync("codeAction/resolve", action, 10000, bufs.b).result
      vim.lsp.util.apply_workspace_edit(resolved.edit, client.offset_encoding)
    end
  end
  out.b_text = vim.api.nvim_buf_get_lines(bufs.b, 0, -1, false)
end

local ok, failure = pcall(probe) -- whatever happens, Neovim quits and says why
out.error = not ok and tostring(failure) or nil
local file = io.open(os.getenv("MINT_PROBE_OUT"), "w")
file:write(vim.fn.json_encode(out))
file:close()
vim.cmd("qa!")
