-- Test driver: type "SPEED." on a new last line, ask for completion after the dot, write the labels and the
-- server's trigger characters as JSON to $MINT_PROBE_OUT, quit.
local bufnr = vim.api.nvim_get_current_buf()
local client
vim.wait(20000, function()
  client = vim.lsp.get_active_clients()[1]
  return client ~= nil and client.initialized
end, 50)
local last = vim.api.nvim_buf_line_count(bufnr)
vim.api.nvim_buf_set_lines(bufnr, last, last, false, { "SPEED." })
local params = {
  textDocument = vim.lsp.util.make_text_document_params(bufnr),
  position = { line = last, character = 6 },
  context = { triggerKind = 2, triggerCharacter = "." },
}
local labels = {}
for _, response in pairs(vim.lsp.buf_request_sync(bufnr, "textDocument/completion", params, 10000) or {}) do
  local result = response.result or {}
  for _, item in ipairs(result.items or result) do
    table.insert(labels, item.label)
  end
end
local provider = client.server_capabilities.completionProvider or {}
local file = io.open(os.getenv("MINT_PROBE_OUT"), "w")
file:write(vim.fn.json_encode({ labels = labels, triggers = provider.triggerCharacters or {} }))
file:close()
vim.cmd("qa!")
