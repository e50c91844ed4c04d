-- mint-dap for nvim-dap (the README's snippet; mint-dap must be on PATH).
local dap = require("dap")
dap.adapters.mint = { type = "executable", command = "mint-dap" }
dap.configurations.mint = {
  { type = "mint", request = "launch", name = "Debug the program in the editor",
    program = "${file}", stopOnEntry = true },
}
