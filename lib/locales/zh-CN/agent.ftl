# plcsh messages (zh-CN): agent — PLC 端辅助程序及其检查. Same ids and arguments in en, ru and zh-CN
# (tests/messages.rs).

## PLS refused on a value kept from an earlier PLS (update bit clear; K2 §3.4.2.2): the same
## words in process and through the helper (k2::sim::pto::explain).
agent-pls-kept-cycle = 沿用的周期时间无效：更新位 SM{ $control }.0 为 0，PLS 使用的是上一次 PLS 装载的值（上电后为 0），而不是 SMW{ $cycle }（周期时间和脉冲数都必须大于 1，§3.4.2.2；频率不得超过该输出的上限，§3.4）
agent-pls-kept-cycle-hint = 设置 SMW{ $cycle } 及其更新位 SM{ $control }.0，然后再执行 PLS
agent-pls-kept-count = 沿用的脉冲数无效：更新位 SM{ $control }.2 为 0，PLS 使用的是上一次 PLS 装载的值（上电后为 0），而不是 SMD{ $count }（周期时间和脉冲数都必须大于 1，§3.4.2.2）
agent-pls-kept-count-hint = 设置 SMD{ $count } 及其更新位 SM{ $control }.2，然后再执行 PLS
agent-pls-kept-both = 沿用的周期时间或脉冲数无效：更新位 SM{ $control }.0 和 SM{ $control }.2 均为 0，PLS 使用的是上一次 PLS 装载的值（上电后为 0），而不是 SMW{ $cycle } 和 SMD{ $count }（周期时间和脉冲数都必须大于 1，§3.4.2.2）
agent-pls-kept-both-hint = 设置 SMW{ $cycle }、SMD{ $count } 及其更新位 SM{ $control }.0 和 SM{ $control }.2（例如 SMB{ $control }=16#85），然后再执行 PLS

# An instruction the helper ran whose status register reports something the PLC does not
# refuse for (HSC's multi-PV table fault, §3.3.2): what ran, then the note.
agent-done-with-note = { $what }：已由辅助程序执行；{ $note }

# The mailbox base (`agent install base=`, `sm … base=`): below the E2PROM area (§2.2.8).
agent-base-not-vb = `{ $text }` 不是 V 字节地址（例如 VB{ $base }）
agent-base-range = 辅助程序的邮箱需要一个偶数地址，并在备份区 (E2PROM) VB{ $eeprom } 之下留出 { $total } 个空闲字节（给定的是 VB{ $n }）

# The helper's result codes, as a refusal reads them.
agent-result-done = 已完成
agent-result-unknown-command = 辅助程序不认识此命令（请更新 lib/k2_agent.il）
agent-result-bad-range = SM 范围超出手册列出的寄存器，或长于 64 字节
agent-result-read-only = 这些 SM 字节只读
agent-result-bad-channel = 此 PLC 没有该通道
agent-result-bad-mode = 该计数器没有此模式
agent-result-instruction-failed = PLC 指令报告了错误（其 ENO）
agent-result-bad-clock = 日期或时间无效
agent-result-status-bit = 指令的状态位报告了拒绝
agent-result-other = 未知的结果代码 { $code }

# The helper's causes of a status-bit refusal (§3.4.2.2, §3.4.3.1, §3.3.2).
agent-pls-invalid = PLS { $n } 之后 PLC 置位了状态位 SM{ $status }.4：周期时间或脉冲数无效（周期时间和脉冲数都必须大于 1，§3.4.2.2）；未发出脉冲
agent-pls-invalid-hint = 装载 SMW{ $cycle } 并置位 SM{ $control }.0，装载 SMD{ $count } 并置位 SM{ $control }.2（例如 SMB{ $control }=16#85），然后再执行 PLS
agent-pstop-not-latched = PSTOP { $n } 之后紧急停止位 SM{ $control }.7 没有锁存（手册 §3.4.3.1：PSTOP 会将其置位）
agent-pstop-not-latched-hint = 请检查 PLC 运行的是当前的辅助程序，并且其上有该定位通道
agent-hsc-pv-table = HSC { $n } 之后 PLC 置位了状态位 SM{ $status }.3：多 PV 表出错（手册 §3.3.2）
agent-hsc-pv-table-hint = 请检查 SMW{ $table } 处的 PV 表（V 地址为奇数、数量为 1..32、相邻 PV 之差大于 1；§3.3.3）

# `plcsh agent check` (docs/agent.md, "agent check"): what each step proves, what it saw and
# what to do when it failed; then the verdict.
agent-check-proves-signature = 辅助程序在此地址使用其邮箱运行（plcsh 在那里读到自己的签名）
agent-check-proves-protocol = 辅助程序使用的邮箱协议与此 plcsh 相同
agent-check-proves-heartbeat = 每个扫描周期都调用辅助程序，因此命令在一两个扫描周期内被接收；由速率可得扫描时间
agent-check-proves-system-bits = 辅助程序的 SM 复制能到达系统状态位：命令送入，应答返回，且这些字节就是 PLC 自己的
agent-check-proves-clock = READ_RTC 可通过辅助程序执行，且 PLC 的实时时钟在走
agent-check-proves-refusal = PLC 拒绝的指令被报告为拒绝（状态位 4），而不是已完成，且拒绝不会使任何东西移动
agent-check-not-run = 未执行：前面的步骤失败
agent-check-not-run-todo = 先修复第一个失败的步骤，然后再次运行 plcsh agent check
agent-check-install = 将辅助程序装入 PLC（plcsh agent il --base VB{ $base } 会输出它；docs/reference/first-connection.md），或给出生成它时所用的地址（agent=VB…）
agent-check-link-probe = 请检查连接（plcsh probe URL 会显示 PLC 的应答）
agent-check-signature-seen = VW{ $base } = 16#{ $got }（辅助程序写入的是 16#{ $want }）
agent-check-version-seen = 版本 { $got }（此 plcsh 使用 { $want }）
agent-check-version-todo = 下载当前的辅助程序：plcsh agent il（然后再次运行 plcsh agent check）
agent-check-link = 请检查连接
agent-check-heartbeat-stopped = 心跳计数在 { $ms } ms 内一直停在 { $hb }
agent-check-heartbeat-todo = 将 PLC 置于 RUN，并检查主程序在每个扫描周期都调用辅助程序（LD %SM0.0 / CAL PLCSH_AGENT）
agent-check-heartbeat-seen = { $ms } ms 内 { $scans } 个扫描周期：每秒 { $rate } 个，扫描时间约 { $scan } ms
agent-check-sm00-todo = SM0.0 读为 0，但在运行中的 PLC 里它总是 1（手册 SM 表）：辅助程序的 SM 复制读的是别的存储区；请检查辅助程序是否为此型号生成（plcsh agent il），提问时请附上 plcsh agent check --json 的输出
agent-check-sm01-todo = 首次扫描早已结束，SM0.1（首次扫描）仍读为 1：辅助程序的 SM 复制没有跟随 PLC 的 SM 字节；请装入当前的辅助程序（plcsh agent il）
agent-check-reply-length = 应答包含 { $n } 个字节，而不是 1 个
agent-check-load-current-il = 请装入当前的辅助程序（plcsh agent il）
agent-check-mailbox-todo = 请检查没有其他客户端使用该邮箱，然后再次运行检查
agent-check-rtc-short = 辅助程序对 READ_RTC 的应答短于 8 字节
agent-check-rtc-invalid = PLC 时钟读数为 { $reading }
agent-check-rtc-invalid-hint = 请设置时钟：plcsh -d URL -c 'rtc set YYYY-MM-DDTHH:MM:SS'（时钟电池可能已耗尽）
agent-check-clock-seen = { $first }，{ $dt } s 后为 { $second }（PLC 时钟走了 { $moved } s）
agent-check-clock-todo = PLC 的时钟不走：请检查时钟电池并设置时钟（rtc set …）
agent-check-relay-model = { $model } 为继电器输出，没有脉冲通道（手册 §2.2.6）：无可测试
agent-check-again = 请再次运行检查
agent-check-all-enabled = 每个脉冲通道的使能位都已置位（{ $bytes }）：程序正在使用它们
agent-check-all-enabled-todo = 检查只在程序未使能的通道上尝试 PLS；请在程序不使用脉冲通道时运行（测试程序，或断开机器的输出）
agent-check-restore-failed = { $name }：无法写回这些字节：{ $error }
agent-check-restore-todo = 请手动写回：SMB{ $control } = 16#{ $value }，SMD{ $count } = { $pulses }
agent-check-wrong-length = 应答长度不对
agent-check-load-current = 请装入当前的辅助程序
agent-check-reported-done = 辅助程序报告已完成
agent-check-reported = 辅助程序报告：{ $message }
agent-check-refusal-seen = { $name }：状态 SMB{ $status } 16#{ $before } → 16#{ $after }（位 4 { $bit4 ->
        [set] 已置位
       *[clear] 未置位
    }），位置 SMD{ $cv } { $moved ->
        [changed] 已改变
       *[unchanged] 未改变
    }；{ $helper }；已写回 { $written }
agent-check-no-bit4-todo = PLC 没有在状态字节中标出无效的脉冲数（手册 §3.4.2.2，位 4）：辅助程序可能访问了此 PLC 上错误的 SM 字节；提问时请附上 plcsh agent check --json 的输出
agent-check-cr-todo = 辅助程序把 PLS 之后的 CR 当作成功，而 K2 不会改变它（§3.4.2，IL）：被拒绝的 PLS 会显示为已完成；请装入当前的辅助程序（plcsh agent il）
agent-check-moved-todo = 通道发生了移动：请停止机器，并在使用脉冲输出前检查通道 { $channel }
agent-check-title = { $model } 上位于 { $base } 的辅助程序
agent-check-proves = 证明：{ $text }
agent-check-todo = 怎么办：{ $text }
agent-check-passed = 所有步骤均通过
agent-check-failed = 检查未通过

# The client of the helper's mailbox (docs/agent.md): what a request did, whether the helper
# is there and current, and why a request did not run.
agent-what-sm-write = 写入 SMB{ $start }…SMB{ $end }
agent-what-sm-read = 读取 SMB{ $start }…SMB{ $end }
agent-no-helper = VB{ $base }…VB{ $last } 中没有 plcsh 辅助程序应答（签名 16#{ $got }，应为 16#{ $want }）
agent-no-helper-hint = SM 寄存器和指令需要 PLC 中的辅助程序：`plcsh agent il --base VB{ $base }` 会输出它（另见 lib/k2_agent.il）；安装方法见 docs/agent.md；或检查 agent=VB… 是否与程序一致
agent-helper-v2 = PLC 中的辅助程序是版本 2，它会把被拒绝的 PLS 报告为已完成（它读取的是 CR，而 PLS 不改变 CR，手册 §3.4.2）
agent-helper-v1 = PLC 中的辅助程序是版本 1，它对同一通道重复的 PLS 或 PSTOP 只执行第一次
agent-helper-old-hint = 请将当前的辅助程序（版本 { $version }）下载到 PLC：`plcsh agent il --model MODEL` 会输出它（lib/k2_agent.il）
agent-helper-version = PLC 中的辅助程序使用邮箱协议版本 { $got }；此 plcsh 使用 { $want }
agent-helper-version-hint = 请下载当前的辅助程序：`plcsh agent il`（lib/k2_agent.il）
agent-mailbox-busy = 邮箱忙：无法发送“{ $what }”
agent-mailbox-busy-hint = 另一个客户端的请求（序号 { $pending }）已等待辅助程序 { $ms } ms；PLC 是否处于 RUN？请重试
agent-reply-short = 辅助程序对“{ $what }”的应答短于所请求的长度
agent-refused = 辅助程序拒绝了“{ $what }”：{ $why }（结果 { $result }，原因 { $cause }）
agent-no-ack = 辅助程序在 { $ms } ms 内没有确认“{ $what }”
agent-no-ack-stopped = 辅助程序的心跳停止了：PLC 可能处于 STOP，或辅助程序不再在每个扫描周期被调用
agent-no-ack-busy = 辅助程序在运行，但没有接收该请求；可能有另一个客户端在使用邮箱
agent-mailbox-races = 邮箱忙：“{ $what }”有 { $races } 次被其他客户端抢先
agent-mailbox-races-hint = 另一个 plcsh（或程序）正同时向此 PLC 发送辅助程序命令；请重试
agent-heartbeat-stopped = plcsh 辅助程序已安装，但其心跳在 { $ms } ms 内没有变化
agent-heartbeat-stopped-hint = PLC 可能处于 STOP，或 PLCSH_AGENT 没有在每个扫描周期被调用（LD %SM0.0 / CAL PLCSH_AGENT）

# The probe's Markdown report (`plcsh probe … --report FILE`): its title, lines and headings.
agent-probe-report-title = plcsh probe 报告
agent-probe-report-device = 设备：`{ $url }`
agent-probe-report-requests = 已发送请求：{ $requests } 个（只读：FC 01、02、03、04）
agent-probe-report-areas = Modbus 区域
agent-probe-report-models = 符合的目录型号
agent-probe-report-no-models = 无
agent-probe-report-timing = 响应时间
agent-probe-report-timed = 读取 { $what } { $reads } 次：{ $failed } 次失败；p50 { $p50 }，p99 { $p99 }，max { $max }
agent-probe-report-verdicts = 结论

# The helper's checks (k2::agent::protocol::checks): the reason of each row, in the helper
# program's comments and docs/agent.md (English) and in a refusal a person reads.
agent-row-commands = 辅助程序认识命令 1..9
agent-row-smb0 = SMB0 保存系统状态位，只读
agent-row-length = 一次 1..{ $max } 字节
agent-row-start = 起始字节为 SMB0..SMB{ $last }，即手册列出的寄存器
agent-row-end = 最后一个字节最多为 SMB{ $last }（SMD{ $dword } 是手册列出的最高寄存器）
agent-row-block = SMB{ $first }..SMB{ $last } 是一个块：请在此处拆分
agent-row-gap = { $bytes }：手册中没有 { $model } 的此寄存器
agent-row-pos-cv = SMD{ $at } 只读（§3.4.3.1）
agent-row-no-pto = { $model } 没有脉冲输出
agent-row-no-hsc = { $model } 没有高速计数器
agent-row-pto = { $model } 的脉冲输出为 0..{ $last }
agent-row-hsc = { $model } 的高速计数器为 0..{ $last }
agent-result-because = { $result }：{ $why }
