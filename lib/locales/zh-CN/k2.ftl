# plcsh messages (zh-CN): k2 — K2 的驱动、仿真器、辅助功能、接线与快照. Same ids and arguments in en, ru and zh-CN
# (tests/messages.rs).

## 脉冲输出：pto、pwm、profile（k2::helpers::pto；手册 §3.4）

k2-pto-rounded = { $hz } Hz 不是整数微秒：周期时间 { $us } µs = { $actual } Hz
k2-pto-relay-model = { $model } 为继电器输出：没有 PTO/PWM（手册 §2.2.6）
k2-pto-relay-model-hint = 高速脉冲输出需要晶体管输出的型号，例如 K205-16DT
k2-pto-no-channel = { $model } 没有脉冲通道 { $channel }
k2-pto-no-channel-hint = 脉冲通道：{ $list }
k2-pto-cycle-register = { $us } µs 超出周期时间寄存器：最大 65 535 µs，或整数毫秒最大 65 535 ms
k2-pto-cycle-below-minimum = 周期时间 { $us } µs 小于最小值 2（§3.4.2.2）
k2-pto-cycle-too-short = 周期时间 { $us } µs 对 { $output } 太短：其最短周期时间为 { $shortest } µs（{ $max } Hz，手册 §3.4）
k2-pto-cycle-too-short-hint = cycle={ $shortest }us 或更长；未写单位时 cycle= 以 µs 计（cycle=1ms）
k2-pto-freq-too-high = { $hz } Hz 超过 { $output } 的上限 { $max } Hz（手册 §3.4）
k2-pto-freq-too-high-hint = { $output } 的最短周期时间为 { $shortest } µs
k2-pto-count-range = count={ $count }：PTO 的脉冲数须为 2 … 4 294 967 295（§3.4.2.1）
k2-pto-ms-base = 周期时间 { $us } µs 使用 1 ms 时基（SM{ $control }.3 = 1）
k2-pwm-width-whole-ms = width={ $width } µs：周期时间为 { $cycle } µs 时时基为 1 ms，脉冲宽度须为整数毫秒
k2-pwm-always-on = 脉冲宽度 ≥ 周期时间：占空比 100 %，输出保持接通（§3.4.2.1）
k2-pwm-always-off = 脉冲宽度 0：占空比 0 %，输出保持断开（§3.4.2.1）
k2-table-odd-hint = 例如 at VB{ $at }
k2-profile-even = VB{ $at } 为偶数地址：包络表须从奇数 V 地址开始（§3.4.2.1）
k2-profile-segments = { $n } 段：包络表有 1 … { $max } 段
k2-profile-past-v = 表 VB{ $at }…VB{ $last } 超出 { $model } 的 V 存储区（VB{ $top }）
k2-profile-backup = 表 VB{ $at }…VB{ $last } 与 E2PROM 备份区 VB{ $first }…VB{ $end } 重叠（§2.2.8）：每次写入都会磨损它
k2-table-backup-hint = 把表移到 VB3648 以下，或加上 `force`
k2-profile-segment = 第 { $n } 段
k2-profile-segment-count = 第 { $n } 段：count={ $count }（1 … 4 294 967 295）
k2-profile-segment-error = 第 { $n } 段：{ $message }
k2-profile-ms-base = 包络表使用 1 ms 时基（SM{ $control }.3 = 1）
k2-profile-mixed-base = 所有段共用一个时基（§3.4.2.1）：有的周期时间需要 1 ms 单位（> 65 535 µs），而其他的不是整数毫秒
k2-pto-control-bit = { $bit ->
    [enabled] 使能
    [disabled] 禁止
    [sync] 同步更新
    [async] 异步更新
    [multi] 多段
    [single] 单段
    [base-ms] 1 ms 时基
    [base-us] 1 µs 时基
    [cycle] 更新周期时间
    [width] 更新脉冲宽度
   *[count] 更新脉冲数
}
k2-pto-status-bit = { $bit ->
    [pto-idle] PTO 空闲
    [pto-busy] PTO 忙
    [pwm-idle] PWM 空闲
    [pwm-running] PWM 运行中
    [invalid] 周期时间或脉冲数无效
   *[aborted] 被用户命令中止
}
k2-pto-status-control = 控制字节：{ $words }
k2-pto-status-position = 位置 { $pulses } 个脉冲
k2-pto-status-estop = 急停已锁存（SM{ $byte }.7）
k2-pto-status-dir-off = 方向输出已禁止（SM{ $byte }.3）
k2-pto-busy = PTO{ $channel } 仍在发送脉冲串（SM{ $byte }.7 PTO 空闲 = 0）
k2-pwm-busy = PWM{ $channel } 正在运行（SM{ $byte }.3 PWM 空闲 = 0）

## 高速计数器：hsc（k2::helpers::hsc；手册 §3.3）

k2-hsc-no-counter = { $model } 没有高速计数器 HSC{ $n }
k2-hsc-no-counter-hint = { $model } 的计数器：{ $list }
k2-hsc-no-mode = HSC{ $n } 没有模式 { $mode }（手册 §3.3.1）
k2-hsc-no-mode-hint = HSC{ $n } 的模式：{ $list }
k2-hsc-rate-4x = rate=4x 只用于 AB 相正交模式（9、10），不用于模式 { $mode }
k2-hsc-dir = 模式 { $mode } 的计数方向来自其输入；dir= 只用于模式 0–2（§3.3.2）
k2-hsc-no-reset = 模式 { $mode } 没有复位输入
k2-hsc-no-start = 模式 { $mode } 没有启动输入
k2-hsc-cyclic-relative = 循环的 CV = PV 中断需要相对 PV（§3.3.2：SM141.2 只在 SM141.1 置位时有效）
k2-hsc-table-needs-at = PV 表（多个 PV、相对或循环）需要一个 V 地址：加上 `at VB3009`
k2-hsc-at-needs-pv = `at` 需要 PV：pv=[100,200,300]
k2-hsc-even = VB{ $at } 为偶数地址：PV 表须从奇数 V 地址开始（§3.3.2）
k2-hsc-too-many-pvs = { $n } 个 PV：一个计数器最多 { $max } 个（§3.3.3）
k2-hsc-past-v = PV 表 VB{ $at }…VB{ $last } 超出 { $model } 的 V 存储区（VB{ $top }）
k2-hsc-backup = PV 表 VB{ $at }…VB{ $last } 与 E2PROM 备份区 VB{ $first }…VB{ $end } 重叠（§2.2.8）
k2-hsc-pv-ends-table = PV{ $index } = { $pv } 会使表在此结束（§3.3.3：相对 |PV| > 1，相邻绝对值之差 > 1）
k2-hsc-events = CV = PV 中断事件 { $first }…{ $last }（§3.3.4）
k2-hsc-status-bit = { $bit ->
    [up] 增计数
    [down] 减计数
    [equal] CV = PV
    [greater] CV > PV
    [fault] PV 表故障
    [enabled] 使能
   *[disabled] 禁止
}
k2-hsc-status-cv = CV { $cv }
k2-hsc-status-written-cv = SMD{ $smd } 为写入的 { $value }：新的当前值，将由下一次 SM{ $control }.6 置位的 HSC { $n } 装入（§3.3.2）
k2-hsc-status-multi-pv = { $kind ->
    [relative] 多 PV，相对，第 { $segment } 段
    [relative-cyclic] 多 PV，相对，循环，第 { $segment } 段
    [absolute-cyclic] 多 PV，绝对，循环，第 { $segment } 段
   *[absolute] 多 PV，绝对，第 { $segment } 段
}
k2-hsc-status-single-pv = 单 PV { $pv }

## 执行辅助功能的计划（k2::helpers）

k2-not-a-k2 = 此设备不是 K2 PLC
k2-duration-not-positive = `{ $text }` 不是正的时长

## 操作数：操作数的含义、`help 操作数`、补全（k2::space）

k2-describe-overlaps = 与 { $names } 重叠
k2-describe-pulse-output = 开关量输出；PTO{ $channel }/PWM{ $channel } 高速脉冲输出（最高 { $khz } kHz）
k2-describe-direction-output = 开关量输出；定位通道 { $channel } 的方向输出
k2-describe-v-backup = 变量存储器，位于 E2PROM 备份区（VB3648–VB4095，§2.2.8）
k2-help-type = 类型 { $dtype }（{ $bits } 位），范围 { $range }
k2-help-area = { $unit ->
    [elements] 存储区 { $area }（{ $meaning }）：{ $model } 上有 { $n } 个元件
   *[bytes] 存储区 { $area }（{ $meaning }）：{ $model } 上有 { $n } 字节
}
k2-help-manual = 手册 { $section }
k2-help-source = 来源：{ $source }
k2-help-written-as = 按手册和 KincoBuilder 的操作数写法（S7-200 风格）
k2-complete-form = { $form ->
    [I] 输入位 I0.0
    [IB] 输入字节
    [Q] 输出位 Q0.0
    [QB] 输出字节
    [M] 存储位 M0.0
    [MB] 存储字节
    [MW] 存储字
    [MD] 存储双字
    [V] V 位 V0.0
    [VB] V 字节
    [VW] V 字
    [VD] V 双字
    [SM] 特殊寄存器
    [AIW] 模拟量输入字
    [AQW] 模拟量输出字
    [T] 定时器
    [C] 计数器
   *[K4M] 由 M 位组成的 16 位组
}

## 仿真器快照（snapshot）

snapshot-cannot-encode = 无法编码快照
snapshot-section-invalid = 快照中 `{ $device }` 的 { $section } 部分无效
snapshot-section-invalid-at = 快照中 `{ $device }` 的 { $section } 部分在 `{ $at }` 处无效
snapshot-file-damaged = 文件可能已损坏
snapshot-wire-of = 快照中 `{ $name }` 的一条接线
snapshot-cannot-snapshot = 无法为 `{ $name }` 做快照：{ $why }
snapshot-all-or-none = 快照要么包含所有仿真设备，要么一个也不包含
snapshot-family-not-kept = 无法为 `{ $name }` 做快照：快照不保存 { $family } 仿真设备的状态
snapshot-family-not-kept-hint = 保存前关闭它，或不带它保存
snapshot-nothing = 没有打开的仿真设备：无可快照
snapshot-nothing-hint = 快照保存仿真器的状态（sim:MODEL、sim-servo:、sim-fx:、sim-umpk:）；真实设备的状态保存在设备自身
snapshot-has-device = 快照中有此设备
snapshot-not-simulated = `{ $name }` 不是保存快照时那样的 { $family } 仿真设备
snapshot-not-simulated-hint = 以相同名称打开相同的仿真器（例如 --device plc=sim:MODEL）
snapshot-model-differs = { $article ->
    [an] 无法恢复 `{ $name }`：快照来自 { $saved }，而此仿真器是 { $model }
   *[a] 无法恢复 `{ $name }`：快照来自 { $saved }，而此仿真器是 { $model }
}
snapshot-open-as = 以 { $name }={ $scheme }:{ $model } 打开它
snapshot-restoring-wire = 恢复 `{ $name }` 的接线 `{ $wire }`
snapshot-cannot-restore = 无法恢复 `{ $name }`：{ $why }
snapshot-wires-not-back = 恢复 `{ $name }`：其接线未按保存时的样子恢复
snapshot-not-format = 不是 plcsh 快照（格式 `{ $format }`）
snapshot-newer-version = 快照版本为 { $version }，此 plcsh 最多读取版本 { $max }
snapshot-newer-version-hint = 用保存它的较新 plcsh 恢复
snapshot-unknown-section = 快照中 `{ $name }` 有此 plcsh 无法恢复的 `{ $section }` 部分
snapshot-unknown-section-hint = 它由较新的 plcsh 保存；不带该部分恢复将得不到相同的状态
snapshot-save-refused = 无法保存快照：{ $why }
snapshot-save-refused-hint = 未写入任何内容：该文件将无法恢复。这是 plcsh 的缺陷；请连同导致此情况的命令一起报告
snapshot-does-not-read-back = 它无法读回（{ $error }）
snapshot-section-changes = `{ $name }` 的 { $section } 部分读回后与保存时不同：`{ $at }` 改变了
snapshot-cannot-read = 无法读取快照 { $path }
snapshot-cannot-read-hint = 用 `sim snapshots` 列出已保存的快照
snapshot-not-snapshot = { $path } 不是 plcsh 快照
snapshot-no-k2 = 快照中没有 K2 仿真器

## 仿真设备之间的接线（core::wiring、wiring）

wire-not-terminal = `{ $text }` 不是端子：写作 设备:端子
wire-no-device-or-terminal = `{ $text }` 没有指明设备或端子
wire-not-wire = `{ $text }` 不是接线：写作 起点 -> 终点
wire-not-wire-hint = 例如 sim wire plc:Q0.0 -> servo:pulse
wire-no-destination = 接线在 `->` 之后没有终点
wire-options-key-value = `{ $word }`：接线选项写作 键=值
wire-options-short-hint = 选项：lines=N（编码器）、delay=D（回环）
wire-lines-positive = lines={ $value }：每转线数须为正整数
wire-delay-negative = delay={ $value } 为负
wire-delay-too-long = delay={ $value } 超过接线能保存的长度：最多 { $max } µs（约 584 年）
wire-no-option = 接线没有选项 `{ $key }`
wire-options-hint = 选项：lines=N（编码器输出）、delay=D（输出到输入）
wire-cannot-join = { $from } 不能接到 { $to }
wire-cannot-join-hint = 可用的接线：PLC 脉冲输出 -> servo:pulse；servo:encoder -> 两个 PLC 输入（A,B）；servo:target_reached|fault|enabled -> PLC 输入；servo:home@POS|limit+@POS|limit-@POS -> PLC 输入；PLC 输出 -> PLC 输入 [delay=D]
wire-lines-encoder-only = lines= 只用于编码器输出（servo:encoder -> …）
wire-delay-loop-only = delay= 只用于接回 PLC 输入的 PLC 输出
wire-not-position = { $terminal }：`{ $text }` 不是以增量计的位置
wire-only-switches-at = { $terminal }：只有 home、limit+ 和 limit- 开关接受 @POS
wire-unknown-drive-terminal = 未知的驱动器端子 `{ $name }`（{ $terminal }）
wire-drive-terminals-hint = 驱动器端子：pulse、encoder、target_reached、fault、enabled、home@POS、limit+@POS、limit-@POS
wire-describe-pulses = PTO{ $channel } 脉冲（连同其方向输出）到脉冲输入
wire-describe-encoder-lines = 编码器 A/B，每转 { $lines } 线（A/B 周期）
wire-describe-encoder = 编码器 A/B，每个增量四分之一周期
wire-describe-drive-output = { $output ->
    [target-reached] 驱动器输出：到达目标位置（状态字第 10 位）
    [fault] 驱动器输出：故障
   *[enabled] 驱动器输出：运行使能
}
wire-describe-switch = { $switch } 开关位于 { $position } 增量处（也是驱动器自身的输入）
wire-describe-loop = 输出到输入，延时 { $delay } µs
wire-describe-pulse-loop = PTO{ $channel } 输出（脉冲与电平）到输入，延时 { $delay } µs
wire-real-plc = { $name } 是真实的 PLC：接线只连接仿真设备
wire-real-plc-hint = 打开一个仿真器，例如 connect plc sim:K205-16DT
wire-real-drive = { $name } 是真实的驱动器：接线只连接仿真设备
wire-real-drive-hint = 打开一个仿真驱动器，例如 connect servo sim-servo:?id=1
wire-cannot-wire = { $name } 不能接线（只有仿真的 K2 PLC 和驱动器可以）
wire-two-plcs = { $wire }：不仿真两台 PLC 之间的接线；PLC 输出只能接回它自己的输入
wire-two-drives = { $wire }：不仿真驱动器之间的接线
wire-two-drives-hint = 把驱动器接到仿真 PLC
wire-nothing = 没有接线
wire-nothing-hint = sim wire 起点 -> 终点 添加接线，例如 sim wire plc:Q0.0 -> servo:pulse

## 试验台：来自文件的仿真设备（wiring::bench）

bench-no-faults = { $device } 不接受注入的故障（只有仿真的 K2 PLC 和驱动器接受）
bench-shape-hint = 试验台文件包含 [devices] 名称 = "URL"，以及可选的 wires = ["A -> B"]、init = ["DEV:OP=VALUE"]、[programs]、[tags]、[[faults]]
bench-no-devices = 试验台 { $file }：[devices] 为空
bench-cannot-read = 无法读取试验台文件 { $file }
bench-not-simulator = 试验台 { $file }：设备 { $name } = { $url } 不是仿真器
bench-not-simulator-hint = 试验台文件描述的是仿真设备：使用 sim:MODEL 和 sim-servo:?id=N
bench-at-device = 试验台 { $file }，设备 { $name }
bench-at-wire = 试验台 { $file }，接线 { $n } `{ $wire }`
bench-at-init = 试验台 { $file }，init { $n } `{ $item }`
bench-at-fault = 试验台 { $file }，故障 { $n } `{ $fault }`
bench-at-program = 试验台 { $file }，{ $device } 的程序
bench-init-shape = 试验台 { $file }，init { $n }：`{ $item }` 不是 DEVICE:OPERAND=VALUE 形式
bench-fault-on = { $device } 上的故障：{ $what }
bench-program-missing = 试验台 { $file }：{ $device } 的程序 { $program } 不存在
bench-program-unreadable = 试验台 { $file }：无法读取程序 { $program }：{ $error }
bench-program-not-k2 = 试验台 { $file }：程序运行在仿真 K2 中，而 { $device } 不是
bench-program-not-k2-hint = 只为 sim:MODEL 设备指定程序
bench-opened = 试验台 { $name }：{ $devices } 台设备，{ $wires } 条接线，{ $values } 个值
bench-second-plc = 试验台 { $file }：{ $name } 是第二台 PLC；sim serve 只服务一台 PLC
bench-second-line = 试验台 { $file }：{ $name } 在第二条驱动器线路上；sim serve 只服务一条线路
bench-second-line-hint = 把驱动器放在同一条线路上：sim-servo:axis?id=1 和 sim-servo:axis?id=2

## 仿真器中的 PLS：启动什么、为何拒绝（k2::sim::pto；手册 §3.4.2）

k2-pls-refused = PLS { $channel }：{ $reason }；状态位 SM{ $byte }.4 已置位
k2-pls-pwm-cycle-below-two = PWM 周期时间 { $cycle } 小于 2
k2-pls-pwm-cycle-below-two-hint = 设置 SMW{ $register }（2…65535）和更新位 SM{ $control }.0，然后再执行 PLS
k2-pls-cycle-below-two = 周期时间 { $cycle } 小于 2（周期时间和脉冲数都须大于 1，§3.4.2.2）
k2-pls-cycle-below-two-hint = 在 SM{ $control }.0 置位时装入 SMW{ $register }（例如 SMB{ $control }=16#85），然后再执行 PLS
k2-pls-count-below-two = 脉冲数 { $count } 小于 2（周期时间和脉冲数都须大于 1，§3.4.2.2）
k2-pls-count-below-two-hint = 在 SM{ $control }.2 置位时装入 SMD{ $register }（例如 SMB{ $control }=16#85），然后再执行 PLS
k2-pls-what-cycle = 周期时间 { $cycle } { $unit }
k2-pls-what-segment-cycle = 第 { $n } 段周期时间 { $cycle } { $unit }
k2-pls-too-fast = { $what } 即 { $hz } Hz，超过此型号上 { $output } 的上限 { $max } Hz（手册 §3.4）
k2-pls-did-nothing = PLS { $channel } 未执行任何操作：控制字节 SMB{ $control } = 16#{ $value } 的使能位 SM{ $control }.7 为 0，且 PTO{ $channel }（{ $output }）空闲
k2-pls-stopped = { $name } 已停止（{ $what }；使能位 SM{ $control }.7 为 0）
k2-pls-pwm-started = { $update ->
    [sync] { $name }：PWM 周期时间 { $cycle } { $unit }，脉冲宽度 { $width } { $unit }（{ $duty } %），同步更新
   *[async] { $name }：PWM 周期时间 { $cycle } { $unit }，脉冲宽度 { $width } { $unit }（{ $duty } %）
}
k2-pls-pto-started = { $name }：{ $pulses } 个脉冲，共 { $segments } 段，{ $seconds } s
k2-pls-table-even = 包络表起始地址 SMW{ $register } = { $start } 为偶数
k2-pls-table-even-hint = 包络表须从奇数 V 地址开始，例如 SMW{ $register }=3001 对应 VB3001（§3.4.2.1）
k2-pls-table-past-v = 包络表起始地址 VB{ $start } 超出 V 存储区（VB{ $top }）
k2-pls-table-past-v-hint = 让它指向 V 存储区内的奇数地址
k2-pls-table-segments = VB{ $start } 处的包络表有 { $n } 段（允许 1–{ $max } 段）
k2-pls-table-segments-hint = 把段数写入表的第一个字节
k2-pls-table-runs-past = 包络表 VB{ $start }…VB{ $last } 超出 V 存储区
k2-pls-table-runs-past-hint = 移动该表或减少段数
k2-pls-segment-cycle = 第 { $n } 段的周期时间 VW{ $word } = { $cycle } 小于 2
k2-pls-segment-cycle-hint = 周期时间在通道的时基下为 2…65535
k2-pls-segment-count = 第 { $n } 段的脉冲数 VD{ $dword } 为 0
k2-pls-segment-count-hint = 每段至少需要 1 个脉冲
k2-pls-other-channel-hint = SMB{ $control } = 16#{ $value } 已设置：那是 PTO{ $channel } 的控制字节（{ $output }）— 是否想执行 PLS { $channel }？
k2-pls-set-control-hint = 先设置控制字节，例如 set SMB{ $control }=16#85, SMW{ $cycle }=500, SMD{ $count }=1000
k2-pstop = { $what ->
    [none] PSTOP { $channel }：没有正在运行的输出；急停锁存 SM{ $byte }.7 = 1（用 set SM{ $byte }.7=0 清除）
   *[other] PSTOP { $channel }：{ $what } 已停止；急停锁存 SM{ $byte }.7 = 1（用 set SM{ $byte }.7=0 清除）
}

## K2 仿真器：输入、断电保持、选项、注入的故障（k2::sim）

k2-input-driven = { $pin } 由仿真信号驱动（{ $source }）
k2-input-driven-by-wire-hint = 由接线驱动：sim unwire plc:{ $pin }
k2-input-driven-hint = 先停止它：sim input { $pin } off
k2-input-counted-by = 由 HSC{ $n } 计数（模式 { $mode }）
k2-input-above-hsc-limit = 警告：超过 { $model } 上 HSC{ $n } 的 { $max } Hz 上限（§3.3）：真实 PLC 会丢失计数
k2-input-no-source = 没有仿真信号驱动 { $pin }
k2-input-no-source-hint = `sim inputs` 列出信号源
k2-retain-area = { $part }：只有 V、M 和 C 范围可以断电保持
k2-retain-area-hint = 例如 sim retain VB0..VB99 MB0[16] C0..C15
k2-retain-too-much = 请求断电保持 { $bytes } 字节；{ $model } 最多保持 { $room } 字节（手册 §2.1.2）
k2-retain-too-much-hint = 保持更少或更短的范围（一个计数器占 2 字节）
k2-state-not-saved = 仿真器状态未保存：{ $error }
k2-fault-exception = PLC 拒绝了请求：Modbus 异常码 { $code } { $name }（注入的故障 { $id }）
k2-fault-no-power = PLC 无回复：它没有供电（注入的故障 { $id }）
k2-fault-no-power-hint = sim faults 显示何时恢复供电；sim fault clear 立即恢复
k2-fault-no-reply = PLC 无回复（注入的故障 { $id }：{ $name }）
k2-fault-no-reply-hint = sim faults 列出注入的故障；sim fault clear 清除它们
k2-option-backup-last = backup_last={ $value } 不是 V 字节地址
k2-option-program-unreadable = 无法读取程序 { $file }：{ $error }
k2-option-unknown = K2 仿真器没有选项 `{ $key }`
k2-sim-relay-model = { $model } 为继电器输出：没有 PTO/PWM 脉冲输出（手册 §2.2.6）
k2-sim-no-pulse-channel-q05 = { $model } 没有脉冲通道 { $channel }（只有 K209M-56DT 的 Q0.5 是脉冲输出）
k2-sim-pulse-channels-hint = { $model } 的脉冲通道：{ $list }

## K2 仿真器的注入故障（k2::sim::fault、k2::sim::control）

k2-fault-negative = { $key }={ $value }：不能为负
k2-fault-not-input = `{ $text }` 不是输入位（例如 I0.1）
k2-fault-which = 哪个故障？{ $usage }
k2-fault-needs-code = `{ $kind }` 需要一个代码（1…255，例如 2 表示非法数据地址）
k2-fault-not-code = `{ $code }` 不是 Modbus 异常码（1…255）
k2-fault-needs-delay = `{ $kind }` 需要一个延时（例如 late 300ms）
k2-fault-needs-input-level = `{ $kind }` 需要一个输入和电平（stuck I0.1=1）
k2-fault-stuck-shape = `{ $word }`：写作 stuck I0.1=1 或 stuck I0.1=0
k2-fault-not-level = `{ $value }` 不是电平（0 或 1）
k2-fault-needs-input = `{ $kind }` 需要一个输入（noisy I0.1 freq=5kHz）
k2-fault-not-kind = `{ $kind }` 不是故障类型；{ $usage }
k2-fault-on-needs-operands = `on` 需要操作数，例如 on VW100..VW110
k2-fault-spans-areas = `{ $operands }` 跨越多个存储区：请给出一个存储区内的范围
k2-fault-not-option = `{ $word }` 不是选项；{ $usage }
k2-fault-times = times={ $value }：从 1 起的次数
k2-fault-freq-noisy-only = freq= 只用于噪声输入
k2-fault-unknown-option = 未知选项 `{ $key }=`；{ $usage }
k2-fault-noisy-needs-freq = 噪声输入需要 freq=（每秒多少个随机电平），例如 freq=5kHz
k2-fault-at-or-after = 给出 at= 或 after=，不能同时给出
k2-fault-power-loss-needs-for = 断电需要给出时长：power-loss for=5s（之后 PLC 恢复）
k2-fault-power-loss-options = 断电只接受 at=、after= 和 for=（它作用于整个 PLC）
k2-fault-on-request-only = `on` 只用于请求类故障；{ $kind } 指明自己的输入
k2-control-words-hint = 控制字：{ $words }；故障：{ $usage }
k2-control-acts-when-served = （在仿真器被服务时起作用：sim serve --fault … 或其控制通道）
k2-control-empty = 空的控制行
k2-control-unknown-word = `{ $word }` 不是 K2 仿真器的控制字

## K2 的线路驱动：Modbus 回复与辅助程序邮箱（k2::driver）

k2-reply-bad-crc = 收到 CRC 校验码错误的回复：{ $frame }（CRC { $got }，这些字节应为 { $want }）
k2-reply-bad-crc-received = 收到 CRC 校验码错误的回复：{ $frame }（CRC { $got }，这些字节应为 { $want }）；已接收：{ $received }
k2-reply-no-frame = 收到 { $n } 个字节，但没有有效的回复帧；已接收：{ $received }
k2-not-k2-request = { $request } 不是 K2 请求
k2-reply-function-code = 对功能码 { $want } 的请求收到功能码 { $got } 的回复
k2-reply-unit = 对站号 { $want } 的请求收到站号 { $got } 的回复
k2-reply-not-tcp = 回复头不是 Modbus TCP：{ $header }
k2-reply-transaction = 对事务 { $want_tid }、站号 { $want_unit } 收到事务 { $tid }、站号 { $unit } 的回复
k2-no-more-replies = 没有更多回复
k2-reply-malformed = 对 { $request } 的回复格式错误：{ $data }
k2-reply-read-short = 读取 { $table } { $addr } 的回复太短
k2-mailbox-refused = { $doing ->
    [reading] PLC 拒绝读取辅助程序邮箱：{ $name }（Modbus 异常码 { $code }）
   *[writing] PLC 拒绝写入辅助程序邮箱：{ $name }（Modbus 异常码 { $code }）
}
k2-mailbox-refused-hint-2 = 检查 agent=VB… 是否位于此型号的 V 存储区内
k2-mailbox-refused-hint-4 = PLC 报告设备故障：检查其错误指示灯和诊断信息，然后重试
k2-mailbox-refused-hint = 检查这是否是 PLC 的 Modbus 端口和站号（plcsh probe URL 会显示它的应答）
k2-mailbox-unexpected-reply = 读取辅助程序邮箱时收到意外的回复 { $reply }
k2-needs-helper = { $what } 需要 PLC 中的 plcsh 辅助程序；此设备未配置
k2-needs-helper-hint = 安装 lib/k2_agent.il（docs/agent.md），并用 …&agent=VB3400 连接
k2-no-helper = 此设备未配置辅助程序
k2-no-helper-hint = 用 …&agent=VB3400 连接
k2-helper-status = 辅助程序协议 { $version }，位于 VB{ $base }，心跳 { $heartbeat }，上一条命令 { $seq }（结果 { $result }）
k2-done-by-helper = { $what }：由辅助程序完成
k2-rtc-reply-short = 辅助程序对 READ_RTC 的回复短于 8 字节
k2-rtc-reads-as = PLC 实时时钟读数为 { $value }

## 仿真器中的高速计数器：HDEF、HSC、PV 表（k2::sim::hsc；手册 §3.3）

k2-hsc-table-even = PV 表起始地址 { $start } 为偶数（须为奇数 V 偏移，§3.3.2）
k2-hsc-table-past-v = PV 表起始地址 VB{ $start } 超出 V 存储区
k2-hsc-table-count = VB{ $start } 处的 PV 表有 { $n } 个 PV（允许 1–{ $max } 个）
k2-hsc-table-runs-past = VB{ $start } 处的 PV 表超出 V 存储区
k2-hsc-table-empty = VB{ $start } 处的 PV 表在第一个 PV 之前就结束了（|PV| 须 > 1）
k2-hsc-no-mode-yet = HSC{ $n } 尚未设定模式
k2-hsc-no-mode-yet-hint = 先执行 `hdef { $n } MODE`（HDEF，手册 §3.3.5）；模式：{ $list }
k2-hsc-stopped = HSC{ $n } 已停止（使能位 SM{ $control }.7 为 0）；CV { $cv }
k2-hsc-table-fault = PV 表故障（SM{ $status }.3 = 1）：{ $reason }
k2-hsc-table-fault-none = PV 表故障（SM{ $status }.3 = 1）：未装入表；置位 SM{ $mpv }.4 以装入 SMW{ $table } 处的表
k2-hsc-counting-table = { $kind ->
    [relative-cyclic] { $n } 个相对 PV（循环），下一个 CV = PV 在 { $target }
    [relative] { $n } 个相对 PV，下一个 CV = PV 在 { $target }
    [absolute-cyclic] { $n } 个绝对 PV（循环），下一个 CV = PV 在 { $target }
   *[absolute] { $n } 个绝对 PV，下一个 CV = PV 在 { $target }
}
k2-hsc-counting-no-table = 没有 PV 表
k2-hsc-counting = HSC{ $n } 以模式 { $mode } 从 CV { $cv } 开始计数；{ $compare }

## 仿真器的状态文件（k2::sim::state）

k2-backup-end = E2PROM 备份区结束于 VB{ $default }（默认）… VB{ $max }，不能是 VB{ $last }
k2-backup-end-hint = 手册 §2.2.8：默认 VB3648–VB3902，可扩展到 VB4095
k2-state-invalid = 状态文件 { $file } 无效
k2-state-invalid-hint = 把它移走，以全新状态开始
k2-state-unreadable = 无法读取状态文件 { $file }
k2-state-cannot-encode = 无法编码状态
k2-state-in-use = 状态文件 { $file } 正被另一个进程使用
k2-state-in-use-by = 状态文件 { $file } 正被进程 { $pid } 使用
k2-state-in-use-hint = 每个状态文件只能有一个 plcsh：给这个 plcsh 单独的文件（--state FILE）或不用文件（--state none），或停止另一个

## PLC 端子上的接线、断点（k2::sim::wired、k2::sim::program::debug）

wire-not-plc-terminal = { $model }：`{ $terminal }` 不是 PLC 端子
wire-plc-terminals-hint = PLC 端子：Q0.0（输出）、Q0.0,Q0.2（脉冲 + 方向）、I0.3（输入）、I0.1,I0.0（A,B）
wire-no-pulse-output = { $model } 在 { $pin } 上没有脉冲输出
wire-no-pulse-output-hint = 脉冲 + 方向的一对以 PTO 输出开头（Q0.0 PTO0、Q0.1 PTO1 …）
wire-a-b-same = A 和 B 都是 { $pin }
wire-ends = { $wire }：两端在同一设备上，或都不在 PLC 上
wire-ends-hint = 把 PLC 端子接到驱动器端子，或把 PLC 输出接到 PLC 输入
wire-nothing-short-hint = sim wire 起点 -> 终点 添加接线
wire-none-touches = 没有接线涉及 `{ $which }`
wire-list-hint = 接线：{ $list }
k2-no-program = 未装入程序
k2-no-program-hint = sim program load FILE.il
k2-no-network = { $source } 中没有网络 { $n }
k2-no-network-hint = 网络由 `(* Network n *)` 注释或 NETWORK 行编号
k2-not-breakpoint = `{ $spec }` 不是断点
k2-no-instruction-after = { $source } 在第 { $line } 行及之后没有指令
k2-breakpoint-at = 断点位于 { $source }:{ $line }：{ $text }

## 中断事件、时钟及连接不支持的操作（k2::instr、k2）

k2-event-pto-complete = PTO{ $channel } 完成
k2-event-cv-eq-pv-multi = HSC{ $channel } CV = PV{ $k }（多 PV）
k2-event-cv-eq-pv = HSC{ $channel } CV = PV（单 PV）
k2-event-hsc-reset = HSC{ $channel } 外部复位
k2-event-hsc-direction = { $dir ->
    [up] HSC{ $channel } 计数方向变为增计数
   *[down] HSC{ $channel } 计数方向变为减计数
}
k2-event-eeprom-wear = E2PROM 字节 VB{ $byte } 已写入 { $writes } 次（寿命约 1 000 000 次，§2.2.8）
k2-event-fault = 注入的故障 { $id }（{ $name }）起作用
k2-rtc-not-datetime = `{ $text }` 不是日期时间；写作 2026-11-22T10:00:00
k2-rtc-year = 年份 { $year } 不在 2000–2099 之内（时钟只保存两位数字）
k2-rtc-month = 月份 { $month } 不在 1–12 之内
k2-rtc-day = { $month } 的日期 { $day } 不在 1–{ $days } 之内
k2-rtc-time = { $time } 不是一天中的时间
k2-rtc-not-bcd = 16#{ $value } 不是 BCD 字节
k2-what-event-access = 中断事件访问
k2-what-helper-status = 辅助程序状态
k2-not-here = { $what } 在此连接上不可用
k2-not-here-hint = 仿真器可以执行它；在真实 PLC 上需要 PLC 端的辅助程序
k2-no-longer-k2 = 该设备不再以 K2 PLC 应答
snapshot-not-name = `{ $name }` 不是快照名（拉丁字母 A-Z a-z、数字、_ - .）
snapshot-not-name-hint = 或给出以 .json 结尾的文件路径
snapshot-no-data-dir = 没有保存快照的数据目录
snapshot-no-data-dir-hint = 给出以 .json 结尾的文件路径

## K2 仿真器中 IL 程序的操作数与指令（k2::sim::program）

k2-program-one-location = 程序操作数是一个位置，而不是范围
k2-program-bit-group = { $operand } 是位组；程序按字节、字和位寻址
k2-program-bit-group-hint = 在程序中使用 MW/VW 字或 M/V 位
k2-program-not-element = { $what ->
    [timer] { $operand } 不是定时器
   *[counter] { $operand } 不是计数器
}
k2-program-timers-hint = 定时器为 T0…T255
k2-program-counters-hint = 计数器为 C0…C255
k2-program-clock-buffer = 8 字节的时钟缓冲区放不下
k2-program-unknown-instruction = 未知的系列指令 { $id }

## 从快照恢复 K2 仿真器（k2::sim::snapshot）

k2-snapshot-model = 快照来自 { $saved }，而此仿真器是 { $model }
k2-snapshot-area-hex = 存储区 { $area } 不是十六进制
k2-snapshot-area-size = 存储区 { $area } 有 { $n } 字节，而 { $model } 有 { $want } 字节
k2-snapshot-element-counts = 定时器或计数器的数量与型号不符
k2-snapshot-channel-counts = 脉冲输出或计数器的数量与型号不符
k2-snapshot-no-area = 没有存储区 { $area }
k2-snapshot-helper-program = 辅助程序：{ $error }
k2-snapshot-program = 快照中的程序 { $source }：{ $error }
k2-snapshot-halt = 快照中的 DEBUG 暂停位于第 { $at } 条指令，而程序只有 { $n } 条
k2-snapshot-breakpoint = 快照中的断点位于第 { $at } 条指令，而程序只有 { $n } 条

## 仿真输入信号、辅助程序邮箱、被服务的仿真器（k2::sim）

k2-hsc-snapshot-mode = HSC{ $n } 没有模式 { $mode }
k2-source-square = { $pin } 方波 { $freq }
k2-source-quadrature = A/B 正交信号，{ $lead } 超前 { $lag }，{ $freq }
k2-source-train = { $pin } 脉冲串，{ $pulses } 个脉冲，每个 { $cycle } ns
k2-source-encoder = 编码器 A 接 { $a }，B 接 { $b }
k2-helper-mailbox-address = 辅助程序邮箱需要一个偶数 V 地址，且其后到 VB{ $top } 有 { $size } 字节空闲（得到 VB{ $base }）
k2-serve-accept-retry = 暂时无法接受连接（{ $error }）；正在重试
k2-serve-stream-closed = 数据流已关闭
