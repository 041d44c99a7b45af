# plcsh messages (zh-CN): devices — 伺服、UMPK 与 FX 的驱动和仿真器，以及链路. Same ids and arguments in en, ru and zh-CN
# (tests/messages.rs).

## UMPK terminal protocol (umpk::codec; UMPK manual §4.1, §4.2, Tables 6 and 8)

# The manual's names of the terminal commands (Table 6).
umpk-command-name = { $command ->
    [reset] 复位控制器
    [echo-on] 打开回显
    [echo-off] 关闭回显
    [info] 控制器信息
    [program-info] 程序信息
    [inputs] 输入状态
    [outputs] 输出状态
    [errors] 错误历史
    [clear-errors] 清除错误历史
    [programming] 进入编程模式
    [monitor-start] 启动实时监视
    [monitor-stop] 停止实时监视
   *[timing] 时间特性
    }
umpk-form-short-command = `{ $text }` 在 ? 之后有 { $count } 个字符，而 UMPK 要等满四个：终端命令是 ? 加四位十六进制数字，即命令码和使两者之和为 100 hex 的校验码
umpk-form-short-command-like = `{ $text }` 在 ? 之后有 { $count } 个字符，而 UMPK 要等满四个：终端命令是 ? 加四位十六进制数字，即命令码和使两者之和为 100 hex 的校验码；要执行“{ $command }”请发送 { $bytes }
umpk-form-no-reclen = `{ $text }` 不是以记录长度（: 之后的两位十六进制数字）开头：终端命令是 ? 加四位十六进制数字，即命令码和使两者之和为 100 hex 的校验码（例如 ?03FD，控制器信息）；HEX 记录是十六进制的 : RECLEN OFFSET TYPE DATA CHECKSUM（例如 :00000002FE，开始编程）
umpk-form-record-length = `{ $text }` 有 { $count } 个字符，而 RECLEN 为 { $reclen } 的 HEX 记录应有 { $want } 个：: RECLEN(2) OFFSET(4) TYPE(2) DATA({ $data }) CHECKSUM(2)，例如 :00000002FE（开始编程）
umpk-form-neither = `{ $text }` 既不是 UMPK 终端命令，也不是 HEX 记录：终端命令是 ? 加四位十六进制数字，即命令码和使两者之和为 100 hex 的校验码（例如 ?03FD，控制器信息）；HEX 记录是十六进制的 : RECLEN OFFSET TYPE DATA CHECKSUM（例如 :00000002FE，开始编程）
umpk-status-bits-not-six = `{ $text }` 不是 W,H,R,E,P,T 的六个位号 0–7（例如 5,4,3,2,1,0）
umpk-status-bits-count = `{ $text }` 必须给出六个位，对应 W,H,R,E,P,T（例如 5,4,3,2,1,0）
umpk-status-bits-twice = 位 { $bit } 在 `{ $text }` 中出现了两次
# The meaning of an error-history code (§4.1.8).
umpk-error-none = 无错误
umpk-error-user = 用户错误 { $code }（由程序设置）
umpk-error-output-overflow = 系统错误 255：输出缓冲区溢出 — 上一条回复尚未收完就发送了命令（§4.1）
umpk-error-cycle-overrun = 系统错误 254（plcsh 仿真器：程序超出 10 ms 周期，已停止；复位前处于待机模式）
umpk-error-program-fault = 系统错误 253（plcsh 仿真器：程序因故障停止；复位前处于待机模式）
umpk-error-system = 系统错误 { $code }
# What each reply letter means (§4.1, §4.2).
umpk-letter = { $letter ->
    [E] E：校验码错误 — 命令的校验码与其字节不符
    [U] U：未知命令
    [C] C：命令含有非法字符
    [L] L：记录的数据超过允许长度（每页 64 字节，程序信息 22 字节）
    [A] A：地址顺序错误或地址超出范围 — 各页必须在程序存储器内依次排列
    [W] W：闪存（IAP）写入失败
    [X] X：现在不允许编程（不在编程模式、尚无开始记录，或之前的记录失败）
   *[other] 未知的回复字母
    }
# What came instead of a reply (umpk::codec::parse_exchange).
umpk-bad-monitor-packet = 损坏的监视数据包：{ $bytes }
umpk-bad-r-cr = `R` CR 之后是 { $bytes }
umpk-bad-echo = 回显 { $echo } 与命令 { $sent } 不同
umpk-bad-length-field = 长度字段错误的数据包：{ $bytes }
umpk-bad-packet-length = 数据包有 { $got } 个字节，应为 { $want } 个
umpk-bad-packet-hex = 含非十六进制字符的数据包：{ $bytes }
umpk-bad-packet-checksum = 校验码错误的数据包：{ $bytes }（应为 { $expected }）
umpk-bad-reply = 意外的回复 { $bytes }
umpk-bad-crlf = 回复不是以 CR LF 结尾：{ $bytes }

## UMPK driver (umpk::driver)

umpk-no-complete-reply = { $timeout } 内未收到 { $link } 上的 UMPK 对 { $sent } 的完整回复
umpk-no-complete-reply-partial = { $timeout } 内未收到 { $link } 上的 UMPK 对 { $sent } 的完整回复；只收到 { $partial }
umpk-hint-silent = 请检查电源、RS-232 电缆（≤ 2 m）和 57600 8N1；控制器复位期间约 0.6 s 不回复
umpk-unexpected-reply = { $link } 上对 { $sent } 的意外回复：{ $what }
umpk-hint-garbled = 可能有其他程序占用该串口，或波特率不是 57600
umpk-refused-command = UMPK 拒绝了 ?{ $code }（{ $command }）：{ $letter }
umpk-hint-programming-mode = 在编程模式下 UMPK 只响应复位、打开/关闭回显和控制器信息（手册表 6）；`umpk reset` 退出编程模式
umpk-hint-corrupted = 线路损坏了字节：请检查电缆和 57600 8N1
umpk-answered-other = UMPK 对 ?{ $code }（{ $command }）回复了 { $reply }
umpk-packet-size = { $what ->
    [info] 控制器信息数据包不是六个字节
    [errors] 错误历史数据包不是八个字节
    [timing] 时间特性数据包不是四个字节
   *[other] 应为 4 字节的数据包
    }
umpk-no-monitor-packet = { $timeout } 内未收到 { $link } 上的 UMPK 的实时监视数据包
umpk-send-empty = umpk send 需要一条命令（?03FD）或一条记录（:00000002FE）
umpk-not-sent = 未发送给 { $link } 上的 UMPK：{ $reason }
umpk-refused-record = UMPK 拒绝了第 { $n } 条记录（共 { $total } 条，{ $record ->
        [start] 开始记录
        [info] 程序信息记录
        [end] 结束记录
       *[data] 地址 16#{ $first }..16#{ $last } 的数据页
    }）：{ $letter }
umpk-hint-program-incomplete = 编程已中止，新程序不完整：请从头重新运行 `umpk program FILE`；控制器仍处于编程模式（`umpk reset` 使其退出，进入待机）
umpk-answered-record = UMPK 对 HEX 记录回复了 { $reply }
umpk-unknown-model-reported = 控制器报告型号 { $model }，{ $inputs } 个输入、{ $outputs } 个输出，不属于 { $models } 中的任何一种
umpk-model-mismatch = 给出了 model={ $given }，但控制器是 { $found }
umpk-hint-model-mismatch = 请去掉 model= 或改用 model={ $found }
umpk-not-writable = UMPK 终端协议没有写命令（手册 §4.1，表 6），因此无法设置 { $operand }
umpk-hint-not-writable = 输入由接线决定，输出、定时器、计数器和标志位属于程序；在仿真器上请用 `umpk sim input I3=1`
umpk-no-option = UMPK 设备没有选项 `{ $key }`
umpk-hint-options = 选项：timeout, status_bits
umpk-not-model = { $url } 中的 `{ $model }` 不是 UMPK 型号
umpk-hint-models = 型号：{ $models }
umpk-baud-zero = { $url } 中的 `baud=0`：波特率必须为正数
umpk-cannot-read-program = { $url }：无法读取 { $file }：{ $reason }

## UMPK operands (umpk::space; UMPK manual §3.3–§3.5)

# What an area holds (`help I0`, completion).
umpk-area-meaning = { $area ->
    [I] 开关量输入
    [Q] 开关量输出（光耦继电器，48 V 0.3 A）
    [T] 通电延时定时器输出
    [C] 计数器输出脉冲
   *[M] 标志位
    }
# Where plcsh reads an area from.
umpk-area-source = { $area ->
    [I] ?05FB 或监视器
    [Q] ?06FA 或监视器
   *[other] 实时监视器
    }
umpk-not-operand = `{ $text }` 不是 UMPK 操作数
umpk-hint-operands = UMPK 操作数：I0…, Q0…, M0…, T0…, C0…C3（help I0 有详细说明）
umpk-number-must-follow = `{ $text }`：{ $letter } 之后必须跟编号（例如 { $letter }0）
umpk-past-end = { $operand } 超出范围：{ $model } 只有 { $letter }0…{ $letter }{ $last }
umpk-not-range = `{ $text }` 不是同一区域内的范围（例如 I0..I7）
umpk-describe = { $meaning } { $operand }（读取自 { $source }）
umpk-help-operand = { $operand }：{ $model } 的{ $meaning }（{ $letter }0…{ $letter }{ $last }）；BOOL；读取自 { $source }；手册 { $section }。UMPK 终端协议没有写命令。
## UMPK Intel HEX files (umpk::hex; UMPK manual §4.2, Appendix 1)

umpk-hex-no-colon = 记录以 `:` 开头
umpk-hex-not-hex-digit = 记录的第 { $position } 个字符不是十六进制数字
umpk-hex-odd-digits = 记录应有奇数个十六进制数字，至少 10 个；这条有 { $count } 个
umpk-hex-reclen = RECLEN 表示 { $reclen } 个数据字节，但记录中有 { $count } 个
umpk-hex-checksum = 校验码为 { $got }，这些字节需要 { $want }
umpk-hex-line = 第 { $line } 行：{ $message }
umpk-hex-after-end = 第 { $line } 行：结束记录（01）之后还有记录
umpk-hex-outside-memory = 第 { $line } 行：地址 16#{ $first }..16#{ $last } 的数据超出程序存储器（16#0000..16#{ $top }，{ $memory } 字节）
umpk-hex-twice = 第 { $line } 行：地址 16#{ $address } 被写了两次
umpk-hex-type-02 = 第 { $line } 行：带 { $count } 个数据字节的 02 类记录：UMPK 只把 02 类当作不带数据的开始记录（:00000002FE，由 plcsh 自己发送）；在标准 Intel HEX 中它是扩展段地址，不超过 3 KB 的程序用不到 — 请删除该行
umpk-hex-info-size = 第 { $line } 行：程序信息为 1–22 字节，而不是 { $count }
umpk-hex-record-type = 第 { $line } 行：UMPK 不接受记录类型 { $rtype }（00 数据，01 结束，02 开始，03 程序信息）
umpk-hex-no-end = 文件没有结束记录（:00000001FF）
umpk-hex-no-data = 文件中没有数据记录

## The simulated UMPK's control words (umpk::sim::control; `umpk sim …`, the control channel)

umpk-sim-hint-words = 控制字：{ $words }
umpk-sim-not-input = `{ $text }` 不是输入（I0…I{ $last }）
umpk-sim-no-such-input = I{ $n } 不是 { $model } 的输入（I0…I{ $last }）
umpk-sim-input-usage = input 需要一个输入和一个电平：input I3=1
umpk-sim-input-extra = 无法理解 input I{ $n } 之后的 `{ $word }`
umpk-sim-level-and-freq = 请给出电平或 freq=，不能两者都给
umpk-sim-freq-range = freq={ $freq }：10 ms 的周期只能识别 0.0001–50 Hz 的方波
umpk-sim-wave-set = I{ $n }：方波，周期 { $period } ms
umpk-sim-not-input-option = `{ $option }` 不是输入的选项（freq=）
umpk-sim-level-missing = I{ $n }：请给出 =1、=0 或 freq=…
umpk-sim-inputs-extra = `inputs` 后面不带参数（收到了 `{ $word }`）
umpk-sim-inputs = 输入 { $bits }（I{ $last }…I0）；方波：{ $waves }
umpk-sim-inputs-no-waves = 输入 { $bits }（I{ $last }…I0）；没有方波
umpk-sim-not-page = `{ $page }` 不是页号
umpk-sim-flash-fail = 写入第 { $page } 页（16#{ $address }）的闪存将以 W 失败
umpk-sim-flash-ok = 闪存写入成功
umpk-sim-not-word = `{ $word }` 不是 UMPK 仿真器的控制字
umpk-sim-empty-line = 空的控制行

## Snapshots of the simulated UMPK (umpk::sim::snapshot): why one cannot be taken or restored

umpk-snap-monitor = 它的实时监视正在发送数据（请先用 `umpk monitor off` 停止）
umpk-snap-programming = 编程过程正在进行（请先完成或复位）
umpk-snap-line-busy = 它的串口上还有字节（命令只收到一半或回复尚未发出）
umpk-snap-builtin-program = 它的程序 `{ $program }` 内置于 plcsh，不是 IL 文本（请改为加载 IL 文件）
umpk-snap-other-model = 快照保存的是 { $saved }，而此设备是 { $model }
umpk-snap-flash-size = 闪存映像大小不对
umpk-snap-info-size = 程序信息或错误历史的大小不对
umpk-snap-markers = 标志位不是 32 位十六进制数字
umpk-snap-timers = 定时器或计数器与型号不符
umpk-snap-wave = 输入 { $input } 上每 { $period } 个周期的方波无法在此型号上运行
umpk-snap-flash-fail-page = 它的故障闪存页 { $page } 超出了该型号的程序存储器
umpk-snap-fault-input = 它的故障 { $fault } 涉及此型号没有的输入
umpk-snap-cycle-ahead = 它的周期计数超前于快照的时钟
umpk-snap-mode = 无法恢复模式 `{ $mode }`
umpk-snap-il-compile = 它的 IL 程序 { $source } 无法编译：{ $reason }
umpk-snap-il-state = 它的 IL 程序保存的状态与程序不符（{ $part }）
umpk-snap-il-mid-scan-part = 它的 IL 程序是在扫描中途保存的（{ $part }）
umpk-snap-il-mid-scan = 它的 IL 程序是在扫描中途保存的

## The simulated UMPK's flash file and its server (umpk::sim::state, umpk::sim::serve)

umpk-state-cannot-encode = 无法编码 UMPK 状态
umpk-state-cannot-read = 无法读取 { $file }
umpk-state-bad-file = { $file } 不是 UMPK 状态文件：{ $reason }
umpk-state-hint-remove = 删除它即可从空闪存开始
umpk-state-other-model = { $file } 保存的是 { $saved } 的闪存，而不是 { $model } 的
umpk-state-hint-other-file = 请为此型号使用另一个状态文件
umpk-state-info-size = 程序信息或错误历史的大小不对
umpk-serve-read-failed = 读取 UMPK 的线路失败
umpk-serve-binary = UMPK 仿真器：写入了二进制程序；{ $note }
umpk-serve-write-failed = 写入 UMPK 的线路失败
umpk-serve-not-model = `{ $model }` 不是 UMPK 型号（{ $models }）
umpk-serve-cannot-read-program = 无法读取 UMPK 程序 { $file }：{ $reason }
umpk-serve-line-stopped = UMPK 线路在就绪前停止了

## The simulated UMPK (umpk::sim)

# What the simulator says when a binary is programmed into it.
umpk-sim-binary-not-executed = 仿真器保存并校验写入的二进制程序，但不执行它（UMPK 的机器码未公开）：复位后状态显示运行模式（已装入程序），而输出保持关闭；要在仿真器中运行逻辑，请装入 IL 程序（`sim program load FILE.il`、`sim serve --umpk-program FILE.il`；docs/il.md）
umpk-sim-page-past-end = 闪存页 { $page } 超出了 { $model } 的程序存储器：页 0–{ $last }（{ $bytes } 字节，每页 { $size } 字节）
umpk-sim-hint-page = 请给出 0 到 { $last } 的页号，或 `off`
umpk-sim-program-kind = { $kind ->
    [none] 无
   *[binary] 二进制程序（已保存并校验，不执行）
    }
umpk-sim-program-logic = { $program }（每个周期执行）
# The status word's flags in words (`umpk info`; UMPK manual §4.1.4).
umpk-status-flag = { $flag ->
    [W] W 运行模式
    [H] H 错误历史非空
    [R] R 实时监视已开启
    [E] E 回显已关闭
    [P] P 编程模式
   *[T] T LED 闪烁相位
    }

## IL programs on the simulated UMPK (umpk::sim::program, umpk::sim::logic; UMPK manual §3.5)

umpk-il-range = `{ $text }` 是一个范围；程序操作数只能是一个位
umpk-il-elements = { $text }：UMPK 的定时器和计数器是它自己的指令
umpk-il-hint-elements = 通电延时：TIMER T0, GROUP, STEPS（例如 TIMER T0, 1, 20 为 2.0 s）；N 分频：DIVIDE C0, 4[, I1]
umpk-il-cannot-assign = { $text }：程序不能给 { $operand }（{ $meaning }）赋值
umpk-il-hint-assign = 程序只能给输出 Q 和标志位 M 赋值；定时器和计数器通过 TIMER 和 DIVIDE 改变
umpk-il-user-error = { $text }：用户错误代码为 1–127（128–255 属于系统）
umpk-il-hint-user-error = 例如 LD I7 / ERROR 12：I7 接通时错误历史中记入错误 12
umpk-il-first-operand = { $text }：第一个操作数必须是{ $what ->
        [timer] 定时器 T0…
       *[counter] 计数器 C0…
    }
umpk-il-delay-group = { $text }：延时组为 0（10 ms）、1（0.1 s）或 2（1 s）
umpk-il-delay-steps = { $text }：延时为其组的 1–255 步
umpk-il-ratio = { $text }：分频比为 1–255
umpk-logic-no-timer = 没有定时器 T{ $n }
umpk-logic-delay = T{ $n }：延时为 1–255 步
umpk-logic-no-counter = 没有计数器 C{ $n }
umpk-logic-ratio = C{ $n }：分频比为 1–255
umpk-logic-cannot-assign = { $operand }：程序不能给 { $area } 操作数赋值

## FX driver: the programming port and the computer link (fx::driver; the FX protocol notes, seed 004)

# What a request was, inside the messages below (`no reply to … on COM6`).
fx-req-port = 在 { $address }H 处{ $kind ->
    [read] 读取
    [e00] E00 读取
    [write] 写入
   *[e10] E10 写入
    } { $count } 个字节
fx-req-port-operand = { $kind ->
    [write] 写入
   *[e10] E10 写入
    } { $operand }
fx-req-link-read = 从 { $device } 起 { $cmd } { $count } 点
fx-req-link-bw = 在 { $device } 处 BW { $count } 点
fx-req-link-ww = 在 { $device } 处 WW { $count } 个值
fx-req-link-wt = WT { $count } 个值
# What one attempt got, in the list of attempts.
fx-got = { $got ->
    [data] 数据
    [bad-sum] 和校验错误
    [other] 其他回复
    [noise] 噪声
    [partial] 不完整的回复
   *[silence] 无回复
    }
fx-attempts = { $n } 次尝试
fx-attempts-list = { $n } 次尝试：{ $list }
fx-late = ；之后又到了 { $count } 个字符，已丢弃（迟到的回复绝不会当作下一个请求的回复）
# The parts of a timeout: where its milliseconds come from.
fx-timeout-given = { $time }（timeout={ $given }）
fx-timeout-wire = { $serial } 下 { $count } 个字符：线路上 { $ms } ms
fx-timeout-wait = 报文等待 { $ms } ms
fx-timeout-plc = PLC 响应 { $ms } ms
fx-timeout-server = 设备服务器 { $ms } ms
fx-timeout-total = { $ms } ms（{ $parts }）
fx-not-quiet = 在 { $what } 之前线路 { $line } 没有安静下来：{ $ms } ms 内到达了 { $count } 个字符
fx-hint-not-quiet-port = 编程口只能由一个程序使用：请关闭其上的 GX Developer、人机界面或终端程序；检查电缆是否有干扰
fx-hint-not-quiet-link = plcsh 必须是计算机链接上唯一的主站：请停止其他轮询该线路的程序；检查电缆干扰和 RS-485 终端电阻
fx-no-reply = { $timeout } 内 { $line } 上没有对 { $what } 的回复{ $late }
fx-no-reply-station = { $timeout } 内 { $line } 上没有对 { $what }（站号 { $station }）的回复{ $late }
fx-no-reply-no-enq = { $timeout } 内 { $line } 上没有对 { $what }（未发 ENQ 发送：它对 ENQ 也没有回复）的回复{ $late }
fx-nak-code = { $who ->
    [plc] PLC
   *[station] 站号 { $station }
    } 对 { $line } 上的 { $what } 回复了 NAK { $code }H：{ $meaning }
fx-hint-nak-area = 请对照型号检查操作数（`help OPERAND`）
fx-hint-nak-pc = FX 的 PLC 号为 FF（pc=FF）
fx-hint-nak-sum = 请检查和校验设置（sum=，D8120）和线路噪声
fx-hint-nak-other = 请检查 PLC 的计算机链接设置（D8120、D8121）
fx-nak = PLC 对 { $line } 上的 { $what } 回复了 NAK（{ $tries }）：它拒绝和校验错误的帧或没有该元件的地址
fx-hint-nak-extended = 请对照型号检查操作数（`help OPERAND`）和线路噪声；不支持 E 命令（E00/E10/E7/E8）的 PLC 会回复 NAK：请以 model=FX2N 打开
fx-hint-nak-classic = 请对照型号检查操作数（`help OPERAND`）和线路噪声
fx-bad-reply = { $line } 上对 { $what } 的回复错误（{ $tries }）：{ $reason }
fx-hint-bad-sum-port = 线路噪声或波特率/奇偶校验错误（编程口为 7E1）
fx-hint-bad-sum-link = 线路噪声，或波特率、字符格式与 PLC 的（D8120）不同
fx-noise = 线路 { $line } 上是噪声而不是对 { $what } 的回复（{ $tries }）：{ $bytes } — 不可能作为回复开头的字符（串口对有奇偶校验或帧错误的字符给出 00H）
fx-hint-noise = 请检查电缆的屏蔽和接地、转换器的电源和 RS-422/485 终端电阻，以及 PLC 是否为 { $serial }（波特率或格式不同也会表现为噪声）
fx-incomplete = { $timeout } 内 { $line } 上对 { $what } 的回复不完整（{ $tries }）：只收到 { $bytes }
fx-hint-incomplete = 请检查波特率（{ $serial }），或加大超时（URL 中的 timeout=）
fx-other-reply = { $who ->
    [plc] PLC
   *[station] 站号 { $station }
    } 对 { $line } 上的 { $what } 回复了别的内容（{ $tries }）：{ $reason }
fx-hint-other-port = 编程口只能由一个程序使用：请关闭其上的 GX Developer、人机界面或终端程序
fx-hint-other-link = 请确认没有其他站设为站号 { $station }（D8121），也没有其他程序轮询这条线路；超时之后到达的回复属于更早的请求（请加大 timeout=）
fx-no-usable-reply = { $line } 上没有对 { $what } 的可用回复（{ $tries }）
fx-hint-late = PLC 的回复晚于 { $time }：请加大超时（URL 中的 timeout={ $twice }），或检查其扫描时间（D8012）
fx-hint-silent-port = 请检查电缆、确认这是编程口，并且设置为 { $serial }
fx-hint-silent-link = 请检查站号 { $station }（PLC 的 D8121）、PLC 号 FF、波特率和格式（D8120）以及和校验设置
fx-read-only = 无法设置 { $operand }（{ $meaning }）
fx-special-device = 特殊元件
fx-driven-by-plc = { $operand }（{ $meaning }）由 PLC 驱动：写入会被忽略
fx-hint-run-stop = RUN/STOP 是 PLC 的开关：在仿真器上用 `sim cpu stop` / `sim cpu run`
fx-hint-driven = PLC 每次扫描都会设置它；请读取它，或用普通的 M 或 D 作为自己的标志
fx-retries = retries `{ $value }` 必须为 0–10
fx-no-option = fx 设备没有选项 `{ $key }`
fx-hint-options = 选项：timeout, retries
# What a reply was instead of the one asked for (fx::driver::computer_link, programming_port).
fx-reply-other-length = 数据帧含 { $got } 个数据字符，而请求的是 { $want } 个（另一个请求的回复）
fx-reply-data-not-ack-link = 应为 ACK 处收到数据帧（{ $bytes }）：只有站回复 ACK 写入才算完成
fx-reply-data-not-ack = 应为 ACK 处收到数据帧（{ $bytes }）
fx-reply-ack-not-data = 应为数据处收到 ACK
fx-reply-sum = 和校验为 { $got }，字符累加和为 { $want }
fx-reply-station = 回复来自站号 { $station }（PLC 号 { $pc }），应由站号 { $want }（PLC 号 { $wantpc }）回复
fx-reply-garbled = 乱码帧（{ $bytes }）：{ $reason }
fx-bad-bits-reply = 对 { $what } 的回复错误：应为 { $count } 个 0/1 字符
fx-bad-words-reply = 对 { $what } 的回复错误：应为 { $count } 个十六进制值
fx-param-out-of-range = { $url } 中的 `{ $key }={ $value }` 超出范围
fx-hint-param = { $key ->
    [station] 站号为 0–31
    [wait] 等待时间为 0–15（×10 ms，0–150 ms）
   *[pc] PLC 号为两位十六进制数字，FX 为 FF
    }
fx-sum-param = { $url } 中的 `sum={ $value }` 不是 0 或 1
fx-format-param = { $url } 中的 `format={ $value }`：支持格式 1 和 4
fx-xy-param = { $url } 中的 `xy={ $value }`：octal 或 decimal
fx-line-params = { $url }：bits=7|8，parity=e|o|n，stop=1|2，baud 大于 0
fx-enq-nak = PLC 在 { $line } 上对 ENQ 回复了 { $count } 次 NAK
fx-hint-enq-nak = 可能有其他程序正在使用编程口
fx-past-table = 超出地址表
fx-baud-zero = { $url } 中的 `baud=0`：波特率必须为正数
fx-sim-other-model = 仿真 PLC `{ $name }` 是 { $model }，不是 { $want }
fx-cannot-read-program = { $url }：无法读取 { $file }：{ $reason }
fx-protocol-param = { $url } 中的 `protocol={ $value }`：port 或 link

## FX operands (fx::operand, fx::space; the FX protocol notes, seed 004)

# What a device area holds (`help`, completion, messages).
fx-area-meaning = { $area ->
    [X] 输入
    [Y] 输出
    [M] 辅助继电器
    [S] 状态继电器
    [TS] 计时器触点
    [TC] 计时器线圈（由程序驱动；只读）
    [CS] 计数器触点
    [CC] 计数器线圈（由程序驱动；只读）
    [TN] 计时器当前值
    [CN] 计数器当前值（CN200–CN255 为 32 位）
   *[D] 数据寄存器
    }
# Special devices (FX programming manual, special device lists).
fx-special-meaning = { $device ->
    [M8000] RUN 监视（PLC 运行时接通）
    [M8001] RUN 监视，取反（PLC 运行时断开）
    [M8002] 初始脉冲（RUN 后第一次扫描接通）
    [M8003] 初始脉冲，取反（RUN 后第一次扫描断开）
    [M8011] 10 ms 时钟脉冲（通 5 ms，断 5 ms）
    [M8012] 100 ms 时钟脉冲（通 50 ms，断 50 ms）
    [M8013] 1 s 时钟脉冲（通 0.5 s，断 0.5 s）
    [M8014] 1 min 时钟脉冲（通 30 s，断 30 s）
    [D8000] 看门狗定时器时间，ms
    [D8010] 当前扫描时间，0.1 ms
    [D8011] 最小扫描时间，0.1 ms
    [D8012] 最大扫描时间，0.1 ms
    [D8120] 通信格式（计算机链接：波特率、奇偶校验、和校验 …）
   *[D8121] 计算机链接站号
    }
fx-range-kind = 范围需要两个种类和大小相同的操作数：{ $first }..{ $last }
fx-range-reversed = 范围终点 { $last } 在起点 { $first } 之前
fx-range-steps = { $last } 与 { $first } 之间不是 { $step } 的整数倍步长
fx-range-long = 范围超过 { $max } 个操作数
fx-number-missing = `{ $text }` 在 { $area } 之后需要元件编号
fx-not-digit = `{ $text }` 中的 `{ $char }` 不是数字
fx-number-long = 元件编号 `{ $digits }` 太长
fx-not-octal = { $area } 的编号是八进制（{ $area }0–{ $area }7，{ $area }10–{ $area }17 …）：`{ $text }` 中的 `{ $char }` 不是八进制数字
fx-number-large-octal = `{ $digits }` 太大：元件编号最大为 177777（八进制）
fx-number-large = `{ $digits }` 太大：元件编号最大为 { $max }
fx-operand-missing = 缺少操作数
fx-unknown-type = 未知类型 `{ $name }`（请用 WORD、INT、DWORD、DINT、REAL）
fx-group-digits = K{ $n }：位组合为 1–8 组，每组 4 位（K1 … K8）
fx-unknown-device = 未知的 FX 元件 `{ $text }`
fx-hint-devices = 元件：X Y M S（位元件），T C 或 TS CS（计时器/计数器触点），TC CC（线圈），TN CN D（字元件），KnX KnY KnM KnS（位组合）
fx-group-area = K{ $n }{ $area }：位组合只能由 X、Y、M 或 S 位组成
fx-view = { $operand } 不能按 { $dtype } 读取
fx-hint-view = D 可用 /WORD、/INT、/DWORD、/DINT、/REAL（32 位：D 和下一个 D）；K1–K4 位组合可用 /INT、/WORD、/DINT、/DWORD；K5–K8 位组合可用 /DINT、/DWORD（K8 也可用 /REAL）

fx-not-on-model = { $model } 上没有 { $operand }（{ $range }）
fx-crosses-special = { $operand } 从普通元件跨入了特殊元件
fx-hint-e-commands = FX3U 上可用 E 命令访问它（用 model=FX3U 打开）；{ $model } 上只能通过计算机链接访问（fxlink:，需要 FX-485 板并设置 D8120）
fx-past-port-table = { $operand } 超出了 { $model } 编程口地址表（{ $commands }；其范围为 { $reach }）
fx-not-on-link = { $operand }（{ $meaning }）无法通过计算机链接访问
fx-hint-not-on-link = 请改为读取触点（TS/CS），或使用编程口（fx:）
fx-describe-group = { $first }–{ $last } 的 { $bits } 位{ $meaning }位组合
fx-describe-pair = D{ $low }（低位）和 D{ $high }（高位）中的 32 位值
fx-describe-special = 特殊{ $meaning }
fx-describe-unaligned = {" "}— 警告：位组合从 { $first } 开始；手册建议编号以 0 结尾（{ $area }0、{ $area }10 …）
fx-complete-group = { $bits } 位{ $meaning }位组合

## Kinco servo driver (servo::driver, servo::frame; Kinco servo RS232 notes, seed 002)

# The manual's three reasons a drive stays silent (§2.4).
servo-silence-causes = 步科驱动器在以下情况不会回复：① 错误的驱动器 ID，② 不存在的对象，③ 校验码错误（手册 §2.4）
servo-port-still-gone = 串口 { $port } 仍然不存在
servo-port-gone = 串口 { $port } 已消失
servo-port-io = 串口 { $port } 读写失败
servo-hint-port-gone = USB 转换器可能被拔出，或串口服务器已重启：请检查电缆和转换器（`plcsh ports` 列出现有串口）；串口恢复后，下一条命令会重新打开它
servo-no-echo = { $port } 上没有请求的回显（环路模式已开启）
servo-hint-no-echo = 环路断开（电缆），或线路不在环路模式：请从 URL 中去掉 echo=1
servo-reply-before-echo = { $port } 上应先收到请求的回显（echo=1），但先到的是驱动器的回复：{ $bytes }；线路不在环路模式
servo-hint-reply-before-echo = 请用 echo=0 连接（或设置驱动器的环路模式，面板 d5.15 = 1）
servo-echo-differs = { $port } 上的回显与请求不同：发送 { $sent }，回显 { $echo }；可能原因：校验码错误 — 驱动器忽略损坏的报文
servo-hint-baud-wiring = 请检查波特率（驱动器默认 38400，面板 d5.02）和接线
servo-reply-is-request = 对 { $object } 的{ $verb ->
        [read] 读取
        [write] 写入
       *[request] 请求
    }的回复就是请求本身：线路回显请求（RS232 环路模式）
servo-hint-use-echo = 请用 echo=1 连接，让 plcsh 跳过回显
servo-bad-reply = 对 { $object } 的{ $verb ->
        [read] 读取
        [write] 写入
       *[request] 请求
    }回复错误：{ $reason }
servo-hint-bad-reply = 线路上可能有其他主站或驱动器在通讯，或波特率不对
# No reply: the head and the likely cause in one sentence.
servo-silent = 驱动器 ID { $id } 在 { $timeout } 内未回复对 { $object } 的{ $verb ->
        [read] 读取
        [write] 写入
       *[request] 请求
    }；可能原因：{ $cause ->
        [function] 未知功能码 { $code } — 驱动器只回复读（40）和写（23、2B、2F），忽略其他功能码
        [checksum] 校验码错误 — 报文以 { $got } 结尾，而前面的字节需要 { $want }
        [stray] 校验码错误 — 只收到 { $count } 个零散字节（{ $bytes }），报文在线路上被破坏（波特率或接线）
        [object] 对象不存在 — 驱动器 ID { $id } 能回复状态字读取，所以此驱动器上很可能没有 { $object }
        [stopped] 驱动器停止回复 — ID { $id } 之前回复过；请检查电源和电缆
       *[id] ID 错误 — 驱动器 ID { $id } 上没有任何回复（出厂 ID 为 1，面板 d5.01；也请检查电源、电缆和波特率）
    }
servo-silent-late = 驱动器 ID { $id } 在 { $timeout } 内未回复对 { $object } 的{ $verb ->
        [read] 读取
        [write] 写入
       *[request] 请求
    }；可能原因：回复迟到 — { $what }
servo-late-stale = 收到的是对另一个请求的回复（{ $frames }）
servo-late-bytes = 超时后到达 { $count } 个字节，已丢弃
servo-hint-late = 驱动器回复晚于超时：请加大超时（URL 中的 timeout=，当前 { $timeout }），并确认线路上没有其他主站；迟到的回复绝不会当作下一个请求的回复
servo-refused = 驱动器 ID { $id } 拒绝了对 { $object } 的{ $verb ->
        [read] 读取
        [write] 写入
       *[request] 请求
    }：中止代码 16#{ $code } — { $meaning }
servo-resolution-zero = 驱动器报告的反馈精度为 0（6410.03）
servo-no-option = servo 设备没有选项 `{ $key }`
servo-hint-options = 选项：encoder, timeout
servo-flag-param = { $url } 中的 `{ $key }={ $value }` 不是 0 或 1
servo-baud-zero = { $url } 中的 `baud=0`：波特率必须为正数
servo-latency-param = { $url } 中的 `latency={ $value }` 不是时长（例如 1ms）
servo-ids-in-url = { $url } 中：{ $message }
servo-not-ids = `{ $list }` 不是驱动器 ID 列表（0–255），例如 1,2
# What is wrong with a reply frame (servo::frame).
servo-frame-checksum = 校验码 { $got } 错误（前面的字节算出的校验码为 { $want }）
servo-frame-reply-checksum = 回复的校验码 { $got } 错误（前面的字节算出的校验码为 { $want }）
servo-frame-id = 回复来自驱动器 ID { $got }，应为 ID { $want }
servo-frame-object = 回复针对对象 { $got }，应为 { $want }
servo-frame-func = 回复的功能码 { $got } 不是对 { $request } 请求的回复
servo-frame-echo = 写入确认回传的数据为 { $got }，而请求发送的是 { $want }
# CANopen abort codes the drive answers with (function code 80).
servo-abort = { $code ->
    [x05040001] 无效命令
    [x06010001] 试图读取只写对象
    [x06010002] 试图写入只读对象
    [x06020000] 对象字典中不存在该对象
    [x06040041] 对象无法映射
    [x06070010] 数据类型不匹配，服务参数长度不匹配
    [x06070012] 数据类型不匹配，服务参数长度过长
    [x06090030] 超出参数的数值范围
   *[other] 未知的中止代码
    }

## The simulated Kinco drive's faults and switches (servo::sim::control, servo::sim::faults; `servo sim …`)

servo-sim-not-number = `{ $text }` 不是数字
servo-sim-id-range = 驱动器 ID 为 0-255
servo-sim-unknown-option = 未知选项 `{ $key }`
servo-sim-count = count 为 1 或以上，或 all
servo-sim-all-and-count = 请给出 `all` 或 count=N，不能两者都给
servo-sim-fault-extra = `fault { $kind }` 之后出现意外的 `{ $word }`：请给出 all 或 count=N
servo-sim-fault-duration = fault { $kind } 需要一个时长，例如 fault { $kind } 50ms
servo-sim-fault-abort = fault abort 需要一个对象和一个中止代码，例如 fault abort target_position 16#06090030
servo-sim-abort-bits = 中止代码为 32 位
servo-sim-pulses-freq = pulses 需要 freq=HZ
servo-sim-pulses-count = pulses 需要 count=N
servo-sim-not-freq = `{ $text }` 不是以 Hz 为单位的频率
servo-sim-pulse-count = count 为 0 或以上
servo-sim-not-dir = `dir={ $dir }` 不是 fwd 或 rev
servo-sim-unknown-word = 未知的 `servo sim { $word }`
servo-sim-fault-bits = 故障代码为 16 位
servo-sim-no-drive = 没有 ID 为 { $id } 的仿真驱动器（ID：{ $ids }）
servo-sim-several-drives = 线路上有多个驱动器（{ $ids }）：请用 id=N 指定
servo-sim-fault-injected = 驱动器 ID { $id }：已注入故障 16#{ $code }
servo-sim-fault-armed = 驱动器 ID { $id }：故障 16#{ $code } 已设定在位置 { $position } inc 触发
servo-sim-fault-acted = { $time }s  驱动器 ID { $id }：在位置 { $position } inc 出现故障 16#{ $code }（设定的故障已触发）
servo-sim-no-fault-acted = 没有设定的故障被触发
servo-sim-line-fault = { $scope ->
        [all] 所有驱动器
       *[one] 驱动器 ID { $id }
    }：{ $count ->
        [one] 下一个请求
        [every] 直到 `servo sim fault clear` 之前的每个请求
       *[many] 接下来的 { $n } 个请求
    }{ $fault }
servo-sim-faults-cleared = 线路故障已清除
servo-sim-switch = 驱动器 ID { $id }：{ $switch ->
        [home] 原点开关
        [neg] 负限位开关
       *[pos] 正限位开关
    }{ $position ->
        [off] 关闭
       *[at] 位于 { $at } inc
    }
servo-sim-pulses = 驱动器 ID { $id }：从 t={ $start } s 到 t={ $end } s，{ $dir ->
        [reverse] 反向
       *[forward] 正向
    } { $count } 个脉冲，频率 { $freq } Hz
servo-sim-strict = 写入长度：{ $strict ->
        [on] 长度必须与对象一致（否则 0x06070010）
       *[off] 宽松长度
    }
# A line fault in words (`servo sim fault …`, `faults`).
servo-sim-fault-kind = { $kind ->
    [no-reply] 无回复
    [bad-checksum] 回复校验码错误
    [delay] 回复延迟 { $ms } ms
    [abort] 对 { $object } 回复中止代码 16#{ $code }（{ $meaning }）
   *[drop-echo] 丢弃回显
    }

## FX frames (fx::link, fx::port; the FX protocol notes, seed 004)

# What is wrong with a frame (inside `a garbled frame (…): …`).
fx-malformed = { $what ->
    [no-crlf] 回复后没有 CR LF
    [too-short] 太短
    [station-not-hex] 站号或 PLC 号不是十六进制
    [code-not-hex] 错误代码不是十六进制
    [length-after-etx] ETX 之后长度错误
    [sum-not-hex] 和校验不是十六进制
    [bytes-after-etx] ETX 之后还有字节
    [unknown-command] 未知命令或长度错误
    [address-not-hex] 地址不是十六进制
    [count-not-hex] 数量不是十六进制
    [data-length] 数据长度与数量不符
    [data-not-hex] 数据不是十六进制
   *[not-read-reply] 不是所请求长度的 STX 数据 ETX 和校验
    }
# The computer link's NAK error codes (seed 004: "若发送码有误，则有以下回应").
fx-nak-meaning = { $code ->
    [c02] 和校验错误（请求中的和校验与其字符不符）
    [c03] 协议错误（请求不符合控制规程）
    [c06] 字符区错误（未知命令，或 PLC 没有的元件编号或数量）
    [c07] 字符错误（写入的数据不是十六进制 ASCII）
    [c0A] PLC 号错误（没有该 PLC 号的站）
    [c18] 远程错误（无法远程切换 RUN/STOP）
   *[other] 未知错误代码
    }

## The simulated FX PLC's control words, snapshots and server (fx::control, fx::snapshot, fx::sim)

fx-sim-not-x = `{ $text }` 不是 X 输入（X0、X17 …）
fx-sim-no-such-input = { $operand } 不是 { $model } 的输入（X0–X{ $last }）
fx-sim-input-usage = input 需要一个输入和一个电平：input X0=1
fx-sim-input-extra = 无法理解 input { $input } 之后的 `{ $word }`
fx-sim-input-level = `{ $input }`：请写 input { $input }=1 或 =0
fx-sim-inputs-none = 没有接通的 X 输入
fx-sim-inputs-on = 接通：{ $inputs }
fx-sim-not-word = `{ $word }` 不是 FX PLC 仿真器的控制字
fx-snap-other-model = 快照来自 { $saved }，而此仿真器是 { $model }
fx-snap-image = 保存的元件映像与此型号不符
fx-serve-cannot-read = 无法读取 { $file }：{ $reason }
fx-serve-stopped = FX 端口在就绪前停止了

## The simulated drive's homing and pulse input (servo::sim)

servo-sim-homing-neg = 方法 17 需要负限位开关
servo-sim-homing-pos = 方法 18 需要正限位开关
servo-sim-homing-method = 回原点方法 { $method } 未仿真（支持的方法 { $methods }）
servo-sim-no-drive-id = 仿真线路上没有驱动器 ID { $id }
servo-sim-pulse-ab = 驱动器的脉冲输入设为 A/B 相（2508.03 = 2）；PLC 的脉冲输出是脉冲 + 方向：请先把 2508.03 设为 1
servo-sim-no-drive-short = 没有驱动器 ID { $id }
servo-not-servo-any-more = 该设备不再作为伺服驱动器应答

## Links: control channels, shared lines, RFC 2217, pseudo-terminals (core::link)

link-cannot-open-channel = 无法在 { $path } 打开{ $what }
link-hint-channel-path = 请选择其他路径，或删除被终止的服务器遗留的旧文件
link-control-line-long = 控制行最多 { $max } 字节
link-control-line-utf8 = 控制行必须是 UTF-8 文本
link-cannot-reach-channel = 无法连接仿真器的控制通道 { $path }
link-hint-reach-channel = `plcsh sim serve` 还在运行吗？它的就绪行给出了控制通道的路径
link-channel-answered = 控制通道回复了 `{ $reply }`
link-simulator-refused = 仿真器拒绝了
# The names of the simulators' control channels (inside link-cannot-open-channel).
link-channel-name = { $device ->
    [servo] 伺服控制套接字
    [umpk] 所服务的 UMPK 的控制通道
   *[fx] 所服务的 FX PLC 的控制通道
    }
link-line-settings = { $line } 已用 { $open } 打开，而不是 { $settings }
link-hint-line-settings = 同一线路上的所有驱动器使用相同的波特率和环路设置
link-pipe-closed = 管道的另一端已关闭
link-no-reply-timeout = 超时内无回复
link-rfc2217 = { $addr } 上的 RFC 2217 服务器{ $what ->
        [confirm] 未及时确认线路设置
        [agree] 未及时同意设置串口（COM-PORT-OPTION）
        [closed] 关闭了连接（{ $reason }）
        [refused] 拒绝让本端设置串口
       *[baud] 设置的波特率为 { $got }，而不是 { $want }
    }
link-hint-rfc2217 = 请确认设备服务器的通道处于 RFC 2217 模式（原始 TCP 通道请用 +tcp://），并支持该波特率和格式
link-pty-dup-master = 无法复制伪终端主端
link-pty-dup-slave = 无法复制伪终端从端
link-pty-register = 无法向 tokio 注册伪终端主端
link-pty-open = 无法打开伪终端
link-pty-call = 伪终端上的 { $call }
link-pty-nonblocking = 无法将伪终端设为非阻塞
link-not-symlink = { $path } 已存在且不是符号链接；请选择其他路径
link-cannot-symlink = 无法创建符号链接 { $path }
link-control-no-port = 控制文件中没有端口号
link-windows-no-pty = Windows 没有可供仿真器使用的伪终端
link-hint-windows-tcp = 请改为在 TCP 端口上运行（sim serve --rtu-tcp 0、--servo-tcp 0、--fx-tcp 0、--fx-link-tcp 0、--umpk-tcp 0），并用 rtu+tcp://、kinco+tcp://、fx+tcp://、fxlink+tcp:// 或 umpk+tcp:// 连接

# `help OPERAND` on an FX (fx::space).
fx-help-group-range = 0…{ $max }（缺少的高位为零）
fx-help-port = 编程口（{ $commands }）：字节地址 { $address }H，{ $bytes } 字节
fx-help-force = ，强制置位/复位地址 { $address }H
fx-help-link = 计算机链接：元件 { $device }
fx-help-manual = 手册：seed 004（FX 位组合 KnX、编程口协议；fx-and-masterk.md A、B）
fx-help-type = 类型 { $dtype }（{ $bits } 位），范围 { $range }
fx-help-on-model = { $model } 上：{ $range }

# The two ways to an FX (fx::space::Proto).
fx-proto = { $proto ->
    [port] 编程口
   *[link] 计算机链接
    }
