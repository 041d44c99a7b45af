# plcsh messages (zh-CN): engine — IL 扫描引擎及其编译器. Same ids and arguments in en, ru and zh-CN
# (tests/messages.rs).

## 加载 IL：读取与编译 (docs/il.md)

engine-comment-unclosed = 注释 `(*` 没有用 `*)` 结束
engine-line-too-long = 行长度超过 { $max } 个字符
engine-empty-operand = `{ $text }` 中有空操作数
engine-no-program = 文件中没有 PROGRAM：主程序每个扫描周期都执行
engine-no-program-hint = 用 `PROGRAM MAIN` 开始主程序（或把它放在第一个 SUBROUTINE 之前）
engine-pou-twice = { $name } 被定义了两次
engine-label-twice = 标号 { $name } 在 { $pou } 中被定义了两次
engine-for-too-deep = FOR 循环嵌套超过 { $max } 层
engine-next-without-for = NEXT 没有对应的 FOR
engine-next-without-for-hint = 循环写作 FOR INDX, INIT, FINAL … NEXT，且在同一个 POU 中
engine-for-without-next = { $pou } 中的 FOR 没有对应的 NEXT
engine-no-label = { $pou } 中没有标号 { $name }
engine-did-you-mean = 是否想用 { $name }？
engine-no-routine = { $file } 中没有子程序或中断服务子程序 { $name }
engine-no-routine-hint = 用 `SUBROUTINE NAME`（或 `INTERRUPT NAME`）… `END_SUBROUTINE` 定义它
engine-needs-constant = { $mnemonic }：{ $operand } 必须是常数
engine-unknown-instruction = 未知指令 { $mnemonic }
engine-unknown-instruction-near = 是否想用 { $name }？（docs/il.md 列出了所有指令）
engine-unknown-instruction-hint = docs/il.md 列出了本仿真器执行的指令
engine-pointer-not-dword = { $operand }：指针是双字，{ $target } 不是
engine-pointer-not-dword-hint = 把指针放在双字中，例如 *%VD{ $index }
engine-not-pointable = { $operand }：不能指向 { $target }
engine-not-pointable-hint = 可以指向 V、M、I、Q 或 SM 字节
engine-operand-type = { $name } 是 { $have }，但此运算使用 { $want }
engine-pointer-needs-dword = { $operand }：指针需要双字
engine-output-not-location = 不能写入 { $operand }：输出必须是存储区地址
engine-not-a-bit = { $name } 是 { $have }，不是位
engine-not-a-bit-hint = 位操作数形如 %M0.0、%I0.1、%SM0.0（或定时器、计数器的位 T5/C5）
engine-bit-needed = { $operand }：此处需要位地址
engine-count-range = { $operand }：数量应为 1…255
engine-convert-first = 先转换：{ $how }
engine-same-size = 使用相同大小的操作数（B、W、D）
engine-numbers-not-bits = { $mnemonic } 作用于数值，不作用于位
engine-int-dint-real = { $mnemonic } 作用于 INT、DINT 或 REAL 值
engine-no-event = ATCH：没有中断事件 { $event }（事件号：{ $events }）
engine-block-n = { $mnemonic }：N 必须为 1…255，实际为 { $n }
engine-timer-preset-range = { $time } 是此 { $base } ms 定时器的 { $units } 个单位；设定值必须为 0…32767（最多 { $longest } s）
engine-timer-rounded = { $time } 不是此定时器 { $base } ms 单位的整数倍：向上取整为 { $got } ms（{ $units } 个单位），不会比设定的短

## 运行：故障（K2 §2.2.1 严重错误与一般错误）

engine-fault = 故障 { $code }（{ $name }）：{ $message }
engine-fault-at = 故障 { $code }（{ $name }）：{ $message }，位于第 { $line } 行 `{ $instruction }`
engine-fault-watchdog = 看门狗
engine-fault-bad-address = 间接地址无效
engine-fault-call-depth = 调用深度
engine-fault-instruction = 指令
engine-fault-div-zero = 除以零
engine-ran-off = 执行超出了程序末尾
engine-parens-too-deep = 括号嵌套超过 { $max } 层
engine-division-by-zero = 除以零
engine-calls-too-deep = 子程序嵌套超过 { $max } 层
engine-watchdog = 扫描时间超过看门狗限制 { $ms } ms（死循环？）
engine-block-length = 块长度 { $n } 不在 1…255 范围内
engine-no-destination = 没有目标地址
engine-bad-address = 间接地址无效
engine-bad-address-at = 间接地址无效 { $pointer }

## 各系列自有指令（docs/il.md 的表：K2 手册 §3.3、§3.4；FX PM；UMPK §3.5）

engine-doc-k2-pls = PLS q：装载该通道的 SM 设置并启动 PTO/PWM（在 EN 上升沿）；CR 保持不变——被拒绝时只置位状态位 SM66.4 …
engine-doc-k2-hdef = HDEF hsc, mode：指定计数模式
engine-doc-k2-hsc = HSC n：应用控制字节并启动或停止计数器
engine-doc-k2-pstop = PSTOP AXIS[, EXEC, DONE, ERRID]：在 EXEC 上升沿（无 EXEC 时为 EN 上升沿）急停；锁存 SM201.7
engine-doc-k2-prel = PREL AXIS, EXEC, MINF, MAXF, TIME, DIST, DONE, ERR, ERRID：相对运动，在 TIME ms 内从 MINF 加速到 MAXF，于 EXEC 上升沿启动
engine-doc-k2-pabs = PABS AXIS, EXEC, MINF, MAXF, TIME, POS, DONE, ERR, ERRID：绝对运动到 POS（SMD212 …）
engine-doc-k2-phome = PHOME AXIS, EXEC, HOME, NHOME, MODE, DIRC, MINF, MAXF, TIME, DONE, ERR, ERRID：沿 DIRC 方向运行直到 HOME（MODE 0：NHOME 之后以 MINF 爬行）
engine-doc-k2-pjog = PJOG AXIS, EXEC, MAXF, DIRC, DONE, ERR, ERRID：EXEC 接通期间以 MAXF 运行（每个扫描周期重新读取）
engine-doc-k2-pflo-f = PFLO_F AXIS, EXEC, F, NUM, DENOM, COUNT, DONE, ERR, ERRID：以 F × NUM / DENOM Hz 跟随输出 COUNT 个脉冲（≥ 30 Hz）
engine-doc-k2-read-rtc = READ_RTC buf：8 个 BCD 字节：年 月 日 时 分 秒 00 星期
engine-doc-k2-set-rtc = SET_RTC buf：用 8 个 BCD 字节设置时钟（数据无效：ENO = 0）
engine-doc-k2-stop = 若 CR 为真：CPU 在本扫描周期结束时进入 STOP（输出变为其 STOP 值；`sim cpu run` 重新运行）
engine-doc-fx-fxtim = OUT Tn K|D：FX 计时器线圈（输入 = CR，CR 不变）
engine-doc-fx-fxcnt = OUT Cn K|D：FX 16 位计数器线圈
engine-doc-fx-fxcnt32 = OUT Cn K|D：FX 32 位增/减计数器线圈
engine-doc-fx-fxrst = RST D/T/C：复位寄存器、计时器或计数器
engine-doc-umpk-timer = TIMER Tn, GROUP, STEPS：接通延时定时器，输入 = CR，延时 STEPS（1–255）× GROUP（0：10 ms，1：0.1 s，2：1 s）；CR := Tn
engine-doc-umpk-divide = DIVIDE Cn, RATIO[, RESET]：对 CR 脉冲进行 N 分频的计数器（RATIO 1–255）；输出脉冲与输入脉冲等长；RESET 接通时清零；CR := Cn
engine-doc-umpk-error = ERROR CODE：在 CR 上升沿把用户错误代码 CODE（1–127）写入错误历史（?07F9）；程序继续运行

## 退出状态（docs/reference/exit-status.md 由此生成，使用英文）

exit-ok-name = ok
exit-ok-when = 所有命令成功；脚本执行完毕；设备组中每台设备都有应答；`sim serve` 被 SIGTERM、SIGHUP 或 Ctrl-C 停止；`publish` 在所有读数送达后被 Ctrl-C、SIGTERM 或 SIGHUP 停止
exit-failed-name = 失败
exit-failed-when = 某条命令、脚本或检查失败（`error[KIND]` 消息说明是哪一个）；设备组中有一台设备失败；实验判据未满足；损坏的记录只显示了一部分
exit-usage-name = 用法错误
exit-usage-when = 命令行有误：未知的选项或子命令，缺少值或值无效，--config 指定的文件不存在，记录无法读取
exit-broker-refused-name = 代理拒绝
exit-broker-refused-when = `publish`：MQTT 代理拒绝了凭据（用户名、密码或其 ACL）
exit-broker-unreachable-name = 代理不可达
exit-broker-unreachable-when = `publish`：代理的 TLS 证书未通过验证，或启动后 10 s 内没有代理应答
exit-hangup-name = SIGHUP
exit-hangup-when = 终端断开（SSH 会话中断；Windows：控制台窗口被关闭）；正在执行的命令已停止，中止处理程序已执行
exit-interrupted-name = Ctrl-C
exit-interrupted-when = Ctrl-C 停止了单次命令、脚本或设备组运行；中止处理程序已执行（在交互式 shell 中 Ctrl-C 则返回提示符）
exit-terminated-name = SIGTERM
exit-terminated-when = SIGTERM（`timeout`、`systemctl stop`、CI；Windows：Ctrl-Break）停止了工作；中止处理程序已执行
