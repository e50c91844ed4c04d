-- mint-lsp for Neovim 0.7 and later: put this in init.lua (mint-lsp must be on PATH).
-- One server per workspace (the nearest folder up with one of the markers), for programs and the
-- configuration files beside them (<name>.cfg with <name>.mnt).
local markers = { "pyproject.toml", "mint.toml", ".git" }

local function root_of(file)
  local folder = vim.fn.fnamemodify(file, ":p:h")
  local here = folder
  while true do
    for _, marker in ipairs(markers) do
      if vim.loop.fs_stat(here .. "/" .. marker) then
        return here
      end
    end
    local parent = vim.fn.fnamemodify(here, ":h")
    if parent == here then
      return folder -- no marker: the file's own folder
    end
    here = parent
  end
end

vim.api.nvim_create_autocmd({ "BufRead", "BufNewFile" }, { pattern = "*.mnt", command = "setfiletype mint" })
vim.api.nvim_create_autocmd({ "BufRead", "BufNewFile" }, {
  pattern = "*.cfg",
  callback = function(args) -- a .cfg is Mint only beside its program
    local stem = vim.fn.fnamemodify(args.file, ":p:r")
    if vim.fn.filereadable(stem .. ".mnt") == 1 or vim.fn.filereadable(stem .. ".MNT") == 1 then
      vim.bo[args.buf].filetype = "mint"
    end
  end,
})

local clients = {} -- Neovim 0.7: one client per workspace root, started once
vim.api.nvim_create_autocmd("FileType", {
  pattern = "mint",
  callback = function(args)
    local root = root_of(vim.api.nvim_buf_get_name(args.buf))
    local config = {
      name = "mint-lsp",
      cmd = { "mint-lsp" },
      root_dir = root,
      init_options = { mint = { controller = "nextmove-pci", dialect = "v4" } },
    }
    if vim.lsp.start then -- Neovim 0.8+: reuses the client with this name and root_dir
      vim.lsp.start(config, { bufnr = args.buf })
    else -- Neovim 0.7
      if not (clients[root] and vim.lsp.get_client_by_id(clients[root])) then -- none, or it stopped
        clients[root] = vim.lsp.start_client(config)
      end
      vim.lsp.buf_attach_client(args.buf, clients[root])
    end
  end,
})
