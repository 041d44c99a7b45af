# plcsh messages (zh-CN): lab — 实验、脚本与记录. Same ids and arguments in en, ru and zh-CN
# (tests/messages.rs).

## Limits of a graded run (core::budget): the verdict names the limit passed.
budget-exceeded-minutes = 超出 { $n } 分钟仿真时间
budget-exceeded-seconds = 超出 { $n } 秒仿真时间
budget-exceeded-instructions = 超出 { $count } 条 Lua 指令
budget-exceeded-memory = 超出 Lua 内存 { $size }
budget-size-mib = { $n } MiB
budget-size-bytes = { $n } 字节

## Verdicts of a graded submission (lab::grader, lab::runner).
lab-grader-error = 评分程序错误：{ $error }
lab-runtime-error = 运行错误：{ $error }
lab-exceeded-write = 写入目录中超出 { $size }
lab-exceeded-wall = 超出实际时间安全上限 { $seconds } s
lab-not-graded = 未评分：被 { $cause } 停止
lab-refused-link = 拒绝：{ $file } 是符号链接：提交的作业只能是自己的文件，不能是链接（请提交文件本身）
lab-refused-size = 拒绝：提交的作业有 { $n } 字节，超过实验的上限 { $cap }（lab.toml 中的 [budget] submission）
lab-not-submission-kind = 不是提交的作业：请提交 .lua 脚本或 .il 程序
lab-not-submission-missing = 不是提交的作业：没有该文件
lab-not-accepted = 不接受：本实验接受 { $kinds } 作业
lab-plc-stopped = { $file }:{ $line }：PLC 已停止：{ $error }
lab-plc-fault-code-at = { $place }：PLC 因故障 { $code }（{ $kind }）停止：{ $error }，位置 `{ $at }`
lab-plc-fault-code = { $place }：PLC 因故障 { $code }（{ $kind }）停止：{ $error }
lab-plc-fault-at = { $place }：PLC 停止（{ $kind }）：{ $error }，位置 `{ $at }`
lab-plc-fault = { $place }：PLC 停止（{ $kind }）：{ $error }
lab-device-replaced = { $file }：提交的作业关闭或替换了实验的设备 `{ $device }`
lab-cannot-read = 无法读取 { $file }：{ $error }
lab-cannot-start-lua = 无法启动 Lua：{ $error }
lab-opening-devices = 打开实验的设备时
lab-view = 提交作业自己的文件、实验的共享模块和初始文件以及写入目录
lab-write-dir-role = 写入目录
lab-cannot-create-write-dir = 无法为本次运行创建写入目录
lab-write-dir-not-own = 给定的写入目录不是评分程序自己的目录
lab-cannot-create-report-dir = 无法创建报告目录：{ $error }
lab-cannot-create-write-dir-error = 无法创建写入目录：{ $error }
lab-cannot-start-worker = 无法启动工作进程：{ $error }
lab-worker-no-report = 工作进程结束（{ $status }）但没有报告
lab-worker-error = plcsh lab 工作进程：{ $error }
lab-worker-cannot-write = plcsh lab 工作进程：无法写入 { $file }：{ $error }
lab-workers-running = 工作进程仍在运行
lab-no-executable = 找不到 plcsh 可执行文件
lab-bytes-more = … 还有 { $n } 字节

## `lab grade`, `lab new`, `lab check` (lab::runner, lab, cli::lab, shell::commands::lab).
lab-cannot-list = 无法列出 { $dir }
lab-no-such-submission = { $file }：没有该文件或目录
lab-hint-submissions = 请给出提交的作业文件（.lua、.il）或包含它们的目录
lab-no-submissions = 没有找到提交的作业（.lua 或 .il 文件）
lab-grade-stopped = lab grade 在所有作业评分完成之前被 { $cause } 停止（已评分 { $done } 份）
lab-hint-grade-again = 请再次运行以对所有作业评分
lab-cannot-write = 无法写入 { $file }
lab-new-exists = { $dir } 已存在
lab-hint-new-name = 请给出新的目录名：plcsh lab new NAME
lab-cannot-create = 无法创建 { $dir }
lab-cannot-create-empty-dir = 无法为空程序创建目录
lab-cannot-write-empty = 无法写入空程序
lab-not-in-sandbox = 在沙箱运行中不能使用 `lab`（它会启动进程并写入目录）
lab-not-in-this-run = 本次运行中不能使用 `lab`
lab-hint-check-table = `plcsh lab check` 的表格列出了每条评分标准的结果
lab-bad-jobs = jobs={ $jobs }：工作进程数须 ≥ 1
lab-needs-sub = `lab` 需要 new、check 或 grade 及其参数

## lab.toml (lab::config).
lab-cannot-read-file = 无法读取 { $file }
lab-hint-lab-folder = 实验是一个包含 lab.toml 的目录；`plcsh lab new NAME` 会写入一个示例
lab-cannot-open = 无法打开 { $dir }
lab-no-such-file = { $file }：{ $key } = "{ $name }"：{ $dir } 中没有该文件
lab-file-outside = { $file }：{ $key } = "{ $name }" 在实验目录之外
lab-hint-files-inside = 实验的文件都放在它的目录中，这样实验可以整体复制
lab-devices-one-way = { $file }：请用 bench = "FILE" 或 [devices] 表给出设备（二选一）
lab-hint-devices-example = 例如 [devices] plc = "sim:K205-16DT"
lab-budget-not-time = { $file }：[budget] { $key } = "{ $text }" 不是 plcsh 能读取的时间
lab-budget-not-time-why = { $file }：[budget] { $key } = "{ $text }" 不是 plcsh 能读取的时间：{ $error }
lab-hint-write-time = 请写 "{ $time }"（单位 h、min、s、ms）
lab-hint-write-time-or = 请写 "{ $time }" 或 "{ $seconds }"（单位 h、min、s、ms）
lab-hint-time-example = 例如 "10min"、"90s"、"1h"（单位 h、min、s、ms）
lab-budget-not-positive = { $file }：[budget] { $key } = "{ $text }" 必须大于零
lab-budget-not-size = { $file }：[budget] { $key } = "{ $text }" 不是大小
lab-hint-write-size = 请写 "{ $size }"（单位 B、KiB、MiB、GiB）
lab-hint-size-example = 例如 "256MiB"（单位 B、KiB、MiB、GiB）
lab-budget-instructions-zero = { $file }：[budget] instructions 必须大于零
lab-not-a-grant = { $file }：grants = ["{ $grant }"]：不是实验可以授权的操作
lab-hint-did-you-mean-grant = 是否想输入 "{ $near }"？grants：{ $grants }
lab-hint-grants = grants：{ $grants }
lab-points-negative = { $file }：[points] "{ $key }" = { $value }：分数须为 ≥ 0 的数
lab-not-a-device = { $file }：device = "{ $device }" 不是实验的设备
lab-hint-did-you-mean-device = 是否想输入 device = "{ $near }"？实验的设备：{ $devices }
lab-hint-devices = 实验的设备：{ $devices }
lab-not-a-kind = { $file }：accepts = ["{ $kind }"]：不是作业类型
lab-hint-kinds = 类型：{ $kinds }
lab-shared-not-lua = { $file }：shared = ["{ $name }"]：共享模块是 .lua 文件
lab-hint-shared-example = 例如 shared = ["helpers.lua"]（作业中再调用 require("helpers")）

## Lua scripts (script): errors plcsh raises in Lua code.
script-session-busy = 会话忙：{ $error }
script-no-session = 没有会话：Lua 只能在 plcsh 中运行
script-device-not-open = 设备 `{ $device }` 未打开（已关闭或从未打开）
script-no-output = 没有输出
script-bad-millis = { $what }：{ $ms } 不是以毫秒为单位的时长（≥ 0 的数）
script-json-too-deep = plcsh.json.encode：值的嵌套超过 { $depth } 层表（或包含自身）
script-hint-json-tree = JSON 保存的是表的树；请把值展平
script-hint-json-split = JSON 数组是没有空缺的 1…n 列表；对象的键是字符串——请拆分该表
script-json-mixed = plcsh.json.encode：{ $path } 混合了列表项和键
script-json-sparse = plcsh.json.encode：{ $path } 是有空缺的列表（{ $items } 项，最大索引 { $max }）
script-unknown-option = { $what }：未知选项 `{ $key }`
script-hint-did-you-mean-option = 是否想输入 `{ $near }`？{ $what } 接受 { $options }
script-hint-options = { $what } 接受 { $options }
script-wait-until-options = wait_until 的第二个参数是 {"{"}timeout=ms, every=ms{"}"} 或超时时间，而不是 { $kind }
script-wait-until-timeout = wait_until：条件在 { $time } 后仍为假
script-wait-until-timeout-what = wait_until：条件（{ $what }）在 { $time } 后仍为假
script-hint-wait-until = 请增大 `timeout`，或用 plcsh.exec/get 检查条件
script-method-error = { $method }：{ $error }
script-hint-runs-command-line = { $method } 运行一条命令行，并附加其余参数
script-hint-runs-template = { $method } 运行 `{ $template }`，并附加其余参数
script-arg-not-utf8 = 参数不是 UTF-8 文本
script-cannot-pass = 不能把 Lua 的 { $kind } 传给命令
script-option-not-utf8 = 选项名不是 UTF-8
script-option-not-string = 选项名是字符串，而不是 { $kind }
script-missing-argument = 缺少 `{ $spec }` 的参数
script-command-not-utf8 = 命令文本不是 UTF-8
script-nothing-to-run = 没有要运行的内容
script-sandbox-refused = 沙箱运行中不能使用 { $what }（它{ $why ->
    [program] 会运行程序
    [delete] 会删除文件
    [rename] 会重命名文件
    [exit] 会结束 plcsh
    [create] 会创建文件
    [environment] 会读取本机的环境变量
   *[library] 会加载 C 库
}）
script-hint-sandbox = 沙箱允许仿真设备、打印、检查以及实验目录中的文件
script-lab-frame = （实验自身的栈帧）
script-sandbox-terminal = 不带文件的 { $function } 会读取终端：沙箱运行中不可用
script-module-not-found = 找不到模块 '{ $name }'：{ $own ->
    [folder] 作业目录中没有 { $path }.lua
   *[single] 单文件作业没有自己的模块
}；{ $shared ->
    [none] 实验没有共享模块
   *[some] 实验共享的模块：{ $modules }
}
script-require-not-string = 'require' 的第 1 个参数错误（应为字符串，实际为 { $kind }）
script-require-loop = 模块 '{ $name }' 需要它自身（require 调用成环）
script-hint-require = 作业可以 require 自己的模块和实验共享的模块
script-date-field-missing = 日期表中缺少字段 '{ $field }'
script-cannot-read = 无法读取 { $file }：{ $error }
script-os-exit = 脚本调用了 os.exit({ $code })
script-tmpname-cannot-create = os.tmpname：无法在 { $dir } 中创建文件：{ $error }
script-tmpname-no-name = os.tmpname：{ $dir } 中没有可用的文件名
script-no-built-in-module = plcsh 内置模块中没有 '{ $name }'
script-sandbox-modules = （沙箱运行只加载 plcsh 的模块和实验自己的模块）
script-operand-not-text = 操作数名是文本
script-field-many-operands = `{ $text }` 指定了 { $count } 个操作数；一个字段只对应一个操作数
script-hint-read-range = 读取范围请用 { $device }:get("{ $text }")
script-hint-methods = 方法：{ $methods }；操作数是字段：{ $device }.VW0
script-hint-did-you-mean-method = 是否想输入 { $count ->
    [1] { $a }
    [2] { $a } 或 { $b }
   *[3] { $a }、{ $b } 或 { $c }
}？
script-no-method = 设备 `{ $device }` 没有方法或操作数 `{ $word }`
script-set-pairs-only = set：只能传入 {"{"}"OPERAND", value{"}"} 对
script-set-odd-arguments = set：{ $count } 个参数；请按 OPERAND, value, OPERAND, value … 传入
script-set-names-strings = set：操作数名是字符串
script-set-needs-values = set 需要操作数和值
script-cannot-write-value = 不能写入 Lua 的 { $kind }（请使用数字、布尔值或 "16#85" 这样的字面量）
script-method-dot = `{ $method }` 是方法：请用冒号调用 `dev:{ $method }(…)`，而不是用点 `dev.{ $method }(…)`

## `plcsh publish` (cli::publish): readings to an MQTT broker.
publish-needs-broker = publish 需要一个代理服务器（broker）
publish-hint-broker = --broker mqtt://HOST:1883，或在配置文件的 [mqtt] 下写 url = "mqtt://HOST:1883"
publish-password-without-user = 有代理服务器密码但没有用户名
publish-hint-username = 请在配置文件的 [mqtt] 下设置 username，或设置 PLCSH_MQTT_USERNAME
publish-cannot-read-ca = 无法读取 [mqtt] ca_file { $file }：{ $error }
publish-auth-refused = 代理服务器 { $broker } 拒绝了凭据（{ $why }）
publish-hint-auth = 请检查配置文件 [mqtt] 下的 username（或 PLCSH_MQTT_USERNAME）和 PLCSH_MQTT_PASSWORD，以及代理服务器的 ACL 是否允许该用户连接
publish-tls-failed = 与代理服务器 { $broker } 的 TLS 失败（{ $why }）
publish-hint-tls = 代理服务器的证书必须能用 [mqtt] 下的 ca_file（其 CA，PEM 格式）或系统根证书验证，并包含 --broker 中的主机名
publish-no-broker = 启动后 { $seconds } s 内 { $broker } 上没有 MQTT 代理服务器应答（{ $why }）
publish-hint-no-broker = 代理服务器是否在运行？--broker 中的主机和端口是否正确（mqtt:// 1883，mqtts:// 8883）？
publish-not-an-operand = `{ $operand }` 不是该设备的操作数：{ $error }
publish-hint-fix-operand = 未发布任何内容；请修正操作数（plcsh -c 'get OPERAND' 显示设备的应答）
publish-not-an-operand-fleet = `{ $operand }` 不是设备组 `{ $fleet }` 中任何成员的操作数：{ $error }
publish-not-an-operand-members = `{ $operand }` 不是 { $members }{ $more ->
    [0] {""}
   *[other] {" "}等另外 { $more } 台设备
} 的操作数：{ $error }
publish-hint-fix-operand-fleet = 未发布任何内容；请修正操作数（plcsh -f FLEET -c 'get OPERAND' 显示每个成员的应答）
publish-bad-every = --every { $every } 不是时长
publish-hint-every = 例如 1s、250ms
publish-no-mqtt-thread = 无法启动 MQTT 线程
publish-no-poll-threads = 无法启动轮询线程
publish-connected = 已连接到 { $broker }
publish-broker-away = 代理服务器 { $broker } 不可用（{ $why }）；读数最多保留 --buffer 条，恢复后发送
publish-device-back = { $device } 重新应答
publish-polling-stopped = 轮询已停止；正在发送队列中的内容（代理服务器有几秒钟时间接收）
publish-summary = 已向 { $broker } 发布 { $published } 条消息（组 { $group }{ $shard ->
    [some] ，分片 { $shard_of }
   *[none] {""}
}）；代理服务器不可用期间丢弃 { $away } 条，因 plcsh 跟不上丢弃 { $behind } 条并跳过 { $skipped } 次轮询，停止时丢弃 { $undelivered } 条（未送达），重连 { $reconnects } 次{ $worst ->
    [some] ；落后最多：{ $worst_list }
   *[none] {""}
}{ $offline ->
    [some] ；离线：{ $offline_list }
   *[none] {""}
}

## `plot` pictures (plot) and fleet runs (fleet).
plot-cannot-draw = 无法绘制曲线图：{ $error }
plot-bad-picture = to={ $path }：图片须为 .png 或 .svg
plot-hint-picture = 例如 to=ramp.png 或 to=ramp.svg
plot-cannot-write = 无法写入 { $path }：{ $error }
plot-bad-size = size={ $text } 不是 宽x高（例如 900x400）
plot-size-range = size={ $text }：每边须为 { $min }…{ $max } 像素
fleet-internal-error = 对该设备的操作因内部错误而停止
fleet-no-thread = 无法启动工作线程
fleet-timeout = { $seconds } s 内没有结果
fleet-hint-timeout = 设备可能已关闭或响应慢；请增大 --device-timeout，或单独检查它的通信链路
fleet-not-started = 未启动：设备组的运行已停止
fleet-all-ok = 设备组 { $fleet }：{ $count } 台设备，全部正常（{ $ms } ms，同时 { $jobs } 台）
fleet-failed = 设备组 { $fleet }：{ $count } 台设备中 { $failed } 台失败：{ $devices }（{ $ms } ms，同时 { $jobs } 台）

## Recordings (record): --record, `replay`.
record-cannot-read = 无法读取记录 { $file }
record-hint-give-file = 请给出 --record FILE 写入的文件
record-not-readable = { $file } 不是可读的 pcapng 记录：{ $error }
record-hint-capture = 请给出 plcsh --record FILE 写入的文件，或在以太网或回环接口上抓取的 Modbus TCP pcapng/pcap 文件（tshark -i lo -f 'tcp port 502' -w FILE.pcapng）
record-snap-length = { $count } 个数据包被抓包长度（snap length）截断：其中的帧不完整（请不带 -s 或用 -s 0 重新抓包）
record-no-tcp = 其 { $count } 个数据包不含 TCP 数据（没有抓到 Modbus TCP 通信）
record-bytes-missing = 抓包中缺少从 { $from } 到 { $to } 的 { $lost } 字节（其附近的帧可能显示为格式错误）
record-cannot-create = 无法创建记录 { $file }
record-hint-writable = 请检查目录是否存在且可写
record-cannot-write = 无法写入记录 { $file }
record-incomplete = 记录 { $file } 不完整：{ $error }
replay-no-sim-plc = { $link }：测试台上没有仿真 PLC
replay-no-sim-drive = { $link }：测试台上没有仿真驱动器
replay-other-protocol = { $link }：{ $protocol } 帧（重放只覆盖 Modbus 和伺服链路）
replay-undeclared-protocol = { $link }：未声明协议的帧
replay-helper-cannot-run = { $link }：辅助程序无法运行：{ $error }
replay-no-reply-recorded = 记录中没有应答；仿真器有应答
replay-no-reply-replayed = 记录中有应答；仿真器没有应答
replay-no-requests = { $file } 中没有记录的请求
replay-hint-record = 请记录一个通过 Modbus 或伺服线路与设备通信的会话：plcsh --record FILE --device plc=tcp://…
publish-command-too-big = 一条命令最多 { $max } 字节
publish-command-not-json = 不是 JSON：{ $error }
publish-command-not-object = 命令是一个 JSON 对象 {"{"}"operand":…, "value":…{"}"}
publish-command-no-operand = 缺少 `operand`（字符串）
publish-command-no-value = 缺少 `value`（数字、true/false 或 "16#85" 这样的字面量）
publish-command-one-write = 每条命令只能有一个操作数和一个值
publish-write-no-allow-list = 写入被拒绝：`{ $device }` 没有允许列表：来自代理服务器的写入需要在其配置中设置
publish-write-profile-no-allow-list = 写入被拒绝：`{ $device }` 的配置没有允许列表：来自代理服务器的写入需要它
publish-no-such-member = `{ $device }` 不是 `{ $group }` 的设备（成员：{ $members }）
publish-no-such-member-near = `{ $device }` 不是 `{ $group }` 的设备（成员：{ $members }）；是否想输入 { $near }？
publish-no-runtime = 无法启动运行时：{ $error }

## Capture files (record::container): pcapng and pcap, as read for `replay` and `decode`.
capture-empty = 文件为空（0 字节）
capture-bad-start = 文件以 { $bytes } 开头，而不是 pcapng 节头（0A 0D 0D 0A）或 pcap 文件头
capture-damaged-block = 字节 { $from }…{ $to }（{ $count } 字节）已损坏（{ $why }）；从偏移 { $next } 处的块继续读取
capture-no-block = 文件中没有完整的块（{ $size } 字节）：偏移 { $at } 处的{ $what ->
    [header] 节头
   *[block] 块
}{ $state ->
    [cut] 被截断
   *[damaged] 已损坏
}（{ $why }）
capture-block-truncated = 偏移 { $at } 处的块{ $state ->
    [cut] 被截断
   *[damaged] 已损坏
}：{ $why }
capture-bad-magic = 其字节序标记 { $magic } 既不是 4D 3C 2B 1A 也不是 1A 2B 3C 4D
capture-short-section = 剩余 { $left } 字节，不足节头的前 12 字节
capture-short-block = 剩余 { $left } 字节，不足一个块头
capture-unknown-block = 未知的块类型 { $kind }
capture-bad-block-length = 块长度 { $total } 不是不小于 12 的 4 的倍数
capture-block-past-end = 块长度为 { $total }，但只剩 { $left } 字节
capture-lengths-differ = 其结尾长度与开头长度不同
capture-block-short = { $block ->
    [section] 节头
    [interface] 接口描述
    [enhanced] 增强数据包块
    [packet] 数据包块
   *[simple] 简单数据包块
}短于 { $bytes } 字节
capture-packet-past-block = 数据包长度 { $length } 超出其所在的块
capture-no-interface = 数据包引用了接口 { $id }，但没有接口描述声明它
capture-short-pcap = { $size } 字节：短于 pcap 文件头（24）
capture-short-record = 剩余 { $left } 字节，不足一个记录头
capture-record-past-end = 记录长度为 { $length }，但只剩 { $left } 字节
capture-record-impossible = 记录长度 { $length }/{ $original } 或时间小数部分不可能
capture-record-unreadable = 无法读取的记录头
capture-damaged-record = 字节 { $from }…{ $to }（{ $count } 字节）已损坏（{ $why }）；从偏移 { $next } 处的记录继续读取
capture-record-truncated = 偏移 { $at } 处的记录被截断或已损坏（{ $why }）
