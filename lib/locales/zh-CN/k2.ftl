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
