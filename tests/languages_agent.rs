//! The PLC-side helper in Russian and Simplified Chinese: the verdict of `plcsh agent check`
//! on a PLC without the helper (docs/agent.md, "agent check") and a read the helper refuses
//! (its range check: SM bytes past the last register the manual names, §2.2.7), each checked
//! word for word in the three languages, with the same JSON `code` in every language. The
//! words follow ../shared/spec/glossary.md (ПЛК, бит состояния, только для чтения; 状态位,
//! 只读); the helper is «программа-помощник» / «辅助程序».

mod common;
use common::*;

/// `plcsh --lang LANG ARGS…`: exit status, stdout and stderr.
fn run_in(lang: &str, args: &[&str]) -> (Option<i32>, String, String) {
    let o = plcsh().args(["--lang", lang]).args(args).output().unwrap();
    (o.status.code(), String::from_utf8_lossy(&o.stdout).into_owned(), String::from_utf8_lossy(&o.stderr).into_owned())
}

/// The verdict of `agent check` on a served K2 that runs no helper: the signature step fails
/// with what it saw and what to do, the steps after it are not run, and the check fails.
#[test]
fn the_check_verdict_reads_in_each_language() {
    let served = serve(&["--tcp", "0"]);
    let url = format!("tcp://{}?model=K205-16DT&agent=VB3400", served.ready["tcp"].as_str().unwrap());
    let want = [
        (
            "en",
            "helper at VB3400 on K205-16DT\n\
             1. FAIL signature: VW3400 = 16#0000 (the helper writes 16#4B41)\n\
             \x20  proves: the helper program runs with its mailbox at this base (plcsh reads its own signature there)\n\
             \x20  what to do: load the helper into the PLC (plcsh agent il --base VB3400 prints it; docs/reference/first-connection.md), or give the base it was made for (agent=VB…)\n\
             2. FAIL protocol: not run: an earlier step failed\n\
             the check FAILED\n",
        ),
        (
            "ru",
            "программа-помощник по адресу VB3400 в K205-16DT\n\
             1. FAIL signature: VW3400 = 16#0000 (программа-помощник пишет 16#4B41)\n\
             \x20  доказывает: программа-помощник работает с почтовым ящиком по этому адресу (plcsh читает там свою подпись)\n\
             \x20  что делать: загрузите программу-помощник в ПЛК (её выводит plcsh agent il --base VB3400; docs/reference/first-connection.md) или укажите адрес, для которого она сделана (agent=VB…)\n\
             2. FAIL protocol: не выполнен: предыдущий шаг не прошёл\n\
             проверка НЕ ПРОЙДЕНА\n",
        ),
        (
            "zh-CN",
            "K205-16DT 上位于 VB3400 的辅助程序\n\
             1. FAIL signature: VW3400 = 16#0000（辅助程序写入的是 16#4B41）\n\
             \x20  证明：辅助程序在此地址使用其邮箱运行（plcsh 在那里读到自己的签名）\n\
             \x20  怎么办：将辅助程序装入 PLC（plcsh agent il --base VB3400 会输出它；docs/reference/first-connection.md），或给出生成它时所用的地址（agent=VB…）\n\
             2. FAIL protocol: 未执行：前面的步骤失败\n\
             检查未通过\n",
        ),
    ];
    for (lang, want) in want {
        let (code, out, err) = run_in(lang, &["agent", "check", &url]);
        assert_eq!(code, Some(1), "{lang}: {err}");
        // The title, the first step whole, the first step not run, and the verdict.
        let lines: Vec<&str> = out.lines().collect();
        assert!(lines.len() > 6, "{lang}:\n{out}");
        let seen: String = lines[..5].iter().chain(lines.last()).map(|l| format!("{l}\n")).collect();
        assert_eq!(seen, want, "{lang}:\n{out}");
    }
}

/// A read the helper refuses: its result code and the row of its checks that refused, both
/// in the language, and the same JSON `code` in every language.
#[test]
fn a_helper_refusal_reads_in_each_language() {
    let served = serve(&["--tcp", "0", "--agent"]);
    let url = format!("tcp://{}?model=K205-16DT&agent=VB3400", served.ready["tcp"].as_str().unwrap());
    // SMB300 is past SMD262, the last register the manual names: the helper's range check
    // refuses it (docs/agent.md, the table of checks).
    let line = "get SMB300";
    let want = [
        (
            "en",
            "error[refused]: plc: the helper refused reading SMB300…SMB300: SM range outside the registers the manual names or longer than 64 bytes: the start is SMB0…SMB265, the registers the manual names (result 2, cause 4)\n",
        ),
        (
            "ru",
            "error[refused]: plc: программа-помощник отвергла чтение SMB300…SMB300: диапазон SM выходит за регистры, названные в руководстве, или длиннее 64 байт: начало — SMB0…SMB265, регистры, названные в руководстве (результат 2, причина 4)\n",
        ),
        (
            "zh-CN",
            "error[refused]: plc: 辅助程序拒绝了“读取 SMB300…SMB300”：SM 范围超出手册列出的寄存器，或长于 64 字节：起始字节为 SMB0…SMB265，即手册列出的寄存器（结果 2，原因 4）\n",
        ),
    ];
    for (lang, want) in want {
        let (_, _, err) = run_in(lang, &["--device", &url, "-c", line]);
        let errors: String = err
            .lines()
            .filter(|l| {
                l.starts_with("error[") || ["  hint: ", "  подсказка: ", "  提示："].iter().any(|h| l.starts_with(h))
            })
            .map(|l| format!("{l}\n"))
            .collect();
        assert_eq!(errors, want, "{lang}:\n{err}");
        let (_, out, _) = run_in(lang, &["--json", "--device", &url, "-c", line]);
        let last: serde_json::Value = out.lines().rev().find_map(|l| serde_json::from_str(l).ok()).unwrap_or_default();
        assert_eq!(last["error"]["code"], "agent-refused", "{lang}: {last}");
    }
}
