# plcsh 的简体中文消息。术语按术语表 (shared/spec/glossary.md)：按步科伺服、K80S 和 FX 手册的写法。
# 操作数、指令助记符、命令、选项和 JSON 键保持原样。

## 错误的格式 (core::error, output)

label-hint = 提示：{ $hint }
label-warning = 警告：{ $warning }
label-note = 注：{ $note }

error-kind-cause = { $kind ->
    [syntax] 该行无法解析：多余的字符、未闭合的引号、`set` 中缺少 `=`
    [operand] 操作数未知或格式错误 (`VX0`、`M0.8`、`SMB`)
    [value] 值超出操作数的范围 (`set VB2=300`)，或不是所要求单位的数值
    [range] 操作数超出该型号存储区的末尾，或该型号没有此存储区 (K205-16DT 上的 `AIW0`)
    [unsupported] 此设备或连接不支持该操作：通过普通 Modbus 访问 SM、T 和 C，没有辅助程序时执行指令
    [refused] 设备回复了拒绝：Modbus 异常响应、伺服驱动器中止代码、辅助程序的结果
    [link] 无回复、超时、校验码错误 (CRC)、连接断开、串口无法打开
    [timeout] 等待超时 (`wait`、辅助程序命令未被确认)
    [usage] 命令用法错误：缺少参数、未知的命令或设备、文件被占用
    [script] Lua 脚本失败：运行时错误、`plcsh.assert_eq` 未通过、`os.exit`
    [io] 文件或操作系统出错：文件无法读取或写入
    [interrupted] Ctrl-C、SIGTERM 或 SIGHUP 停止了命令；中止处理已执行
   *[state] 设备处于无法执行该命令的状态：PTO 忙、辅助程序的邮箱忙、辅助程序已停止
}
error-kind-fix = { $kind ->
    [syntax] 行下方的 ^ 指向出错的词；`help COMMAND` 显示命令格式
    [operand] `help VW100` 解释操作数；Tab 键补全操作数
    [value] 消息给出操作数类型的范围；有符号值请使用视图 (`VW0/INT`)
    [range] 将 URL 中的 `model=` 与 PLC 核对 (`plcsh models`)；提示列出具有该存储区的型号
    [unsupported] 为 SM 寄存器和指令安装辅助程序 (docs/agent.md)，或使用仿真器
    [refused] 提示说明是哪种拒绝；遇到 `illegal data address` 时将 `model=` 与 PLC 核对
    [link] 按无回复检查清单：unit id、baud/parity/stop、A/B 接线、权限、占用串口的程序；`-v` 显示收发的帧
    [timeout] 延长等待时间，或检查 PLC 是否处于 RUN 模式、辅助程序是否每个扫描周期都被调用
    [usage] `help COMMAND`；`devices` 列出设备名称
    [script] 消息给出 文件:行 以及回溯
    [io] 消息给出文件名和系统给出的原因
    [interrupted] 重新运行；退出状态说明是哪个信号 (docs/reference/exit-status.md)
   *[state] 等待正在执行的操作结束 (`pto 0 status`)，或将 PLC 切换到 RUN 模式
}

lang-unknown = 未知的语言 `{ $lang }`：plcsh 支持 en、ru、zh-CN

## 数值 (core::literal)：IEC 61131-3 常数及其是否适合操作数

literal-missing = 缺少数值
literal-space = 数值 `{ $value }` 中有多余的空格
literal-duration = { $message }
literal-typed-integer = { $prefix }# 只接受整数；浮点数请写 REAL#{ $rest }
literal-unknown-prefix = 未知的类型前缀 `{ $prefix }#` (请用 B#、W#、DW#、INT#、DI#、REAL#、T# 或基数 2#、8#、16#)
literal-number-missing = 缺少数字
literal-c-notation = `{ $typed }` 是 C 语言写法；请写 { $iec } (IEC 61131-3，与 KincoBuilder 相同)
literal-unknown-radix = 基数 { $radix }# 不是 2#、8#、10#、16# 之一
literal-no-digits = { $radix }# 之后没有数字
literal-not-digit-of-base = `{ $char }` 不是 { $radix } 进制的数字
literal-too-wide = { $value } 超过 32 位 (最大 16#FFFF_FFFF)
literal-not-number = `{ $value }` 不是数字
literal-not-digit = `{ $char }` 不是 `{ $value }` 中的数字
literal-too-large = { $value } 太大：整数最大为 { $max }
value-does-not-fit = { $value } 超出 { $dtype } 的范围 ({ $min }…{ $max })
value-not-bit = { $value } 不能写入位 (请用 0/1、TRUE/FALSE、ON/OFF)
value-bit-not-real = { $value } 是位，不是 REAL
value-not-real = { $value } 超出 REAL 的范围 (32 位 IEEE 浮点数：最大 ±{ $max })
value-not-integer = { $value } 不是整数；{ $dtype } 只存整数 (要存 IEEE 浮点数，请用带 /REAL 的 32 位操作数，例如 VD100/REAL)
value-type-too-wide = { $value } 是 { $dtype } ({ $bits } 位)，不能写入 { $width } 位的操作数
value-out-of-range = { $value } 超出 { $dtype } 的范围 (0…{ $max })
value-out-of-range-group = { $value } 超出 { $bits } 位组的范围 (0…{ $max })
value-out-of-range-signed = { $value } 超出 { $dtype } 的范围 (0…{ $max })；写成 { $signed }#{ $number } 可存入其补码
value-out-of-range-group-signed = { $value } 超出 { $bits } 位组的范围 (0…{ $max })；写成 { $signed }#{ $number } 可存入其补码

## 时间、超时和频率 (core::literal)

duration-not-whole-ms = T#{ $value } 不是整数毫秒
duration-too-long = `{ $value }` 超过最长时间 { $max } µs (约 292 000 年)
duration-missing = 缺少时间 (例如 500ms、2s、250us)
duration-not-duration = `{ $value }` 不是时间 (例如 500ms、2s、250us)
duration-needs-unit = `{ $value }` 的每个数字都需要单位 (h、m、s、ms、us)，例如 { $number }ms 或 { $number }s
duration-unknown-unit = `{ $value }` 中有未知的时间单位 `{ $unit }` (请用 h、m、s、ms、us)
timeout-not-positive = `timeout={ $value }` 必须大于零 (例如 200ms)
timeout-too-short = `timeout={ $value }` 短于一微秒，即连接等待的最小单位 (例如 200ms)
timeout-too-long = `timeout={ $value }` 超过一天 ({ $max } ms)，即等待回复的最长时间
freq-not-frequency = `{ $value }` 不是频率 (例如 2kHz、500Hz)
freq-unknown-unit = `{ $value }` 中有未知的频率单位 `{ $unit }` (请用 Hz、kHz)
freq-not-positive = `{ $value }` 不是正的频率
freq-too-large = `{ $value }` 频率太大 (最大 { $max } Hz)

## 操作数表达式：数量和范围 (core::operand, k2::operand)

count-missing-bracket = 数量写法中缺少 `]` (例如 { $example })
count-not-a-count = `{ $count }` 不是数量 (例如 { $example })
count-out-of-range = 数量必须为 1…{ $max }
range-one-dots = 范围只有一个 `..`：首..尾，例如 { $example }
range-mixed = 范围需要同一存储区、同一大小的两个操作数：{ $first }..{ $last }
range-group-sizes = 位组的范围需要相同的组大小
range-backwards = 范围的结尾 { $last } 在开头 { $first } 之前
range-off-step = { $last } 不在从 { $first } 起步长为 { $step } 的位置上 (范围按操作数大小步进)
range-too-long = 范围超过 { $max } 个操作数
operand-missing = 缺少操作数
operand-unknown-type = 未知的类型 `{ $name }` (请用 BOOL、BYTE、SINT、WORD、INT、DWORD、DINT、REAL)
operand-view-width = { $operand } 宽 { $bits } 位；/{ $view } 需要 { $need } 位 (视图保持宽度：字节用 /SINT，字用 /INT，双字用 /DINT 或 /REAL)
operand-unexpected-after = { $head } 之后有多余的 `{ $rest }`

## K2 操作数 (k2::operand, k2::space；K2 手册 §3.2)

k2-area-meaning = { $area ->
    [I] 开关量输入
    [Q] 开关量输出
    [M] 内部存储位
    [V] 变量存储器
    [SM] 特殊寄存器 (系统和功能寄存器)
    [AI] 模拟量输入
    [AQ] 模拟量输出
    [T] 定时器 (当前值)
   *[C] 计数器 (当前值)
}
k2-address-too-large = `{ $operand }` 超出 K2 的所有存储区：地址最大为 { $max } (最大的存储区 V 结束于 VB{ $last })
k2-element-needs-number = { $area } 之后需要编号 ({ $area }0…{ $area }255)
k2-analog-words = 模拟量是字：{ $area }W0、{ $area }W2 …
k2-analog-needs-address = { $area }W 之后需要字节地址 (例如 { $area }W0)
k2-analog-even = 模拟量字位于偶数地址：{ $below } 或 { $above }
k2-analog-even-last = 模拟量字位于偶数地址：{ $below }
k2-needs-byte-address = { $operand } 之后需要字节地址
k2-byte-has-no-bit = 字节没有位；位应写成 { $bit }
k2-word-has-no-bit = 字没有位；位应写成 { $bit }
k2-needs-bit-or-size = { $area } 之后需要位 (`{ $area }0.0`) 或大小字母 (`{ $area }B0`、`{ $area }W0`、`{ $area }D0`)
k2-byte-needs-bit-or-size = { $area }{ $byte } 需要位 ({ $area }{ $byte }.0) 或大小 ({ $area }B{ $byte }、{ $area }W{ $byte }、{ $area }D{ $byte })
k2-bit-missing = 缺少位号 0…7
k2-bit-too-large = 位 { $bit } 不存在：位号为 0…7 (最后一位是 { $last })
k2-group-size = 位组为 K1…K8 (4 到 32 位)
k2-group-nested = { $group } 组合 I、Q、M、V 或 SM 的位；位组不能嵌套
k2-group-needs-bit = { $group } 组合位：请写 { $example } (位地址)，而不是字节或字
k2-group-area = { $group } 组合 I、Q、M、V 或 SM 的位
k2-not-operand-no-area = `{ $operand }` 不是 K2 操作数：操作数以存储区字母开头
k2-not-operand-unknown-area = `{ $operand }` 不是 K2 操作数：未知的存储区 `{ $area }`
k2-hint-did-you-mean = 是否想输入 { $suggestions }？存储区有 I Q M V SM AI AQ T C
k2-hint-no-data-blocks = K2 没有数据块：它的数据存储器是 V (VB0、VW0、VD0 …)；存储区有 I Q M V SM AI AQ T C
k2-hint-no-options = 这里的命令不接受 -选项；请给出操作数，例如 VW0、I0.0、SMB67
k2-hint-areas = 存储区有 I Q M V SM AI AQ T C，例如 VW0、I0.0、Q0.1、SMB67、T5
k2-model-has-no-area = { $model } 没有 { $area } 存储区 ({ $meaning })
k2-hint-models-with = 具有 { $area } 的型号：{ $models }
k2-past-the-end = { $operand } 超出 { $model } 上 { $area } 存储区的末尾 (最后一个{ $size ->
        [bit] 位
        [byte] 字节
        [word] 字
        [dword] 双字
        [group] 位组
       *[element] 元件
    }是 { $last })
k2-area-too-small = { $operand } 放不进 { $model } 上的 { $area } 存储区：它只有 { $bits } 位，不够一个{ $size ->
        [bit] 位
        [byte] 字节
        [word] 字
        [dword] 双字
        [group] 位组
       *[element] 元件
    }
k2-bit-and-byte-past-the-end = { $operand }：位 { $bit } 不存在 (位号为 0…7)，而且字节 { $byte } 超出 { $model } 上 { $area } 存储区的末尾 (最后一位是 { $last })
k2-hint-area-bits = { $model } 上的{ $meaning }：{ $first } … { $last }

## 通信：无回复、超时、串口 (core::link, k2::driver)

link-no-reply = 设备没有应答：unit { $unit } 在 { $timeout } 内无回复
link-no-valid-reply = unit { $unit } 在 { $timeout } 内没有发来有效的回复：{ $what }
link-closed = PLC 没有回复，而是关闭了连接
link-failed = 通讯错误
link-attempts = { $message } (尝试 { $attempts } 次)
k2-hint-no-reply = { $link ->
    [tcp] 请检查 unit id (unit=)、HOST:PORT 是否为该 PLC (K204ET 在端口 502 上应答 Modbus TCP)，以及 PLC 是否上电并可以访问 (ping)
    [rtu] 请检查 unit id (unit= 是 PLC 端口的站号)、接线 (RS485 A/B、地线)、串口设置 (baud=、parity=、stop=) 是否与 PLC 端口一致，以及串口路径
    [gateway] 请检查 unit id (unit=)、网关的地址和端口，以及网关的串口设置 (波特率、奇偶校验、停止位) 是否与 PLC 端口一致
    [rfc2217] 请检查 unit id (unit=)、串口服务器的地址和端口，以及线路设置 (baud=、parity=、stop=) 是否与 PLC 端口一致
   *[stream] 请检查 unit id 以及数据流另一端是什么
}
k2-hint-garbled = { $link ->
    [rtu] 请检查串口设置 (baud=、parity=、stop=) 是否与 PLC 端口一致、接线 (RS485 A/B、地线、长线两端的终端电阻)，以及线路上是否有其他主站或设备在通信
    [gateway] 请检查网关的串口设置 (波特率、奇偶校验、停止位) 是否与 PLC 端口一致、网关到 PLC 的接线，以及网关是否处于透明 (RTU) 模式而不是 Modbus TCP
    [rfc2217] 请检查线路设置 (baud=、parity=、stop=) 是否与 PLC 端口一致，以及串口服务器到 PLC 的接线
    [tcp] 请检查 HOST:PORT 是否使用 Modbus TCP (RTU 网关需要 rtu+tcp://)
   *[stream] 请检查数据流另一端是什么
}
k2-hint-damaged = { $link ->
    [rtu] 字节在传输中损坏；请检查串口设置 (baud=、parity=、stop=) 是否与 PLC 端口一致、接线 (RS485 A/B、地线、长线两端的终端电阻)，以及线路上是否有其他主站或设备在通信；plcsh 会重试 (retries=)
    [gateway] 字节在传输中损坏；请检查网关的串口设置 (波特率、奇偶校验、停止位) 是否与 PLC 端口一致、网关到 PLC 的接线，以及网关是否处于透明 (RTU) 模式而不是 Modbus TCP；plcsh 会重试 (retries=)
    [rfc2217] 字节在传输中损坏；请检查线路设置 (baud=、parity=、stop=) 是否与 PLC 端口一致，以及串口服务器到 PLC 的接线；plcsh 会重试 (retries=)
    [tcp] 字节在传输中损坏；请检查 HOST:PORT 是否使用 Modbus TCP (RTU 网关需要 rtu+tcp://)；plcsh 会重试 (retries=)
   *[stream] 字节在传输中损坏；请检查数据流另一端是什么；plcsh 会重试 (retries=)
}
k2-hint-closed = plcsh 会重新连接并重试 (retries=)；如果反复出现，请检查 PLC 对 Modbus TCP 连接数的限制，以及是否有其他客户端或网关接管了连接
link-cannot-connect = 无法连接到 { $addr }
link-name-not-looked-up = 无法连接到 { $addr }：{ $ms } ms 内未能解析该名称
link-hint-name-server = 请使用 IP 地址，或检查域名服务器
link-connect-timeout = 无法连接到 { $addr }：{ $ms } ms 内无应答
link-cannot-listen = 无法在 { $addr } 上监听
link-hint-listen = 请换一个端口 (0 表示任选一个空闲端口)；1024 以下的端口需要权限
link-cannot-open-port = 无法打开串口 { $port }
link-cannot-use-port = 无法使用串口 { $port }
link-hint-open-port = `plcsh ports` 列出本机的串口及其 USB 转换器；请检查名称 ({ $examples })，以及是否有其他程序 (KincoBuilder、终端程序) 占用了该串口
link-hint-open-port-group = `plcsh ports` 列出本机的串口及其 USB 转换器；请检查名称 ({ $examples })、是否有其他程序 (KincoBuilder、终端程序) 占用了该串口，以及您是否有权限打开它 (dialout 组：sudo usermod -aG dialout $USER，然后重新登录)
link-not-host-port = { $url } 中的 `{ $target }` 不是 HOST:PORT
link-hint-host-port = 请给出串口服务器的地址及其串行通道的 TCP 端口，例如 192.168.127.254:4001
link-no-address = 该名称解析不到任何地址
link-hint-server = 请检查串口服务器的地址和此串行通道的 TCP 端口、它是否处于 raw TCP 服务器模式 (+rfc2217:// 则为 RFC 2217)、是否有其他客户端占用该通道，以及防火墙是否阻挡了该端口
link-connection-closed = 连接已关闭
link-cannot-start-thread = 无法启动接受连接的线程
link-no-port-named = { $url } 没有指定串口
link-hint-port-example = 例如 { $example } (`plcsh ports` 列出本机的串口)
link-unknown-carrier = { $url } 中的 `+{ $carrier }` 不是连接串行线路的方式
link-hint-carriers = 请用 +tcp://HOST:PORT (串口服务器的 raw TCP 端口) 或 +rfc2217://HOST:PORT
link-cannot-list-ports = 无法列出串口
link-hint-list-ports-dev = ls /dev/ttyUSB* /dev/ttyACM* /dev/serial/by-id 显示内核识别到的串口
link-hint-list-ports-device-manager = 设备管理器 → 端口 (COM 和 LPT) 显示 Windows 识别到的串口
k2-no-option = K2 通信设备没有选项 `{ $key }`
k2-hint-options = 选项：word_order (high-first、low-first)、timeout、retries、agent
k2-retries-not-number = `retries={ $value }` 不是数字
k2-not-scheme = `{ $scheme }:` 不是 K2 通信方式
k2-cannot-start-runtime = 无法为接入的数据流启动运行时
k2-attached-failed = 接入的数据流出错，plcsh 无法重新打开它
k2-hint-reopen = { $hint }；恢复后，下一条命令会重新打开它
k2-reply-too-short = 读取 { $span } 的回复太短
k2-request = { $doing ->
        [reading] 读取
       *[writing] 写入
    } { $operand }{ $more ->
        [0] {""}
       *[other] {" "}及另外 { $more } 个
    } ({ $span }，FC { $fc })
k2-while = { $what }：{ $message }
k2-refused = PLC 拒绝了{ $what }：{ $exception } (Modbus 异常码 { $code })
k2-hint-exception-1 = 此 PLC 在此端口上不支持该功能码
k2-hint-exception-2 = 地址超出 PLC 的 Modbus 映射；请检查 model={ $model } 是否与 PLC 一致
k2-hint-exception-3 = PLC 拒绝了请求的大小或数值 (限制：读 1600 位或 100 个寄存器，写 800 位或 100 个寄存器)
k2-hint-exception = 请查看 PLC 的诊断信息
k2-hint-connect = 请检查 HOST:PORT 是否为该 PLC 或网关 (K204ET 在端口 502 上应答 Modbus TCP)、是否上电并可以访问 (ping)，以及防火墙是否阻挡了该端口
k2-writes-before = { $message }；在它之前的 { $sent } 个写请求已发送
link-not-parity = { $url } 中的 `parity={ $parity }` 不是奇偶校验方式
link-hint-parity = 请用 parity=none、parity=even 或 parity=odd
link-not-stop-bits = { $url } 中的 `stop={ $stop }` 不是 1 或 2
link-baud-zero = { $url } 中的 `baud=0` 不是波特率
link-not-unit-id = { $url } 中的 `unit={ $unit }` 不是 Modbus 站号
link-hint-unit-id = 站号为 1…247 (0 是广播，不会有回复)
link-cannot-use-connection = 无法使用到 { $addr } 的连接

## 命令行 (cli)

cli-about = 用于调试和投运 Kinco K2 PLC 及伺服驱动器的 shell
cli-opt-command = 执行这些命令（以 `;` 分隔）后退出
cli-opt-json = 每条命令的结果输出一个 JSON 对象
cli-opt-verbose = 显示更多：每个收发的帧（十六进制，带时间）、请求次数、采样率
cli-opt-model = 默认仿真 PLC 的型号
cli-opt-device = 添加设备：NAME=URL、NAME=PROFILE、单独的 PROFILE（以其名称打开并设为当前设备）或单独的 URL（替换 `plc`）。可重复
cli-opt-time = 仿真器时间：跟随实际时钟，或只在单步时前进
cli-opt-config = 设备配置文件（默认：PLCSH_CONFIG，否则 { $file }）。
cli-opt-state = 仿真器状态文件（备份区、断电保持范围、时钟）；默认 PLCSH_STATE，否则在用户数据目录中；`none` 不读也不写（实验、测试）。`sim serve` 只有带 --state FILE 时才保存状态
cli-opt-record = 将每条设备链路上的每一帧记录到 FILE（pcapng；`plcsh record show FILE`）
cli-opt-bench = 打开由台架文件描述的仿真设备组（设备、接线、初始值）
cli-opt-read-only = 拒绝对任何设备的任何更改（写入、指令、伺服命令）：用于检查运行中的设备
cli-opt-fleet = 在配置文件中该设备组的每台设备上同时执行 -c 的命令（或 `run` 的脚本）（docs/fleets.md）
cli-opt-jobs = 配合 --fleet：同时处理多少台设备
cli-opt-lang = 消息的语言：en、ru、zh-CN（默认：PLCSH_LANG，否则为系统语言；两者都不是其中之一时使用英语）
cli-opt-device-timeout = 配合 --fleet：设备忙碌超过此时长即报告为超时（`30s`、`2m`；0 表示不限）
cli-opt-tags = 标签文件（CSV、TOML 或 IEC VAR_GLOBAL），其中的名称可用在任何能用操作数的地方：FILE 用于当前设备，DEVICE=FILE 用于其他设备（docs/tags.md）。可重复
cli-sub-models = 列出 K2 型号目录；`models MODEL` 显示单个型号的完整信息（存储区、计数器、手册说明）
cli-sub-devices = 列出已打开的设备和设备配置文件（devices.toml），以及该文件中的问题
cli-sub-ports = 列出现有的串口及其 USB 适配器（VID:PID、产品、序列号）
cli-sub-paths = 显示每个文件所在的位置：配置文件、Lua 模块、状态、历史、快照、UMPK 闪存、记录
cli-sub-man = 输出由这些选项和 shell 命令生成的手册页（roff）：plcsh man > plcsh.1
cli-sub-completions = 输出 shell 补全脚本（bash、zsh、fish、powershell），或全部写入文件
cli-sub-sim = 向其他程序提供仿真器：`sim serve` 将仿真 K2 置于 Modbus TCP / RTU 上，并将驱动器置于 { $served ->
        [tcp] TCP 端口上（原始或 RFC 2217，可通过 com0com 等 COM 端口对访问）
       *[pty] pty 或 TCP 端口上（原始或 RFC 2217）
    }。
cli-sub-agent = PLC 端的辅助程序，它在真实的 K2 上为 plcsh 提供 SM 寄存器和指令
cli-sub-probe = 安装辅助程序之前 K2 通过 Modbus 的应答：各存储区及其最后地址、相符的型号、响应时间；只读（docs/reference/first-connection.md）
cli-sub-run = 运行 Lua 脚本：plcsh [--time stepped] [--device NAME=URL] run SCRIPT.lua [ARGS…]
cli-sub-record = 用 --record 制作的记录：`record show FILE` 输出解码后的时间线
cli-sub-replay = 在仿真器上重放记录中的请求，并报告每个不同的回复
cli-sub-lab = 教学实验：`lab new NAME`、`lab check LAB`、`lab grade LAB SUBMISSIONS…`（在沙箱中并行）
cli-sub-publish = 轮询设备或设备组的操作数并发布到 MQTT 代理（docs/fleets.md）
cli-sub-tags = 标签表（docs/tags.md）：`tags FILE` 列出名称，`tags check FILE` 检查名称，`tags export FILE --to csv|iec` 以另一种形式写出
cli-lab-new = 将一个可运行的示例实验（K2 和驱动器及接线、IL 初始文件、Lua 评分程序）写入 NAME
cli-lab-new-name = 新实验的文件夹
cli-lab-check = 检查实验：其 lab.toml、文件和初始状态，以及评分程序在参考答案上的结果
cli-lab-arg-lab = 实验文件夹（或其 lab.toml）
cli-lab-grade = 为提交的作业评分（.lua / .il 文件或其文件夹），每份在新的沙箱工作进程中运行
cli-lab-grade-submissions = 提交的文件或文件夹
cli-lab-grade-jobs = 同时运行的工作进程数（默认：每个核一个）
cli-lab-grade-junit = 同时将结果以 JUnit XML 写入 FILE
cli-lab-grade-show-output = 显示每份作业输出的内容（stdout 和 stderr，各自前 64 KiB）；`--json` 总是以 `stdout` 和 `stderr` 给出
cli-heading-usage = 用法:
cli-heading-commands = 命令
cli-heading-arguments = 参数
cli-heading-options = 选项
cli-heading-global = 全局选项
cli-help-flag = 显示帮助
cli-version-flag = 显示版本
cli-hint-shell-command = `{ $line }` 是 shell 命令：plcsh -c '{ $line }'

## 帮助和命令卡片 (shell::commands::help)：每个命令的作用、帮助界面

summary-get = 读取操作数（可用范围和 device: 前缀）
summary-set = 按顺序写入操作数；写入任何内容之前先检查整行
summary-read = 以表格读取一个范围：数值、十六进制和二进制
summary-use = 将 DEVICE 设为无前缀操作数所指的设备
summary-devices = 列出已打开的设备和设备配置文件
summary-connect = 以一个名称打开设备，或打开 devices.toml 中的设备配置文件
summary-close = 关闭设备
summary-sim = 仿真器的时钟（显示、单步并保持单步、跟随实际时间）、计数器的输入信号、断电保持范围、运行 IL 程序的 CPU、仿真设备之间的接线、仿真状态的快照、注入的故障
summary-watch = 操作数的实时表格，原地刷新直到 Ctrl-C 或 count=N；变化高亮显示
summary-trace = 随时间记录操作数（供 `plot` 使用），可选写入 CSV 文件
summary-plot = 在终端中绘制最近一次 trace，并可用 to= 输出 PNG 或 SVG 图片（脉冲输出绘制其频率）
summary-servo = Kinco 伺服工具：DS402 状态机、运动、点动、回原点、等待、单位、原始报文
summary-umpk = UMPK8/UMPK16 教学 PLC：控制器和程序信息、错误历史、时序、复位、回显、实时监视、Intel HEX 编程
summary-pls = 在脉冲通道 N 上执行 PLS 指令（0 = Q0.0，1 = Q0.1，2 = Q0.4，K209M 上 3 = Q0.5）
summary-pstop = 急停脉冲通道 N（锁存 SM201.7 …；用 set SM201.7=0 清除）
summary-pto = 启动单段脉冲串输出（写入 SMB67、SMW68、SMD72，然后 PLS），或解读其状态
summary-pwm = 在通道 N 上启动脉宽调制 PWM（写入 SMB67=16#D3、SMW68、SMW70，然后 PLS）
summary-profile = 按包络表执行多段 PTO（写入包络表、SMW168、SMB67=16#A0，然后 PLS）；`plan` 只绘制频率随时间的变化
summary-hdef = 执行 HDEF 指令：为高速计数器 HSC N 指定模式（§3.3.1）
summary-hsc = 执行 HSC 指令；带选项时先写入计数器的寄存器（然后 HDEF、HSC）；或解读其状态
summary-events = 显示至今产生的中断事件及其虚拟时间，并清空记录（`keep` 保留记录）
summary-wait = 等待设备产生中断事件（从记录中取出）；单步时间直接跳到该时刻
summary-rtc = 读取 PLC 的实时时钟、设置它，或按主机本地时间设置
summary-eeprom = 将 E2PROM 备份区（VB3648…）保存为二进制文件或从中载入；显示写入次数；设置备份区的结束位置
summary-data = 数据集：将操作数的类型化数值保存到文件，将文件与设备或另一文件比较，只载入不同之处
summary-lua = 在会话的 Lua 状态中运行 Lua（设备是全局变量：plc.VW100 = 5）
summary-agent = 检查 PLC 端的辅助程序，它通过 Modbus 提供 SM 寄存器和指令（docs/agent.md）
summary-lab = 教学实验：生成示例实验、按参考答案检查实验、为提交的作业评分（在沙箱中并行）
summary-models = K2 型号目录；单个型号的完整信息（存储区、计数器、脉冲输出、手册说明）
summary-ports = 现有的串口及其 USB 适配器（VID:PID、产品、序列号）
summary-paths = 每个文件所在的位置：配置文件、Lua 模块、状态、历史、快照
summary-help = 列出命令，或说明一个命令（其完整用法）或操作数
summary-quit = 退出 shell

help-groups-heading = 按用途分组的命令（`help all` 列出每个命令及其作用）：
help-group = { $group ->
    [io] 读写
    [devices] 设备
    [simulator] 仿真器
    [pulse] 脉冲输出
    [counters] 计数器
    [interrupts] 中断
    [plc] PLC
    [servo] 伺服、UMPK
    [scripts] 脚本、实验
   *[shell] 本 shell
}
help-footer = `help COMMAND`：命令的各种形式（`help pto`）；`help sim step`：子命令的形式。`help VW100`、`help SMB67`：操作数的含义。Tab 键补全命令、操作数和选项（`pto 0 fr` ⇥ `freq=`）。
help-all-heading = 命令（`help COMMAND` 显示其形式和子命令）：
help-all-footer = 操作数：`help VW100`、`help SMB67` 说明一个操作数；Tab 键补全操作数
help-sub-commands = 子命令：{ $list }
help-no-topic = 没有命令或操作数 `{ $topic }`
help-extra-word = help 只接受一个命令和一个子命令（其后还有 `{ $word }`）
help-no-sub-command = `{ $command }` 没有子命令 `{ $sub }`
shell-takes-nothing = { $command } 后面不接任何内容（收到 `{ $word }`）
man-shell-commands = SHELL 命令
man-shell-commands-intro = 在 plcsh> 提示符下输入，交给 -c（多条以 ; 分隔），或在 Lua 中用 plcsh.exec 执行。help 按用途分组列出命令，help COMMAND 显示命令的各种形式。

## 实验 (lab)：评分和检查的输出行、表格和结论，使用实验的 `language`

lab-new-wrote = 已写入 { $dir }（{ $files }）；用以下命令检查：plcsh lab check { $dir }
lab-grade-head = { $lab }：{ $count } 份提交的作业，{ $passed } 份通过全部评分标准
lab-duplicate-student = 警告：{ $count } 份提交的作业使用同一学生名 { $student }：{ $files }
lab-grade-columns = 学生 | 分数 | 通过 | 未通过 | 结论 | 仿真时间
lab-check-columns = 评分标准 | 分数 | 结果
lab-verdict = { $verdict ->
        [passed] 通过
       *[failed] 未通过
    }
lab-criterion-ok = 通过
lab-not-reached = 未执行到
lab-expected = 期望 { $expected }，实际为 { $got }
lab-expected-at = 期望 { $expected }，实际为 { $got }（{ $at } s 时）
lab-expected-what = { $what }：期望 { $expected }，实际为 { $got }
lab-expected-what-at = { $what }：期望 { $expected }，实际为 { $got }（{ $at } s 时）
lab-error-at = { $error }（{ $at } s 时）
lab-free-points-starter = 初始文件 { $file } 得到 { $points }/{ $max } 分（{ $criteria }）：程序不完成任务也能通过的评分标准检查不到任务要求的任何内容
lab-free-points-empty = 空程序得到 { $points }/{ $max } 分（{ $criteria }）：程序不完成任务也能通过的评分标准检查不到任务要求的任何内容
lab-points-no-criterion = { $file }：[points] "{ $key }" 不是评分程序定义的评分标准（在参考答案上）
lab-hint-did-you-mean-criterion = 是否想输入 "{ $near }"？评分程序定义了：{ $criteria }
lab-hint-no-criteria = 评分程序没有定义评分标准（lab.criterion(name, points, fn)）
lab-hint-criteria = 评分程序定义了：{ $criteria }
lab-check-passed = { $lab }：参考答案在 { $time } s 仿真时间内得到 { $points }/{ $max } 分
lab-check-failed = { $lab }：参考答案得到 { $points }/{ $max } 分（{ $verdict }）：需要修改评分程序或参考答案

## 探测 (k2::probe, cli::probe)：安装辅助程序之前 K2 的应答

probe-head = 探测 { $url }：{ $requests } 次读请求，无写入
probe-serial-answered = 有回复的串口参数：{ $settings }
probe-serial-tried = 尝试过但无回复的串口参数：{ $settings }
probe-columns = 表 | FC | 存储区 | 首地址 | 末地址 | 单元数 | 读次数 | 结果
probe-models = 相符的型号：{ $models }
probe-models-none = 相符的型号：无
probe-verdict = { $ok ->
        [ok] 正常
       *[failed] 失败
    }：{ $what }
probe-what-to-do = 处理方法：{ $todo }
probe-result-answers = 有应答
probe-result-no-end = 一直应答到下一个存储区：未找到末尾
probe-result-absent = 不存在（首地址返回异常码 02）
probe-result-refused = 地址 { $address } 返回异常码 { $code }（{ $name }）
probe-result-no-reply = 地址 { $address } 无回复
probe-no-answer = PLC 未回复对 { $table } { $address } 的读取：{ $message }
probe-refused = { $table } { $address }（{ $area }，FC { $fc }）被拒绝，异常码 { $code }（{ $name }）
probe-no-reply = { $table } { $address }（{ $area }，FC { $fc }）无回复：{ $message }
probe-todo-link-again = { $hint }；然后再次探测
probe-no-model = 目录中没有型号具有这些存储区大小（{ $sizes }）
probe-todo-no-model = 使用最接近的 model=（plcsh models 列出所有型号）连接，并在提问时附上此报告（--report FILE）：plcsh 的目录中可能没有这台 PLC
probe-models-fit = 存储区大小与 { $count } 个型号相符：{ $models }
probe-todo-same-areas = 这些型号的 Modbus 存储区相同：请将 PLC 铭牌上的型号作为 model= 给出
probe-no-mailbox = V 作为保持寄存器未能应答到寄存器 { $register }（VB{ $first } … VB{ $last }，辅助程序的默认邮箱）
probe-todo-mailbox = SM 寄存器和指令需要辅助程序在 V 区的邮箱：请选择 PLC 有应答的基址（plcsh agent il --base VB…）
probe-timed-failed = 对 { $what } 的 { $reads } 次计时读取中有 { $failed } 次无回复或返回异常
probe-todo-link-slow = { $hint }；丢失回复的线路会使每条命令变慢（plcsh 会重试）
probe-timed = { $what } 读取 { $reads } 次：p50 { $p50 } ms，p99 { $p99 } ms
probe-todo-exception-01 = 该端口不接受这个读功能码：请确认它是 PLC 的 Modbus 口（在 KincoBuilder 中将 PORT1/PORT2 设为 Modbus RTU 从站，或 K204ET 上的 Modbus TCP），而不是编程口或自由协议口
probe-todo-exception-04 = PLC 报告设备故障：请检查其错误指示灯和 KincoBuilder 中的诊断信息，然后再次探测
probe-todo-exception-06 = PLC 忙：请再次探测；如果一直忙，说明有其他事情占用它（另一个主站、程序下载）
probe-todo-gateway = 网关代替 PLC 作了应答：请检查网关到 PLC 的路由（站号、串口参数、接线）
probe-todo-attach = 提问时请附上此报告：plcsh probe … --report FILE

## REPL (shell::repl)：开头几行
repl-banner = plcsh { $version } — `help` 列出命令，`quit` 退出。
repl-devices = 设备：{ $devices }
repl-device-simulated = { $name }（{ $model } 仿真）
repl-no-line-editor = 无法启动行编辑器：{ $error }
repl-input-error = 输入错误：{ $error }

## 仿真状态的快照 (shell::commands::snapshot)
snapshot-list-sandboxed = `sim snapshots` 列出用户数据目录：在沙箱运行中不可用
snapshot-hint-sandboxed = 沙箱运行将快照作为文件保存在其写入目录下
snapshot-none = 没有保存的快照（sim snapshot save NAME）
snapshot-columns = 快照 | 文件
snapshot-one-name = `sim snapshot { $verb }` 只接受一个名称或文件，而不是 { $count } 个词
snapshot-hint-quotes = 含空格的路径请加引号：sim snapshot { $verb } { $path }
snapshot-needs-verb = `sim snapshot` 需要 save 或 restore 以及一个名称：{ $usage }
snapshot-saved = 已将 { $devices } 在 { $time } 时的状态保存到 { $file }
snapshot-restored = 已将 { $devices } 恢复到 { $time } 时的状态
snapshot-unknown = 未知的 `sim snapshot { $verb }`

## Shell (shell)

shell-unknown-command = 未知的命令 `{ $name }`
shell-hint-did-you-mean = 是否想输入 `{ $name }`？`help` 列出所有命令
shell-hint-help = `help` 列出所有命令
shell-hint-subcommand = 是否想输入 `{ $command } { $near }`？`help { $command }` 显示其用法

## Servo parameter sets (servo::params, servo params)

servo-params-cannot-read = 无法读取 { $file }
servo-params-bad-file = { $file } 不是参数集文件：{ $reason }
servo-params-other-drive = { $file } 保存的是 { $kind } 驱动器的参数，而此驱动器是 { $expected }：参数集只能载入读出它的同类型驱动器
servo-params-unknown-object = { $file } 把参数 { $name } 写为 { $object }/{ $dtype }，此驱动器的对象字典中没有这个参数：文件来自其他类型的驱动器或被修改过
servo-params-duplicate = { $file } 两次列出参数 { $name }
servo-params-out-of-range = { $file }：{ $value } 超出参数 { $name } 的范围
servo-params-unknown-group = 未知的参数组 `{ $group }`；参数组有 { $groups }
servo-params-read-back = 写入 { $value } 后读回 { $name }（{ $object }）为 { $back }；载入在此停止
servo-params-stopped = 载入在 { $name }（{ $object }）处停止，此前已写入 { $written } 次：{ $reason }
servo-params-usage = 用法：servo params save FILE [group…] | servo params diff FILE [FILE2] | servo params diff --with DRIVE | servo params load FILE [--store]
servo-params-saved = 已将 { $count } 个参数保存到 { $file }；拒绝或不存在：{ $refused }
servo-params-same = 没有差异
servo-params-loaded = 已写入 { $written } 个参数，均已读回；未改变：{ $unchanged }
servo-params-loaded-stored = 已写入 { $written } 个参数，均已读回；未改变：{ $unchanged }；参数已保存到驱动器存储器（2FF0.01 = 1）

## 仿真器的注入故障，K2、UMPK 和 FX 仿真器共用（core::sim_faults、k2::sim::control）

sim-fault-describe = 故障 { $id }：{ $what }，从 { $from } s 起直到清除
sim-fault-describe-until = 故障 { $id }：{ $what }，从 { $from } s 到 { $until } s
sim-control-words-hint = 控制字：{ $words }
sim-not-level = `{ $value }` 不是电平（1、0、on、off）
sim-not-option-here = `{ $word }` 在此不是选项（for=DURATION）
sim-word-takes-nothing = `{ $word }` 后面不接任何内容（得到 `{ $rest }`）
sim-no-faults = 没有注入的故障
sim-no-fault-acted = 没有注入的故障起作用
sim-fault-acted = { $seconds } s：故障 { $id }（{ $name }）起作用
sim-not-fault-id = `{ $text }` 不是故障编号
sim-no-such-fault = 没有故障 { $id }
sim-no-such-fault-hint = `faults` 列出它们
sim-faults-cleared = 已清除 { $n } 个故障
sim-stuck-needs-input = fault stuck 需要一个输入和电平：stuck IN=1
sim-stuck-shape = `{ $spec }`：写作 stuck { $spec }=1 或 stuck { $spec }=0
sim-not-fault-here = `{ $kind }` 在此不是故障（no-reply、stuck）
sim-which-fault = 哪个故障？fault no-reply | fault stuck IN=1

## 文件（core::durable）

file-cannot-create = 无法创建 { $path }
file-cannot-open = 无法打开 { $path }
file-cannot-write = 无法写入 { $path }

## 设备配置与设备组（profile、profile::fleet）

profile-cannot-read = 无法读取：{ $error }
profile-file-not-loaded = { $error }（未装入此文件中的任何配置）
profile-skipped = 已跳过配置 `{ $name }`：{ $reason }
profile-unknown = `{ $name }` 既不是设备 URL 也不是配置
profile-unknown-define-hint = 给出 URL（sim:MODEL、tcp://HOST:PORT …），或在 { $file } 中定义 { $section }
profile-unknown-list-hint = { $file } 中的配置：{ $list }
profile-name-letters = 配置名只能由拉丁字母 A-Z a-z、数字、_ 和 - 组成（它会成为设备名，写在操作数之前：press1:VW0）
profile-url-not-string = `url` 必须是字符串
profile-url-missing = 缺少 `url`（例如 { $example }）
profile-read-only-bool = `read_only` 必须是 true 或 false
profile-allow-list = `allow` 必须是操作数列表，例如 { $example }
profile-option-scalar = 选项 `{ $key }` 必须是字符串、数字或布尔值
profile-options-table = `options` 必须是表
profile-key-scalar = `{ $key }` 必须是字符串、数字或布尔值
profile-unknown-scheme = { $url } 中的设备方案 `{ $scheme }:` 未知
profile-known-schemes-hint = 已知方案：{ $list }
profile-allow-item = 配置 `{ $name }`（{ $origin }）：allow 项 `{ $item }`：{ $reason }
profile-allow-item-hint = allow 项是此设备的操作数或范围，例如 "VW100..VW120"
profile-read-only-refused = { $what ->
    [none] 写入被拒绝：配置 `{ $profile }` 为 read_only（{ $origin }）
   *[other] { $what } 被拒绝（它会改变 { $name }）：配置 `{ $profile }` 为 read_only（{ $origin }）
}
profile-read-only-refused-hint = 可以读取；若要写入，从配置中删除 `read_only = true`
profile-allow-refused = { $what ->
    [none] 写入被拒绝：{ $name } 不在配置 `{ $profile }` 的 allow 列表 [{ $list }] 中（{ $origin }）
   *[other] { $what } 被拒绝（它会改变 { $name }）：{ $name } 不在配置 `{ $profile }` 的 allow 列表 [{ $list }] 中（{ $origin }）
}
profile-allow-refused-hint = 只允许写入列出的操作数，且大小相同
profile-summary-read-only = 只读
profile-summary-allow = allow { $list }
fleet-needs-range = 按 URL 定义的设备组需要在 url 中有一个范围，例如 { $example }
fleet-unclosed-brace = url 中的 `{"{"}` 没有对应的 `{"}"}`
fleet-one-range = 设备组的 url 中只允许一个 { $form } 范围
fleet-not-range = `{ $range }` 不是范围（写作 { $form }）
fleet-not-number = `{ $range }` 中的 `{ $text }` 不是数字
fleet-backwards = 范围 { $range } 是倒序的
fleet-too-many = 范围 { $range } 包含 { $n } 台设备；一个设备组最多 { $max } 台
fleet-devices-or-url = 给出 `devices` 或 `url`，不能同时给出
fleet-needs-devices = 设备组需要 `{ $devices }` 或 `{ $url }`
fleet-devices-list = `devices` 必须是配置名或 URL 的列表
fleet-devices-empty = `devices` 为空
fleet-devices-rules = `{ $key }`：`devices` 设备组的规则取自各个配置
fleet-listed-twice = `{ $name }` 列出了两次
fleet-lists-unknown = 设备组 `{ $name }`（{ $origin }）列出了 `{ $profile }`，但它不是已装入的配置
fleet-unknown = 没有名为 `{ $name }` 的设备组
fleet-unknown-define-hint = 在 { $file } 中用 { $devices } 或 { $url } 定义 { $section }
fleet-unknown-list-hint = { $file } 中的设备组：{ $list }
fleet-name-letters = 设备组名只能由拉丁字母 A-Z a-z、数字、_ 和 - 组成
fleet-skipped = 已跳过设备组 `{ $name }`：{ $reason }

## 设备 URL 与文件（schemes、paths、pending）

schemes-known-hint = 已知方案：sim:MODEL、tcp://HOST:PORT、rtu:PORT、kinco:PORT?id=1、sim-servo:?id=1、fx:PORT、fxlink:PORT、sim-fx:FX2N、umpk:PORT、sim-umpk:UMPK16（PORT：COM3、/dev/ttyUSB0；串口设备服务器：rtu+tcp://HOST:PORT、kinco+rfc2217://HOST:PORT、…）
pending-not-connected = 暂时无法读取 `{ $operand }`：设备未连接
pending-not-connected-hint = 检查连接（`plcsh ports`、电缆、电源）；下一条命令会再次尝试连接

## 设备 URL、文本文件、选项（core::url、core::encoding、core::device、core::signal）

url-not-url = `{ $text }` 不是设备 URL
url-not-url-hint = 使用 sim:MODEL、tcp://HOST:PORT?unit=1、{ $rtu }、rtu+tcp://HOST:PORT、{ $kinco } 或 sim-servo:?id=1
url-param-too-large = { $url } 中的 `{ $param }` 太大：最大 { $max }
url-param-not-number = { $url } 中的 `{ $param }` 不是整数
url-unknown-param = { $url } 中有未知参数 `{ $key }`
url-known-params-hint = 已知参数：{ $list }
encoding-utf16-kind = { $kind ->
    [bom-le] UTF-16 文本（字节顺序标记 FF FE）
    [bom-be] UTF-16 文本（字节顺序标记 FE FF）
    [le] 无字节顺序标记的 UTF-16 小端文本（每个 ASCII 字符后有一个 NUL）
   *[be] 无字节顺序标记的 UTF-16 大端文本（每个 ASCII 字符前有一个 NUL）
}
encoding-utf16-odd = { $what } 在第 { $byte } 字节处于字符中间结束（请把文件保存为 UTF-8）
encoding-utf16-surrogate = { $what }：第 { $byte } 字节处 UTF-16 无效：孤立代理项 { $surrogate }（请把文件保存为 UTF-8）
device-no-option = { $family } 设备没有选项 `{ $key }`
signal-freq-positive = 脉冲频率 { $freq } Hz 必须为正
