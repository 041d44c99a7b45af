# plcsh messages (zh-CN): shell — 外壳与命令行的命令和选项. Same ids and arguments in en, ru and zh-CN
# (tests/messages.rs).

## 命令行本身的错误 (cli::clap_error)：clap 发现的问题，按 clap 的格式

cli-error = 错误：{ $message }
cli-error-unknown-argument = 未知的参数 '{ $arg }'
cli-error-unknown-subcommand = 未知的子命令 '{ $subcommand }'
cli-error-invalid-value = '{ $arg }' 的值 '{ $value }' 无效
cli-error-value-missing = '{ $arg }' 需要一个值，但未提供
cli-error-possible-values = [可选值：{ $values }]
cli-error-value-refused = '{ $arg }' 的值 '{ $value }' 无效：{ $reason }
cli-error-no-equals = 给 '{ $arg }' 赋值时需要使用等号
cli-error-too-many-values = '{ $arg }' 有多余的值 '{ $value }'：不需要更多的值
cli-error-too-few-values = '{ $arg }' 至少需要 { $min } 个值，只提供了 { $given } 个
cli-error-wrong-number-of-values = '{ $arg }' 需要 { $expected } 个值，但提供了 { $given } 个
cli-error-missing-arguments = 未提供以下 { $count } 个必需的参数：
cli-error-missing-subcommand = '{ $command }' 需要一个子命令，但未提供
cli-error-subcommands = [子命令：{ $values }]
cli-error-used-twice = 参数 '{ $arg }' 不能多次使用
cli-error-conflict = 参数 '{ $arg }' 不能与 { $other } 同时使用
cli-error-conflict-others = 参数 '{ $arg }' 不能与已给出的其他一个或多个参数同时使用
cli-error-invalid-utf8 = 一个或多个参数中含有无效的 UTF-8
cli-error-similar-subcommand = 提示：{ $count ->
   *[other] 存在相似的子命令
}：{ $names }
cli-error-similar-argument = 提示：{ $count ->
   *[other] 存在相似的参数
}：{ $names }
cli-error-similar-value = 提示：{ $count ->
   *[other] 存在相似的值
}：{ $names }
cli-error-pass-as-value = 提示：要把 '{ $arg }' 作为值传递，请写 '{ $example }'
cli-error-remove-dashes = 提示：子命令 '{ $subcommand }' 存在；要使用它，请去掉它前面的 '--'
cli-error-tip = 提示：{ $tip }
cli-error-more = 更多信息请尝试 '{ $help }'。
cli-no-such-subcommand = plcsh：`{ $command }` 没有子命令 `{ $subcommand }`；它的子命令：{ $subcommands }
cli-help-describes-each = `{ $command } --help` 说明每一个子命令

## 子命令本身的子命令和选项 (`plcsh sim serve --help`; cli::localise)

cli-default = [默认：{ $value }]
cli-possible-values = [可选值：{ $values }]
cli-help-subcommand = 显示此帮助或给定子命令的帮助
cli-models-name = 一个型号（唯一的前缀即可：K209EA）
cli-completions-shell = 要输出补全脚本的 shell
cli-completions-write = 将所有脚本写入 DIR（plcsh.bash、_plcsh、plcsh.fish、_plcsh.ps1）
cli-sim-serve = 通过 Modbus TCP、伪终端上的 Modbus RTU 和/或 TCP 上的 RTU 提供仿真器
cli-sim-serve-tcp = 在 ADDR 上提供 Modbus TCP（`127.0.0.1:5020`、`5020`，`0` 表示空闲端口；未给出主机时只监听本机回环地址）
cli-sim-serve-rtu-pty = 在新的伪终端上提供 Modbus RTU，并在 LINK 处创建指向其设备的符号链接
cli-sim-serve-rtu-tcp = 在 ADDR 上通过 TCP 传送 Modbus RTU 帧（与串口转以太网网关的传送方式相同）
cli-sim-serve-unit = K2 应答的 Modbus 站号（从站地址）；发给其他站号的请求不予应答
cli-sim-serve-agent = 运行 PLC 端的辅助程序 (lib/k2_agent.il)，其邮箱位于此 V 地址
cli-sim-serve-program = 在提供的 K2 中运行此 IL 程序 (docs/il.md)；加载错误会停止服务器
cli-sim-serve-servo-pty = 在新的伪终端上提供仿真的步科伺服驱动器；LINK 成为指向它的符号链接
cli-sim-serve-servo-tcp = 像串口设备服务器那样，在 TCP 端口上提供仿真的步科伺服驱动器 (kinco+tcp://ADDR)
cli-sim-serve-servo-control = 所提供驱动器线路的控制通道位于 PATH（默认：--servo-pty 链接旁的 LINK.ctl）；客户端用 `control=PATH` 指定它（例如 `kinco+tcp://ADDR?control=PATH`）
cli-sim-serve-servo-id = 伺服线路上的驱动器 ID（多台驱动器共用一条线路）
cli-sim-serve-servo-loop = RS232 回环模式：在回复之前回显每个请求（以 echo=1 连接）
cli-sim-serve-servo-baud = 线路时序：回复按此波特率下的帧传输时间发送（每字节 10 位）
cli-sim-serve-servo-latency = 线路时序：驱动器应答前的处理时间（例如 1ms、0）
cli-sim-serve-servo-instant = 立即应答，而不按线路速度应答（基准测试、CI）
cli-sim-serve-servo-strict = 拒绝大小代码与对象不符的写入（中止代码 0x06070010）
cli-sim-serve-fx-pty = 在新的伪终端上提供仿真 FX PLC 的编程口（符号链接位于 LINK）
cli-sim-serve-fx-tcp = 在 TCP 端口上提供仿真 FX PLC 的编程口 (fx+tcp://ADDR)
cli-sim-serve-fx-link-pty = 在另一个伪终端上提供同一台 FX PLC 的计算机链接（格式 1，带和校验）
cli-sim-serve-fx-link-tcp = 在 TCP 端口上提供同一台 FX PLC 的计算机链接 (fxlink+tcp://ADDR)
cli-sim-serve-fx-model = 仿真 FX PLC 的型号（FX1S、FX1N、FX2N、FX3U；FX2NC 和 FX3UC 即 FX2N 和 FX3U）
cli-sim-serve-fx-station = 计算机链接的站号（0–31）
cli-sim-serve-fx-program = 仿真 FX PLC 运行的 FX 指令表（docs/il.md，“The FX family”）
cli-sim-serve-umpk-pty = 在新的伪终端上提供仿真的 UMPK 教学 PLC；LINK 成为指向它的符号链接
cli-sim-serve-umpk-tcp = 在 TCP 端口上提供仿真的 UMPK 教学 PLC (umpk+tcp://ADDR)
cli-sim-serve-umpk-model = 仿真 UMPK 的型号（UMPK8 或 UMPK16）
cli-sim-serve-umpk-status-bits = W、H、R、E、P、T 在 UMPK 状态字中的位号
cli-sim-serve-umpk-flash-fail = 让仿真 UMPK 的闪存写入在这一 64 字节页上失败（编程得到 `W`）：UMPK8 为 0–31，UMPK16 为 0–47
cli-sim-serve-umpk-state = 仿真 UMPK 保存其闪存、程序信息和错误历史的位置（默认：在用户数据目录中按型号和线路各一个文件；`none` 不保存）
cli-sim-serve-umpk-program = 仿真 UMPK 每 10 ms 周期运行的 IL 实验程序（docs/il.md，“The UMPK family”）
cli-sim-serve-fx-control = 所提供 FX PLC 的控制通道位于 PATH（默认：--fx-pty 链接旁的 LINK.ctl）：在客户端使用其端口时切换 X 输入、使线路静默、使输入卡住
cli-sim-serve-umpk-control = 所提供 UMPK 的控制通道位于 PATH（默认：--umpk-pty 链接旁的 LINK.ctl）：在实验软件使用线路时设置输入、方波和故障
cli-sim-serve-k2-control = 所提供 K2 的控制通道位于 PATH（默认：--rtu-pty 链接旁的 LINK.ctl）：在客户端轮询时添加、列出和清除故障，读取故障事件日志（`plcsh sim control PATH …`，或在客户端 URL 中写 `control=PATH`）
cli-sim-serve-fault = 向所提供的 K2 注入故障，例如 `--fault "no-reply on VW100 after=2s times=1"`（可重复；见 `help sim`）
cli-sim-serve-max-connections = 同时服务的网络连接数（每种传输方式）；超出的连接在接受时即关闭
cli-sim-serve-idle-timeout = 关闭在这段时间内没有发送任何数据的网络连接（`300s`、`2m`、`500ms`）
cli-sim-serve-strict-unit = 在 Modbus TCP 上只应答 --unit 站号（默认站号 0xFF 也指本设备，与 libmodbus 相同）
cli-sim-serve-fleet = 在 N 个 TCP 端口上提供 N 台仿真 K2，各有自己的存储器（配合 --tcp：端口 0 为每台分配空闲端口，端口 P 依次为 P、P+1、…）；就绪行在 `fleet` 下列出它们 (docs/fleets.md)
cli-sim-serve-rfc2217 = 串口类选项的 TCP 端口（--rtu-tcp、--servo-tcp、--fx-tcp、--fx-link-tcp、--umpk-tcp）使用 RFC 2217（Telnet COM-PORT-OPTION）而不是原始 TCP：用于 FAMILY+rfc2217:// 和虚拟 COM 端口驱动程序
cli-sim-control = 向所提供仿真器的控制通道发送一行（故障、事件）并输出回复
cli-sim-control-path = 控制通道（服务器就绪行中的 `k2_control`、`umpk_control` 或 `servo_control`）
cli-sim-control-words = 控制行，例如 `fault no-reply times=2`、`faults`、`events`、`fault clear`
cli-agent-il = 输出供 KincoBuilder 使用的辅助程序（K2 指令表）
cli-agent-il-model = PLC 的型号：辅助程序只运行该型号具有的脉冲输出、计数器和计数器模式（默认：默认的仿真型号）
cli-agent-il-base = 邮箱起始地址：E2PROM 区 (VB3648) 以下的偶数 V 字节地址
cli-agent-check = PLC 中辅助程序的自检：签名、版本、扫描速率、系统位、时钟和一次被拒绝的 PLS；只写邮箱，并恢复它用过的 SM 字节 (docs/agent.md)
cli-agent-check-url = PLC：tcp://HOST:PORT?agent=VB3400、rtu:PORT?… 或配置名称（URL 中没有时为 agent=VB3400）
cli-probe-url = PLC：tcp://HOST:PORT、rtu:PORT?baud=…、rtu+tcp://HOST:PORT 或配置名称
cli-probe-report = 同时将结果以 Markdown 报告写入 FILE
cli-probe-reads = 为测量响应时间 (p50, p99) 计时的读取次数
cli-probe-scan-serial = 串行线路无应答时，尝试常用设置（9600…115200 波特，无校验、偶校验或奇校验），并说明哪一种得到了应答
cli-run-sandbox = 运行他人编写的脚本：不允许 os.execute、io.popen、os.remove/rename/exit、C 库和 debug 库；只能在 --write-dir 下写文件
cli-run-write-dir = 配合 --sandbox：脚本可以写文件的目录（没有此选项则不能写）
cli-run-fleet = 在该设备组的每台设备上同时运行脚本，每台使用各自的 Lua 状态 (docs/fleets.md)
cli-run-report = 写调试报告：此 HTML 文件及其旁边的 JSON 副本 (docs/commissioning.md)。调试运行器在其中写入检查清单；其他脚本写入设备和它所做每次写入的日志
cli-run-script = Lua 脚本
cli-run-args = 脚本的参数（`arg[1]`… 和 `...`）：脚本之后的所有内容，即使看起来像 plcsh 的标志。给 plcsh 的标志写在脚本之前
cli-record-show = 将记录输出为解码后的时间线（K2 操作数名称、伺服对象名称）；带 --json 时每帧一个对象
cli-record-file = 由 --record 写入的文件
cli-replay-sim-model = 仿真此 K2 型号，而不是每条记录链路所指明的型号
cli-replay-snapshot = 从此快照启动仿真 K2（文件，或用 `sim snapshot save` 保存的名称）
cli-replay-agent = 运行 PLC 端的辅助程序 (lib/k2_agent.il)，其邮箱位于此 V 地址。没有此选项时，若记录显示读取了辅助程序的状态块，则运行辅助程序
cli-publish-broker = 代理：mqtt://HOST:PORT，TLS 用 mqtts://HOST:PORT（默认：配置文件 [mqtt] 中的 `url`）
cli-publish-fleet = 发布该设备组的每个成员（默认：当前设备）
cli-publish-every = 每台设备的读取间隔
cli-publish-qos = 值的 MQTT 服务质量：0（至多一次）或 1（至少一次）
cli-publish-on-change = 只在值发生变化（超过 --deadband）时发布；否则每次轮询都发布
cli-publish-deadband = 配合 --on-change：发布的最小变化量（以操作数的单位计）
cli-publish-buffer = 等待发送给代理的读数上限：代理离线时，超出部分中最旧的被丢弃；代理在线但 plcsh 来不及发送时，主题的最新值替换队列中的值（两种情况都计数）
cli-publish-mqtt-version = MQTT 协议版本
cli-publish-count = 每台设备轮询这么多次后停止（默认：直到 Ctrl-C）
cli-publish-client-id = MQTT 客户端 ID（默认：plcsh-GROUP-PID）
cli-publish-accept-writes = 接受代理在 plcsh/GROUP/DEVICE/set 上发来的写入，只写设备配置允许列表中的操作数（回复在 plcsh/GROUP/DEVICE/reply）；只读配置从不接受写入
cli-publish-shard = 只发布设备组的这一部分（N 个发布者中的第 K 个；默认：配置文件 [mqtt] 中的 `shard`）
cli-publish-operands = 要发布的操作数（允许范围：VW100..VW110）
cli-tags-file = 要列出的标签文件（CSV、TOML `[tags]` 或 IEC `VAR_GLOBAL` 声明）
cli-tags-model = 地址所属操作数的型号（K2、FX 或 UMPK；默认：仿真 K2 的型号）
cli-tags-format = 按此格式读取文件，而不是根据文件名和内容判断
cli-tags-check = 检查标签文件：每个问题一行，带 file:line:column；有任何问题时退出状态为 1
cli-tags-export = 将标签文件以另一种形式（CSV 或 IEC VAR_GLOBAL）写到标准输出或 --output
cli-tags-export-to = 要写出的形式
cli-tags-export-output = 写到此处而不是标准输出（整个替换，原子操作）

## 标准错误输出上的进度行和说明 (shell, cli, signals)

shell-requests-on-wire = { $command }：线路上发送了 { $count } 个请求
shell-samples = { $count } 个采样
shell-sample-report = { $command }：时钟时间 { $clock } 秒内 { $samples } 个采样（{ $clock_rate } Hz；要求 { $asked_rate } Hz），实际时间 { $wall } 秒（{ $wall_rate } Hz），{ $requests } 个请求{ $interrupted ->
    [yes] ，已中断
   *[no] { "" }
}
shell-umpk-programming = 编程 { $bar } 记录 { $record }/{ $records }
shell-not-connected-yet = plcsh：{ $device }：{ $reason } — 未连接；下一条命令会重试
shell-state-taken = plcsh：警告：{ $reason }：此 shell 的 plc 从空白状态开始，不保存任何内容（与 --state none 相同）；要保存自己的状态，请用 --state FILE 启动
shell-stop-overdue = plcsh：已停止：停止操作未在 { $seconds } 秒内完成（中止处理程序仍在运行？）

## shell 命令行的用法错误 (shell::lex, shell::commands::forms)

shell-hint-close-quote = 请闭合引号；在双引号内用 \" 表示引号、用 \\ 表示反斜杠，或改用单引号
shell-hint-one-file = 只能一个文件：{ $line }
shell-hint-quote-path = 带空格的路径要放在引号中：{ $line }
shell-one-file-only = { $form } 只接受一个文件，而不是 { $count } 个词（`{ $words }`）
shell-cli-only-run = `run` 是命令行命令：plcsh run SCRIPT.lua [ARGS…]；在 shell 中用 lua dofile("SCRIPT.lua")
shell-cli-only-replay = `replay` 是命令行命令：plcsh replay FILE.pcapng（它自己创建仿真器）
shell-cli-only-record = `record` 是命令行命令：plcsh record show FILE.pcapng；要记录本次会话，请用 --record FILE 启动 plcsh
shell-cli-only-completions = `completions` 是命令行命令：plcsh completions bash|zsh|fish|powershell
shell-cli-only-serve = 提供仿真器是命令行命令：plcsh sim serve --tcp 5020 …
shell-no-options = `{ $forms }` 不接受选项（给出了 `{ $key }=`）
shell-hint-the-form = 命令格式为 { $forms }；`help { $command }` 显示所有格式
shell-hint-nothing-after-files = { $files ->
   *[other] 文件
}之后不能再有内容；`{ $help }` 显示所有格式
shell-hint-quote-name = 带空格的路径或名称要放在引号中：{ $line }
shell-unexpected-after = `{ $typed }` 之后出现意外的 `{ $extra }`：命令格式为 { $forms }
shell-hint-number-and-unit = 数值和单位要写成一个词：{ $line }
shell-no-arguments = 意外的 `{ $extra }`：`{ $command }` 不接受参数
shell-hint-nothing-after = 其后不能再有内容；`{ $help }` 显示所有格式

## 命令的操作数、选项和设备 (shell::commands::io, shell::sample, session, guard)

shell-needs-operand = { $command } 至少需要一个操作数
shell-set-needs-items = set 需要 OPERAND=VALUE 项
shell-set-not-item = `{ $item }` 不是 OPERAND=VALUE
shell-set-st-assignment = `:=` 是 ST 语言的赋值；plcsh 的写法是 `{ $operand }={ $value }`
shell-set-commas = 多个写入之间用逗号分隔：`set { $line }`
shell-option-positive = { $key } 必须大于零
shell-name-an-operand = 请至少给出一个操作数
shell-count-not-number = count={ $value } 不是数字
shell-count-at-least-one = count 至少为 1
shell-unknown-option = 未知的选项 `{ $key }`
shell-hint-options = 选项：{ $options }；{ $usage }
shell-not-traced = `{ $name }` 不在上一次 trace 中
shell-hint-traced = 已记录：{ $names }
session-bad-device-name = `{ $name }` 不是设备名称：只能使用拉丁字母 A-Z a-z、数字、_ 和 -
session-hint-device-name = 例如 connect press1 sim:K209EA-50DX（名称写在操作数之前：press1:VW0）
session-sandbox-real-profile = `{ $url }` 是真实设备的配置：沙箱运行只能打开仿真设备
session-sandbox-not-url = `{ $url }` 不是设备 URL：沙箱运行只能通过 URL 打开仿真设备
session-from-profile = 来自配置 `{ $profile }`（{ $origin }）
session-no-device-named = 没有名为 `{ $name }` 的设备
session-hint-none-open = 没有打开任何设备；请用 --device NAME=URL 添加
session-hint-open-devices = 已打开的设备：{ $names }
session-none-open = 没有打开任何设备
session-hint-add-device = 请用 --device NAME=URL 或 `connect NAME URL` 添加
guard-read-only-action = 拒绝 { $action }（它会更改 { $name }）：会话为只读 (--read-only)
guard-read-only-write = 拒绝写入：会话为只读 (--read-only)
guard-hint-read-only = 可以读取；要写入，请不带 --read-only 启动 plcsh
cli-config-missing = --config { $file }：没有这个文件
cli-hint-config-missing = 请给出已有的 devices.toml，或去掉 --config 以使用默认文件
cli-fleet-needs-work = --fleet 在设备组的每台设备上执行 -c COMMANDS 或 run SCRIPT.lua
cli-hint-fleet-needs-work = 例如 plcsh -f { $fleet } -c 'get VW100'，或 plcsh run --fleet { $fleet } check.lua
shell-prompt-not-connected = 未连接
shell-complete-operating-mode = 工作模式
shell-complete-open-device = 已打开的设备（{ $profile }）；connect NAME URL 会替换它

## K2 命令的通道、选项和事件 (shell::commands::k2cmd, events, trend, models, …)

shell-not-a-channel = `{ $num }` 不是{ $what ->
    [counter] 计数器
   *[pulse] 脉冲输出通道
}编号（0…{ $max }）
shell-status-needs-channel = status 格式需要{ $what ->
    [counter] 计数器
   *[pulse] 脉冲输出通道
}编号，例如 { $example }
shell-unexpected = 意外的 `{ $extra }`
shell-not-a-k2 = { $name } 不是 K2 PLC
shell-simulator-only = { $command } 是仿真器控制命令；{ $name } 不是仿真设备
shell-unknown-key = 未知的选项 `{ $key }=`
shell-hint-option-near = 是否想输入 `{ $near }=`？选项：{ $options }；用法：{ $usage }
shell-hint-option-usage = 选项：{ $options }；用法：{ $usage }
shell-cannot-write = 无法写入 { $file }：{ $reason }
shell-plot-not-a-size = { $key }={ $value } 不是有效的尺寸（2…1000 个字符）
shell-plot-nothing = 还没有可绘制的数据
shell-hint-plot-nothing = 请先记录，例如 trace SMD72 every=10ms for=2s
shell-no-events = 没有事件
shell-wait-needs-event = wait 需要 `event N`
shell-wait-event-number = 事件 { $number } { $name }（{ $what }）发生于 { $at }，等待了 { $waited }
shell-wait-event = { $name }（{ $what }）发生于 { $at }，等待了 { $waited }
shell-wait-interrupted = 等待 { $event } 被中断
shell-wait-timeout = { $timeout } 内没有 { $event }
shell-hint-wait-timeout = `events keep` 列出已到达的事件；`pto N status` / `hsc N status` 显示是否有任何东西在运行
shell-ports-no-arguments = ports 不接受参数（给出了 `{ $extra }`）
shell-no-ports = 未找到串口（请插入 USB 适配器，然后再次运行 `ports`）
shell-lua-cannot-run = 此处不能运行 Lua
shell-hint-lua-nested = 不允许在正在运行的 Lua 代码块 (plcsh.exec) 中使用 `lua` 行；请直接调用 Lua
shell-hint-fault-served = 所提供的 K2 通过其控制通道接受故障：用 control=PATH 打开它（服务器的就绪行给出了它）
shell-agent-il-cli = `agent il` 是命令行命令：它输出供 KincoBuilder 使用的辅助程序
shell-hint-agent-il-cli = plcsh agent il > k2_agent.il（见 plcsh agent il --help）
shell-agent-simulator = 仿真器：直接访问 SM 寄存器和指令（不需要辅助程序）
shell-wire-needs-ends = sim wire 需要 FROM -> TO
shell-nothing-wired = 没有接线
shell-unwire-needs-terminal = sim unwire 需要一个端子或 `all`
shell-watch-cannot-write = 无法写出 watch 的输出：{ $reason }
shell-models-columns = 型号 | DI/DO/DIO | AI/AO | HSC | 脉冲输出 | 手册说明
shell-models-footer = `models MODEL` 显示单个型号的完整信息（存储区、计数器、手册说明）
shell-models-no-pulses = 无（继电器输出）
shell-models-pto = { $output }，最高 { $khz } kHz

## 脉冲输出：PLS、PTO、PWM 和包络 (shell::commands::pulse; K2 手册 §3.4)

shell-pulse-channel-missing = 缺少脉冲输出通道号：{ $usage }
shell-pulse-one-channel = { $command } 只接受一个通道号
shell-pulse-busy-strict = { $busy }：{ $by } { $channel } 会替换它；未写入任何内容
shell-hint-pulse-busy = 等待其结束 (pto { $channel } status)、停止它 (pstop { $channel })，或去掉 `strict` 以替换它
shell-pulse-busy-replaced = { $busy }；{ $by } { $channel } 已替换它（加上 `strict` 则改为拒绝）
shell-freq-or-cycle = 请给出 freq= 或 cycle=，不要同时给出
shell-too-many-pulses = { $key }={ $value } 脉冲数过多：PTO 最多计数到 4 294 967 295 (§3.4.2.1)
shell-pulses-not-whole = { $key } 必须是正整数个脉冲，1 … 4 294 967 295（给出的是 { $key }={ $value }）
shell-pto-needs-rate = pto 需要 freq= 或 cycle=
shell-pto-needs-count = pto 需要 count=
shell-pwm-needs-cycle = pwm 需要 cycle=（或 freq=）
shell-pwm-needs-width = pwm 需要 width=
shell-pwm-negative-width = 脉宽不能为负数
shell-segments-in-brackets = 段列表要写在方括号中：[(cycle=500us, count=1000), …]
shell-not-a-segment = `{ $text }` 不是段：请写成 (cycle=500us, count=1000)
shell-unexpected-in-segment = 段中出现意外的 `{ $extra }`
shell-segment-needs-rate = 段需要 cycle= 或 freq=
shell-segment-needs-count = 段需要 count=
shell-at-needs-address = `at` 需要一个 V 地址，例如 at VB3001
shell-not-a-v-byte = `{ $text }` 不是 V 字节地址（例如 { $example }）
shell-profile-needs-at = profile 需要 `at VBxxxx`（奇数 V 地址）
shell-profile-needs-segments = profile 需要段列表 [(cycle=…, count=…), …]
shell-profile-series = PTO{ $channel } 频率
shell-profile-plan-title = PTO{ $channel } 包络计划：{ $pulses } 个脉冲，{ $segments } 段
shell-profile-plan-segment = 段 { $segment }：{ $from }–{ $to } 秒  { $hz } Hz  { $pulses } 个脉冲
shell-profile-plan-total = 共计：{ $seconds } 秒内 { $pulses } 个脉冲；未写入任何内容（去掉 `plan` 即可运行）

## 高速计数器和 E2PROM 备份区 (shell::commands::counter, eeprom; K2 手册 §3.3, §2.2.8)

shell-hsc-not-a-number = `{ $text }` 不是{ $what ->
    [mode] 模式编号
    [cv] DINT 当前值
   *[pv] DINT 预设值
}
shell-hdef-needs-two = hdef 需要一个计数器和一个模式
shell-hsc-needs-counter = hsc 需要计数器编号
shell-hsc-needs-mode = hsc 辅助设置需要 mode=
shell-hsc-dir = dir={ $value }：请用 up 或 down
shell-hsc-level = { $key }={ $value }：有效电平为 high 或 low
shell-at-needs-v-address = `at` 需要一个 V 地址
shell-eeprom-saved = 已将 VB{ $first }…VB{ $last }（{ $bytes } 字节）保存到 { $file }
shell-cannot-read = 无法读取 { $file }
shell-eeprom-too-big = { $file } 有 { $bytes } 字节，但备份区 VB{ $first }…VB{ $last } 只有 { $room } 字节
shell-hint-eeprom-area = 请先扩大该区域：eeprom area 4095
shell-eeprom-restored = 已从 { $file } 将 { $bytes } 字节恢复到 VB{ $first }…VB{ $last }
shell-eeprom-area-size = 备份区 VB{ $first }…VB{ $last }（{ $bytes } 字节）
shell-eeprom-hottest = 写入最多的字节 VB{ $byte }：{ $writes } 次写入（约 { $endurance } 次的 { $share } %）
shell-eeprom-wear = 按本次会话的速率（虚拟时间每秒 { $rate } 次写入），它将在 { $left } 后磨损
shell-eeprom-wear-warning = 这会在 10 年内使 E2PROM 磨损；请不要把频繁变化的数据放在备份区 (§2.2.8)
shell-eeprom-no-writes = 没有统计到写入
shell-eeprom-area = 备份区 VB{ $first }…VB{ $last }
shell-one-file-only-plain = { $form } 只接受一个文件，而不是 { $count } 个词
shell-eeprom-unknown = 未知的 eeprom 命令

## 仿真器的时钟、输入和断电保持范围 (shell::commands::sim, siminputs)

shell-sim-step-form = sim step DURATION（例如 sim step 1s、sim step 500ms）
shell-unexpected-after-sim = `sim { $sub }` 之后出现意外的 `{ $extra }`
shell-sim-step-needs-duration = sim step 需要一个时长，例如 sim step 500ms
shell-sim-time-forward = 时间只能向前
shell-sim-step-too-far = sim step { $step } 会使仿真时钟超过 { $latest } 秒（约 584 年），即它能计数的最晚时间
shell-sim-clock-graded = 评分运行中不能使用 `sim clock real`：其时钟是仿真的
shell-hint-sim-clock-graded = 请用 sim step DURATION 或 plcsh.sleep(ms) 等待
shell-sim-not-clock-mode = `{ $mode }` 不是时钟模式
shell-hint-sim-clock-modes = sim clock real（跟随实际时钟）| sim clock stepped（只在 sim step 时前进）
shell-sim-run-ambiguous = `sim run` 有歧义：请说明要运行什么
shell-hint-sim-run-ambiguous = sim clock real：时间跟随时钟；sim cpu run：运行程序
shell-sim-cli-only = `sim { $sub }` 是命令行命令，不是 shell 命令
shell-hint-sim-cli-only = 在另一个终端中：plcsh sim { $sub } …（plcsh sim { $sub } --help 列出其选项）
shell-hint-fault-clear = sim fault clear（所有故障）| sim fault clear 2（故障 2；`sim faults` 列出编号）
shell-not-a-fault-id = `{ $id }` 不是故障编号：命令格式为 { $form }
shell-sim-unknown = 未知的 `sim { $sub }`
shell-sim-time = 仿真器时间 { $time }（{ $mode ->
    [stepped] 单步
   *[wall] 跟随实际时钟
}）
shell-not-an-input-bit = `{ $text }` 不是输入位（例如 I0.1）
shell-signal-needs-freq = 信号需要 freq=，例如 freq=1kHz
shell-signal-freq = freq={ $value }：必须是不超过 10 MHz 的整数 Hz
shell-sim-inputs-alone = sim inputs 之后不能再有内容（给出了 `{ $extra }`）
shell-no-input-signals = 没有仿真的输入信号
shell-retain-none-alone = `sim retain none` 必须单独使用（旁边给出了 `{ $extra }`）
shell-hint-retain-forms = sim retain none（不保持任何内容）| sim retain VB0..VB99 MB0[8]（这些范围）
shell-no-retained = 没有断电保持范围
shell-retained = 断电保持：{ $ranges }
shell-signal-stopped = 已停止：{ $signal }
shell-no-direction-input = { $input } 没有方向输入：dir= 只适用于 I0.1（方向 I0.5）和 I0.3（方向 I0.2）
shell-direction-input = ；方向输入 { $input } = { $value }
shell-quad-needs-two = sim quad 需要两个输入：A（超前）和 B
shell-quad-same-input = A 和 B 必须是不同的输入
shell-quad-dir = dir={ $value }：请用 up（A 超前）或 down（B 超前）

## 列表：设备、路径、端口；命令行的 run、completions 和 man (shell::commands, cli)

shell-devices-read-only = 只读
shell-devices-per-profile = 按各自配置
shell-devices-count = { $count } 台设备
shell-devices-profile-problem = 配置文件：{ $problem }
shell-paths-columns = 文件 | 路径 | 设置来源
shell-ports-columns = 端口 | 类型 | usb id | 适配器 | 序列号
cli-run-no-lua = 无法启动 Lua：{ $reason }
cli-run-no-sandbox = 无法设置沙箱：{ $reason }
cli-completions-cannot-write = plcsh：无法将补全脚本写入 { $dir }：{ $reason }
cli-completions-name-a-shell = plcsh completions：请指定 shell（bash、zsh、fish、powershell）或给出 --write DIR
cli-completions-wrote = 已写入 { $file }
cli-man-manual = plcsh 手册

## 仿真 CPU：程序、扫描、断点；FX 仿真器 (shell::commands::simprogram, fxsim)

shell-sim-no-program = { $name }：未加载程序（sim program load FILE.il）
shell-sim-cpu = { $name }：CPU { $mode }{ $switch ->
    [stop] （开关在 STOP 位置）
   *[run] { "" }
}
shell-sim-loaded = { $what ->
    [helper] 辅助程序
   *[program] 程序
}：{ $source }（{ $instructions } 条指令）
shell-sim-scans = 扫描 { $scans } 次；扫描时间 最近 { $last } ms、最小 { $min } ms、最大 { $max } ms (SMW22/24/26)；最近一次扫描 { $instructions } 条指令；运行了 { $interrupts } 个中断程序
shell-sim-costs = 看门狗 { $watchdog } ms，最短扫描 { $min_scan } ms，开销 { $overhead } ms
shell-sim-stopped-by-program = 已被程序的 STOP 指令停止（sim cpu run 可重新启动）
shell-sim-fault = { $at } 秒时故障：{ $fault }
shell-sim-err-led = Err 指示灯亮：{ $count } 个一般错误（CPU 继续运行）；最近一个发生于 { $at } 秒：{ $error }
shell-sim-cpu-needs-mode = sim cpu 需要 run、stop 或 pause
shell-sim-load-needs-file = sim program load 需要一个文件，例如 { $example }
shell-cannot-read-because = 无法读取 { $file }：{ $reason }
shell-sim-stop-values = STOP 时的值：{ $values }
shell-sim-program-unknown = 未知的 `sim program { $sub }`
shell-sim-switch-form = sim switch run|stop（仿真的 RUN/STOP 开关）
shell-sim-scan-count = sim scan N：N 是扫描次数 1…10000000，而不是 `{ $text }`
shell-sim-no-breakpoints = 没有断点
shell-sim-breakpoints = { $count ->
   *[other] 断点位于第
} { $lines } 行
shell-sim-breakpoints-cleared = 已清除断点
shell-sim-stepi-count = sim stepi N：N 为 1…100000，而不是 `{ $text }`
shell-fx-program = { $name }：{ $model } { $mode }；程序 { $program }（{ $instructions } 条指令）
shell-fx-no-program = { $name }：{ $model } { $mode }；没有程序（sim program load FILE.il）
shell-fx-scans = 扫描 { $scans } 次；扫描时间 最近 { $last } ms、最小 { $min } ms、最大 { $max } ms (D8010/D8011/D8012)；时间 { $time } 秒
shell-fx-fault = 因故障停止：{ $fault }
shell-fx-not-simulator = 不是 FX 仿真器
shell-fx-real = 真实的 FX 运行它自己的程序
shell-fx-loaded = { $file }：已加载 { $instructions } 条指令；PLC 以 RUN 模式重新启动
shell-fx-unloaded = 程序已删除：PLC 扫描空程序
shell-fx-program-unknown = FX PLC 上未知的 `sim program { $sub }`
shell-fx-no-pause = FX PLC 只有 RUN 和 STOP，没有 PAUSE
shell-fx-cpu-needs-mode = sim cpu 需要 run 或 stop
shell-fx-mode = { $model } 处于 { $mode }
shell-fx-sim-unavailable = FX PLC 上不能使用 `sim { $sub }`

## UMPK 教学 PLC (shell::commands::umpk; UMPK8/16 手册)

shell-umpk-not-umpk = `{ $name }` 不是 UMPK
shell-umpk-none-open = 没有打开任何 UMPK
shell-hint-umpk-open = 请用 --device lab=umpk:{ $port } 或 connect lab sim-umpk:UMPK16 打开一个
shell-umpk-several = 打开了多个 UMPK；请指定一个（umpk NAME info）
shell-umpk-needs-subcommand = umpk 需要一个子命令
shell-umpk-program-info-none = 程序信息（22 个空格：没有程序，等待模式）
shell-umpk-program-info = 程序信息 "{ $info }"
shell-umpk-timing = 最长周期 { $total } µs，固件 { $firmware } µs，程序 { $program } µs（T = (LLMM − HHKK) × 0.271 µs；HHKK={ $hhkk } LLMM={ $llmm }）
shell-umpk-reset = 复位：控制器已重新启动（收到 R；回显已打开）
shell-umpk-unknown = 未知的 `umpk { $sub }`
shell-umpk-real-program = 真实的 UMPK 只运行写入其中的程序（umpk program FILE.hex）；IL 程序在仿真器中运行
shell-umpk-il-loaded = { $file }：已加载 { $instructions } 条指令；在运行模式下每 { $cycle } ms 周期执行一次
shell-umpk-sim-program-unknown = UMPK 上未知的 `sim program { $sub }`
shell-hint-umpk-sim-program = sim program load FILE.il | sim program
shell-umpk-program-mode = 程序：{ $program }；模式 { $mode }
shell-umpk-info-columns = 字段 | 值
shell-umpk-info-fields = 型号 | 固件 | 输入 / 输出 | 模式 | 状态字 | 微码 | 回显 | 程序（仿真器）
shell-umpk-no-flag = 未设置任何标志
shell-umpk-mode = { $mode ->
    [Programming] 编程
    [Work] 运行
   *[Wait] 等待
}
shell-umpk-errors-cleared = 已清除错误历史
shell-umpk-errors-empty = 错误历史为空
shell-umpk-errors-columns = # | 代码 | 含义（最新的在前；1–127 用户，128–255 系统）
shell-umpk-send-needs = umpk send 需要一个命令或记录，例如 umpk send ?03FD
shell-umpk-sim-needs-simulator = umpk sim 只用于仿真的 UMPK：进程内的（sim-umpk:UMPK16），或由 plcsh sim serve --umpk-pty LINK 提供并以 control=LINK.ctl 打开的；真实 UMPK 的输入需要接线
shell-umpk-reference-in-process = 参考程序只能加载到进程内的仿真器（sim-umpk:UMPK16）
shell-umpk-no-reference = 没有参考程序 `{ $name }`
shell-hint-umpk-references = 参考程序：{ $names }
shell-umpk-reference-loaded = 已加载参考程序 { $name }（{ $description }）；模式 { $mode }
shell-umpk-program-needs-file = umpk program 需要一个 HEX 文件
shell-umpk-program-extra = 意外的 `{ $extra }`（文件之后只能跟 `run`）
shell-umpk-info-text = info="{ $info }"：1–22 个可打印 ASCII 字符（手册 §4.2.4）
shell-hint-umpk-hex = 未发送任何内容；{ $model } 接受 16#0000..16#{ $last } 范围内的 00/01/02/03 记录
shell-umpk-programmed-run = 复位：程序已启用（运行模式）
shell-umpk-programmed-stays = 控制器保持在编程模式；`umpk reset` 启用程序
shell-umpk-programmed = 已写入 { $bytes } 字节，共 { $pages } 页，确认了 { $records } 条记录{ $named ->
    [yes] ，程序信息 "{ $info }"
   *[no] { "" }
}{ $stopped ->
    [yes] ；控制器原处于运行模式：编程开始时其程序已停止，输出已关闭
   *[no] { "" }
}；{ $next }
shell-umpk-monitor-stopped = 实时监视数据流已停止（超时内没有数据包）
shell-umpk-monitor-cannot-write = 无法写出监视输出：{ $reason }
shell-umpk-monitor-samples = 来自 { $packets } 个数据包的 { $samples } 个监视采样

## 命令行的设备组、probe、记录和提供的仿真器 (cli::fleet, probe, record, serve)

cli-device-timeout-bad = --device-timeout { $value } 不是时长
cli-hint-device-timeout = 例如 30s、2m、500ms；0 表示不限
cli-jobs-at-least-one = --jobs 至少为 1
cli-fleet-all-refused = { $message }（设备组 `{ $fleet }` 的每个成员都拒绝了；没有执行任何内容）
cli-fleet-no-sandbox = --sandbox 只在仿真设备上运行，不能用于设备组
cli-hint-fleet-no-sandbox = 请用 plcsh lab grade 评分，或不带 --sandbox 运行设备组脚本
cli-fleet-checks = { $passed } 项检查通过，{ $failed } 项失败
cli-agent-check-read-only = agent check 会写入辅助程序的邮箱和一个脉冲输出通道的 SM 字节，而 --read-only 拒绝任何更改
cli-agent-check-profile = agent check 会写入辅助程序的邮箱和一个脉冲输出通道的 SM 字节，而配置 `{ $profile }`（{ $origin }）限制写入
cli-hint-agent-check-writes = 请在设备可以安全测试时，不带 --read-only、使用 PLC 的 URL 运行它（docs/reference/first-connection.md 列出了它写入的内容）
cli-probe-in-process = { $url } 是进程内的仿真器：线路上没有可探测的设备
cli-hint-probe-in-process = 请先提供它再探测：plcsh sim serve --tcp 127.0.0.1:0 [--agent]，然后 plcsh probe tcp://ADDRESS
cli-probe-not-on-wire = `{ $scheme }:` 不是线路上的 K2
cli-hint-probe-urls = 请给出 tcp://HOST:PORT、rtu:PORT?baud=…、rtu+tcp://HOST:PORT 或 rtu+rfc2217://HOST:PORT
cli-probe-cannot-write-report = 无法将报告写入 { $file }
cli-replay-bench-options = replay --bench 运行台架自己的仿真器：--sim-model 和 --snapshot 不适用
cli-hint-replay-bench-options = 请在台架文件中修改型号或初始值
cli-replay-no-device = replay 只把记录的请求发给它自己创建的仿真器，从不发给 --device
cli-hint-replay-no-device = 请用 --sim-model 选择仿真型号，用 --snapshot 选择其初始状态
cli-replay-no-reply = （无回复）
cli-replay-recorded = 记录的：{ $reply }
cli-replay-replayed = 重放的：{ $reply }
cli-replay-skipped = 未重放：{ $what }
cli-replay-summary = 重放了 { $requests } 个请求，{ $differences } 处不同
cli-record-damaged = plcsh：警告：{ $file }：{ $doing ->
    [replaying] 重放
   *[showing] 显示
}损坏处周围读出的 { $frames } 帧；退出状态 1
cli-record-truncated = plcsh：警告：{ $file } 提前结束（{ $why }）；{ $doing ->
    [replaying] 重放
   *[showing] 显示
}之前的 { $frames } 帧
cli-serve-not-an-address = `{ $text }` 不是可监听的地址
cli-hint-serve-address = 请用 HOST:PORT（127.0.0.1:5020、0.0.0.0:502）或端口（5020；0 表示选择空闲端口）
cli-serve-cannot-listen = 无法在 { $addr } 上监听
cli-hint-serve-port = 请选择另一个端口（0 表示空闲端口）；1024 以下的端口需要权限
cli-serve-fault-acted = plcsh sim serve：{ $line }
cli-serve-idle-timeout = --idle-timeout { $value } 不是时长
cli-hint-serve-idle-timeout = 例如 300s、2m
cli-serve-servo-latency = --servo-latency { $value }：不是时长
cli-hint-serve-servo-latency = 例如 1ms、500us、0
cli-serve-servo-baud = --servo-baud 必须为正数（例如 38400）
cli-serve-servo-line-stopped = 伺服线路在就绪之前就已停止
cli-serve-needs-transport = sim serve 至少需要一种传输方式
cli-hint-serve-transport = 例如 plcsh sim serve --tcp 127.0.0.1:5020 --rtu-tcp 0 --servo-tcp 0（在 Unix 上还可用 --rtu-pty /tmp/k2 --servo-pty /tmp/kinco）
cli-serve-agent-needs-k2 = --agent 在所提供的 K2 中运行：请同时给出 --tcp、--rtu-pty 或 --rtu-tcp
cli-serve-no-signals = 无法安装信号处理程序
cli-serve-no-readiness = 无法输出就绪行
cli-serve-server-stopped = 一个服务器已停止
cli-serve-failed = 提供服务失败
cli-serve-no-runtime = 无法启动运行时
cli-serve-fleet-state = --state 与 --fleet 同时使用：这些仿真器会共用一个状态文件
cli-hint-serve-fleet-state = 请去掉 --state（所提供的设备组不保存状态）
cli-serve-fleet-bench = --bench 与 --fleet 同时使用：台架只描述一台设备
cli-serve-fleet-ports = --tcp { $tcp } --fleet { $count }：端口超过了 65535
cli-serve-fleet-member-stopped = 设备组中一个成员的线程已停止
cli-serve-rfc2217-needs-tcp = --rfc2217 用于通过 TCP 提供的串行线路
cli-hint-serve-rfc2217 = 请同时给出 --rtu-tcp、--servo-tcp、--fx-tcp、--fx-link-tcp 或 --umpk-tcp，例如 --rtu-tcp 0 --rfc2217

## 步科伺服驱动器 (shell::commands::servo; 步科伺服 RS232 通讯说明，CiA 402 状态)

shell-usage-line = 用法：{ $line }
shell-servo-needs-subcommand = servo 需要一个子命令
shell-servo-nothing-after = servo { $sub } 之后不能再有内容（给出了 `{ $extra }`）
shell-servo-already-enabled = 已处于 operation enabled 状态
shell-servo-enabled = operation enabled（{ $steps }）
shell-servo-mode-needs = servo mode 需要一个模式：position、velocity、immediate-velocity、homing、torque 或 pulse
shell-servo-unknown-mode = 未知的模式 `{ $mode }`
shell-hint-servo-modes = position (1)、velocity (3)、immediate-velocity (-3)、homing (6)、torque (4)、pulse (-4)
shell-servo-mode-set = 工作模式 { $number }（{ $name }）
shell-servo-halted = 已暂停：制动到停止并保持（controlword 16#{ $controlword }）
shell-servo-halt-released = 已解除暂停：运动继续（controlword 16#{ $controlword }）
shell-servo-homing = 已开始原点回归（模式 6，controlword 16#000F → 16#001F）
shell-servo-saved = 参数已保存（2FF0.01 = 1）
shell-servo-not-servo = `{ $name }` 不是伺服驱动器
shell-servo-none-open = 没有打开任何伺服驱动器
shell-hint-servo-open = 请用 --device ax=kinco:{ $port }?id=1 或 connect ax sim-servo:?id=1 打开一个
shell-servo-several = 打开了多个伺服驱动器；请指定一个
shell-hint-servo-several = servo { $first } status（已打开：{ $names }）
shell-servo-not-whole = `{ $key }={ $value }` 不是整数
shell-hint-servo-options = 选项：{ $options }
shell-servo-move = 已开始{ $kind ->
    [rel] 相对
   *[abs] 绝对
}运动到 { $target } inc
shell-servo-move-speed = 已开始以 { $rpm } rpm（{ $dec } DEC）{ $kind ->
    [rel] 相对
   *[abs] 绝对
}运动到 { $target } inc
shell-servo-jog-usage = 用法：servo jog SPEED [acc=… dec=…]，例如 servo jog 300rpm；servo jog 0 停止
shell-servo-jogging = 以 { $rpm } rpm 点动（{ $dec } DEC，模式 3）
shell-servo-over-max = { $rpm } rpm 超过了驱动器的最高速度 { $max } rpm（6080.00 max_speed）
shell-hint-servo-max = 速度不超过 { $max }rpm；最高速度是驱动器的设定 6080.00（servo read max_speed）
shell-hint-servo-wait = servo wait target timeout=5s
shell-servo-target-reached = { $seconds } 秒后到达目标（position_actual { $position } inc）
shell-servo-read-needs = servo read 需要对象，例如 servo read target_velocity position_actual
shell-servo-read-columns = 对象 | 索引 | 值 | 单位 | 工程值
shell-servo-encoder = 编码器分辨率 { $resolution } inc/rev
shell-servo-not-hex-byte = `{ $text }` 不是十六进制字节
shell-servo-frame-length = 一帧为 9 字节（会加上校验和）或 10 字节，而不是 { $count }
shell-hint-servo-raw = 例如 servo raw 01 40 41 60 00 00 00 00 00
shell-servo-sim-needs = servo sim 需要一个控制命令
shell-servo-sim-needs-simulator = servo sim 只用于仿真的驱动器：进程内的（sim-servo:）、由 plcsh sim serve --servo-pty LINK 提供的，或以 --servo-tcp ADDR --servo-control PATH 提供并以 control=PATH 打开的
shell-hint-servo-sim-control = 所提供驱动器的控制套接字为 LINK.ctl；如果在别处，请在 kinco: URL 中用 control=PATH 给出
shell-servo-unknown = 未知的 `servo { $sub }`
