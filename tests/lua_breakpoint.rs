//! The debugger from Lua takes the shell's wording (docs/il.md "Debugging"):
//! `plc:breakpoint("network 2")` is `sim break network 2`.

mod common;
use common::*;

#[test]
fn a_lua_breakpoint_by_network_halts_there() {
    let dir = std::env::temp_dir().join(format!("plcsh-lua-break-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let il = dir.join("n.il");
    std::fs::write(&il, "(* Network 1 *)\nLD %SM0.0\nINC %VW0\n(* Network 2 *)\nLD %SM0.0\nINC %VW2\n").unwrap();
    let lua = dir.join("b.lua");
    std::fs::write(
        &lua,
        format!(
            "local plc = plcsh.connect(\"sim:K205-16DT\", \"plc\")\n\
             plc:program_load({:?})\n\
             local r = plc:breakpoint(\"network 2\")\n\
             plcsh.assert_eq(r.breakpoints[1], 5, \"network 2 starts on line 5\")\n\
             plcsh.sleep(10)\n\
             plcsh.assert_eq(plc:program().mode, \"DEBUG\", \"halted\")\n\
             local s = plc:step_instruction(1)\n\
             print(\"ok\")\n",
            il.display().to_string()
        ),
    )
    .unwrap();
    let o = run(&["--time", "stepped", "run", lua.to_str().unwrap()], "");
    assert!(o.status.success() && stdout(&o).contains("ok"), "{}", both(&o));
    let _ = std::fs::remove_dir_all(&dir);
}
