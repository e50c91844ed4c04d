-- mint-lsp for Neovim 0.7 and later: put this in init.lua (mint-lsp must be on PATH).
vim.api.nvim_create_autocmd({ "BufRead", "BufNewFile" }, { pattern = "*.mnt", command = "setfiletype mint" })
vim.api.nvim_create_autocmd("FileType", {
  pattern = "mint",
  callback = function(args)
    local config = {
      name = "mint-lsp",
      cmd = { "mint-lsp" },
      root_dir = vim.fn.fnamemodify(vim.api.nvim_buf_get_name(args.buf), ":p:h"),
      init_options = { mint = { controller = "nextmove-pci", dialect = "v4" } },
    }
    if vim.lsp.start then -- Neovim 0.8+
      vim.lsp.start(config, { bufnr = args.buf })
    else -- Neovim 0.7
      vim.lsp.buf_attach_client(args.buf, vim.lsp.start_client(config))
    end
  end,
})
