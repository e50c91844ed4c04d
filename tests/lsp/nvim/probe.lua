-- Test driver: wait for diagnostics, ask for a hover, write both as JSON to $MINT_PROBE_OUT, quit.
local bufnr = vim.api.nvim_get_current_buf()
vim.wait(20000, function()
  return #vim.diagnostic.get(bufnr) > 0
end, 50)
local diagnostics = {}
for _, d in ipairs(vim.diagnostic.get(bufnr)) do
  local code = d.code or (d.user_data and d.user_data.lsp and d.user_data.lsp.code)
  table.insert(diagnostics, { line = d.lnum, code = code, message = d.message })
end
local params = {
  textDocument = vim.lsp.util.make_text_document_params(bufnr),
  position = { line = tonumber(os.getenv("MINT_HOVER_LINE")), character = tonumber(os.getenv("MINT_HOVER_CHARACTER")) },
}
local hover = vim.NIL
for _, response in pairs(vim.lsp.buf_request_sync(bufnr, "textDocument/hover", params, 10000) or {}) do
  if response.result then
    hover = response.result.contents.value
  end
end
local file = io.open(os.getenv("MINT_PROBE_OUT"), "w")
file:write(vim.fn.json_encode({ diagnostics = diagnostics, hover = hover }))
file:close()
vim.cmd("qa!")
