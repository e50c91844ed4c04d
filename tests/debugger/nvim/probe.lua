-- Test driver: nvim-dap ($NVIM_DAP) with dap.lua on the open .mnt file; stops at the entry, runs to a
-- breakpoint on line $MINT_BREAK_LINE, steps back once; writes each stop's line as JSON to $MINT_PROBE_OUT.
vim.opt.runtimepath:prepend(os.getenv("NVIM_DAP"))
vim.cmd("runtime plugin/dap.lua")
vim.cmd("setfiletype mint")
dofile(os.getenv("MINT_DAP_CONFIG"))
local dap = require("dap")
local lines = {}

local function stop_line(previous)
  vim.wait(20000, function()
    local session = dap.session()
    return session ~= nil and session.current_frame ~= nil and session.current_frame ~= previous
  end, 50)
  local frame = dap.session() and dap.session().current_frame
  table.insert(lines, frame and frame.line or vim.NIL)
  return frame
end

vim.api.nvim_win_set_cursor(0, { tonumber(os.getenv("MINT_BREAK_LINE")), 0 })
dap.toggle_breakpoint()
dap.continue()
local frame = stop_line(nil)
dap.continue()
frame = stop_line(frame)
dap.step_back()
stop_line(frame)
dap.terminate()
vim.wait(5000, function() return dap.session() == nil end, 50)
local file = io.open(os.getenv("MINT_PROBE_OUT"), "w")
file:write(vim.fn.json_encode({ lines = lines }))
file:close()
vim.cmd("qa!")
