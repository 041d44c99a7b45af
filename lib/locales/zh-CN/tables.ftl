# plcsh messages (zh-CN): tables — SM 字节、伺服对象、指令与元件的说明. Same ids and arguments in en, ru and zh-CN
# (tests/messages.rs).

## K2 special memory (src/k2/sm_map.rs; K2 manual §3.3.2, §3.3.3, §3.4.2.2, §3.4.3.1)

tbl-sm-pos-cv-read-only = SMD{ $cv } 是位置通道 { $n } 的当前值，只读（手册 §3.4.3.1）
tbl-sm-pos-cv-overlap = { $written } 与 SMD{ $cv } 重叠，SMD{ $cv } 是位置通道 { $n } 的只读当前值（手册 §3.4.3.1）
tbl-sm-pos-cv-read-only-hint = 通过 SMD{ $new } 和 SM{ $control }.4 装入新值（set SMD{ $new }=100, SM{ $control }.4=1），或用 SM{ $control }.6 清零
tbl-sm-pls-did-nothing = PLS { $n } 未执行任何操作：控制字节 SMB{ $control } 的使能位 SM{ $control }.7 为 0，且 PTO{ $n } 处于空闲
tbl-sm-pls-did-nothing-hint = 设置 SMB{ $control }=16#85（使能、PTO、更新周期时间和脉冲数）、SMW{ $cycle } 和 SMD{ $count }，然后执行 PLS { $n }
tbl-sm-smb0-read-only = { $written } 存放系统状态位，只读
tbl-sm-smb0-read-only-hint = SM0.0 始终为 1，SM0.1 标记第一次扫描，SM0.5 是 1 秒时钟
tbl-hsc-mode-0-0 = 计数 I0.1，方向由 SM37.3 决定
tbl-hsc-mode-0-1 = 计数 I0.1，复位 I0.0，方向由 SM37.3 决定
tbl-hsc-mode-0-2 = 计数 I0.1，复位 I0.0，启动 I0.5，方向由 SM37.3 决定
tbl-hsc-mode-0-3 = 计数 I0.1，方向输入 I0.5
tbl-hsc-mode-0-4 = 计数 I0.1，方向输入 I0.5，复位 I0.0
tbl-hsc-mode-0-6 = 增计数 I0.0 / 减计数 I0.1（双脉冲）
tbl-hsc-mode-0-9 = AB相正交，A = I0.1，B = I0.0
tbl-hsc-mode-1-0 = 计数 I0.3，方向由 SM47.3 决定
tbl-hsc-mode-1-1 = 计数 I0.3，复位 I0.4，方向由 SM47.3 决定
tbl-hsc-mode-1-2 = 计数 I0.3，复位 I0.4，启动 I0.6，方向由 SM47.3 决定
tbl-hsc-mode-1-3 = 计数 I0.3，方向输入 I0.2
tbl-hsc-mode-1-4 = 计数 I0.3，方向输入 I0.2，复位 I0.4
tbl-hsc-mode-1-6 = 增计数 I0.2 / 减计数 I0.3（双脉冲）
tbl-hsc-mode-1-7 = 增计数 I0.2 / 减计数 I0.3（双脉冲），复位 I0.4
tbl-hsc-mode-1-9 = AB相正交，A = I0.3，B = I0.2
tbl-hsc-mode-1-10 = AB相正交，A = I0.3，B = I0.2，复位 I0.4
tbl-hsc-mode-2-0 = 计数 I0.5，方向由 SM57.3 决定
tbl-hsc-mode-2-9 = AB相正交，A = I0.4，B = I0.5
tbl-hsc-mode-3-0 = 计数 I0.7，方向由 SM127.3 决定
tbl-hsc-mode-3-9 = AB相正交，A = I0.6，B = I0.7
tbl-sm-smb0 = 系统状态位（只读）
tbl-sm-sm0-0 = 始终为 1
tbl-sm-sm0-1 = 仅在第一次扫描时为 1
tbl-sm-sm0-5 = 1 秒时钟（0.5 秒为 1，0.5 秒为 0）
tbl-sm-sm0-6 = 每次扫描翻转
tbl-sm-pto-control = PTO{ $n }/PWM{ $n }（{ $q }）控制字节
tbl-sm-pto-control-0 = PTO{ $n } 控制：更新周期时间
tbl-sm-pto-control-1 = PTO{ $n } 控制：更新脉冲宽度（PWM）
tbl-sm-pto-control-2 = PTO{ $n } 控制：更新脉冲数（PTO）
tbl-sm-pto-control-3 = PTO{ $n } 控制：时基：0 = 1 µs，1 = 1 ms
tbl-sm-pto-control-4 = PTO{ $n } 控制：PWM 更新方式：0 异步，1 同步
tbl-sm-pto-control-5 = PTO{ $n } 控制：PTO 模式：0 单段，1 多段
tbl-sm-pto-control-6 = PTO{ $n } 控制：功能：0 PTO，1 PWM
tbl-sm-pto-control-7 = PTO{ $n } 控制：使能
tbl-sm-pto-status = PTO{ $n }/PWM{ $n }（{ $q }）状态字节
tbl-sm-pto-status-3 = PTO{ $n } 状态：PWM 空闲
tbl-sm-pto-status-4 = PTO{ $n } 状态：周期时间或脉冲数无效（必须大于 1）
tbl-sm-pto-status-5 = PTO{ $n } 状态：包络被用户命令中止
tbl-sm-pto-status-7 = PTO{ $n } 状态：PTO 空闲
tbl-sm-pto-cycle = PTO{ $n }/PWM{ $n } 周期时间（2…65535，以时基为单位）
tbl-sm-pwm-width = PWM{ $n } 脉冲宽度（0…65535，以时基为单位）
tbl-sm-pto-count = PTO{ $n } 脉冲数（≥ 2）
tbl-sm-pto-profile = PTO{ $n } 多段包络表首地址（V 区奇数偏移）
tbl-sm-pos-cv = 位置通道 { $n } 当前值，脉冲数（只读）
tbl-sm-pos-new-cv = 位置通道 { $n } 新当前值（由 SMB{ $control } 的位 4 装入）
tbl-sm-pos-control = 位置通道 { $n } 控制字节
tbl-sm-pos-control-7 = 位置通道 { $n } 控制：急停已锁存（由 PSTOP 置位）
tbl-sm-pos-control-6 = 位置通道 { $n } 控制：清除当前值
tbl-sm-pos-control-4 = 位置通道 { $n } 控制：装入新当前值
tbl-sm-pos-control-3 = 位置通道 { $n } 控制：禁止方向输出
tbl-sm-hsc-control = HSC{ $n } 控制字节
tbl-sm-hsc-control-0 = HSC{ $n } 控制：复位有效电平（0 高，1 低）
tbl-sm-hsc-control-1 = HSC{ $n } 控制：启动有效电平（0 高，1 低）
tbl-sm-hsc-control-2 = HSC{ $n } 控制：正交倍频（0 = 1倍频，1 = 4倍频）
tbl-sm-hsc-control-3 = HSC{ $n } 控制：计数方向（0 减计数，1 增计数）
tbl-sm-hsc-control-4 = HSC{ $n } 控制：写入计数方向
tbl-sm-hsc-control-5 = HSC{ $n } 控制：写入新设定值
tbl-sm-hsc-control-6 = HSC{ $n } 控制：写入新当前值
tbl-sm-hsc-control-7 = HSC{ $n } 控制：使能
tbl-sm-hsc-status = HSC{ $n } 状态字节
tbl-sm-hsc-status-3 = HSC{ $n } 状态：多 PV 表故障
tbl-sm-hsc-status-5 = HSC{ $n } 状态：当前计数方向（1 增计数）
tbl-sm-hsc-status-6 = HSC{ $n } 状态：CV = PV
tbl-sm-hsc-status-7 = HSC{ $n } 状态：CV > PV
tbl-sm-hsc-cv = HSC{ $n } 当前值（CV）
tbl-sm-hsc-pv = HSC{ $n } 设定值（PV，单 PV 模式）
tbl-sm-hsc-mpv-control = HSC{ $n } 多 PV 控制字节
tbl-sm-hsc-mpv-control-0 = HSC{ $n } 多 PV 控制：使用多个 PV
tbl-sm-hsc-mpv-control-1 = HSC{ $n } 多 PV 控制：PV 类型（0 绝对，1 相对）
tbl-sm-hsc-mpv-control-2 = HSC{ $n } 多 PV 控制：循环 CV=PV 中断（仅相对值）
tbl-sm-hsc-mpv-control-4 = HSC{ $n } 多 PV 控制：装入 PV 表
tbl-sm-hsc-mpv-control-5 = HSC{ $n } 多 PV 控制：复位中断变量（0 是，1 否）
tbl-sm-hsc-table = HSC{ $n } PV 表首地址（V 区奇数偏移）
tbl-sm-hsc-segment = HSC{ $n } 当前 PV 段号（从 0 开始）

## Servo object dictionary (src/servo/objects.rs; Kinco servo RS232 protocol, CiA 402)

tbl-servo-not-in-table = 不在对象表中
tbl-servo-object-missing = 缺少对象（例如 controlword 或 6040.00）
tbl-servo-not-a-type = `/{ $suffix }` 不是对象类型
tbl-servo-not-a-type-hint = 请使用 /u8、/i8、/u16、/i16、/u32 或 /i32
tbl-servo-not-an-object = `{ $text }` 不是伺服对象
tbl-servo-suffix-size = { $name }（{ $address }）为 { $bits } 位；/{ $suffix } 为 { $suffix_bits } 位
tbl-servo-suffix-size-hint = 去掉后缀，或使用 /{ $suffix }
tbl-servo-size-unknown = { $address } 不在对象表中，因此长度未知
tbl-servo-size-unknown-hint = 请加类型后缀，例如 { $address }/u16（u8、i8、u16、i16、u32、i32）
tbl-servo-suggest-none = `help servo` 或补全可列出对象；表外对象写作 6040.00
tbl-servo-suggest = 是否要输入 { $names }？
tbl-servo-read-only = { $name }（{ $address }）为只读
tbl-servo-read-only-hint = 请用 get 读取；驱动器会回复 0x80（试图写只读对象）
tbl-servo-far-too-large = { $text } 远超 { $dtype } 的范围（{ $lo }…{ $hi }）
tbl-servo-does-not-fit = { $text } = { $raw } 超出 { $dtype } 的范围（{ $lo }…{ $hi }）
tbl-servo-resolution-hint = 反馈精度为 { $resolution } inc/圈
tbl-servo-help-type = 类型 { $dtype }（{ $bits } 位），范围 { $lo }…{ $hi }
tbl-servo-help-access = 访问 { $access }
tbl-servo-help-access-unit = 访问 { $access }，单位 { $unit }
tbl-servo-help-access-unit-example = 访问 { $access }，单位 { $unit }（可写作 { $name }=300{ $eng }；反馈精度 { $resolution } inc/圈）
tbl-servo-help-source = 来源：{ $source }
tbl-servo-controlword = DS402 控制字：0x06 关闭（shutdown），0x07 启动（switch on），0x0F 使能运行，位 4 新设定点，位 5 立即更新设定，位 6 相对，位 7 故障复位，位 8 暂停（halt），位 12 Kinco 写目标即启动（0x103F）
tbl-servo-statusword = DS402 状态字：状态位 0-6，位 10 目标到达，位 11 内部限制，位 12 设定点确认/回原点完成，位 13 跟随误差/回原点错误，位 15 Kinco 找到原点
tbl-servo-error-code = 最近的故障代码（DS402；0 = 无故障）
tbl-servo-quickstop-option = 快速停止选项码：0 自由停车，1/2 按梯形减速度/快速停止减速度停止后进入禁止启动，5/6 同上但保持快速停止状态
tbl-servo-shutdown-option = 关闭选项码（仅保存；仿真器立即停止）
tbl-servo-disable-option = 禁止运行选项码（仅保存；仿真器立即停止）
tbl-servo-halt-option = 暂停选项码：1 按梯形减速度停止，2 按快速停止减速度停止
tbl-servo-fault-reaction-option = 故障反应选项码（仅保存；仿真器立即停止）
tbl-servo-operating-mode = 工作模式：1 位置模式，3 速度模式，-3 立即速度模式，4 转矩模式，6 回原点，-4 脉冲模式
tbl-servo-mode-display = 当前生效的工作模式（DS402；在 Kinco 上未确认）
tbl-servo-position-actual = 实际位置（Kinco 驱动器使用 6063，而非 6064）
tbl-servo-position-actual-value = DS402 编号的实际位置（仿真器中与 6063 相同；在 Kinco 上未确认）
tbl-servo-max-following-error = 跟随误差窗口：跟随误差超出该值的时间长于 6066.00 时驱动器报故障（0x8611）
tbl-servo-following-error-timeout = 跟随误差超时，ms
tbl-servo-position-window = 目标到达的位置窗口
tbl-servo-velocity-actual = 实际速度
tbl-servo-target-torque = 目标转矩（单位未确认）
tbl-servo-max-current = 最大电流指令（单位未确认）
tbl-servo-torque-actual = 实际转矩（单位未确认）
tbl-servo-current-actual = 实际电流（单位未确认）
tbl-servo-target-position = 位置模式的目标位置
tbl-servo-home-offset = 原点偏移：回原点后赋给原点的位置
tbl-servo-soft-limit-pos = 软件位置限位 +（依据 notes 和 C# 客户端；CiA 402 称子索引 1 为最小限位，请核对驱动器）；+ <= - 时限位无效
tbl-servo-soft-limit-neg = 软件位置限位 -（依据 notes 和 C# 客户端；CiA 402 称子索引 2 为最大限位，请核对驱动器）
tbl-servo-polarity = 方向：0 逆时针（CCW）为正，1 顺时针（CW）为正
tbl-servo-max-speed = 最大速度（单位未确认）
tbl-servo-profile-velocity = 位置运动的梯形速度
tbl-servo-profile-acceleration = 梯形加速度
tbl-servo-profile-deceleration = 梯形减速度
tbl-servo-quickstop-deceleration = 快速停止使用的减速度
tbl-servo-homing-method = 回原点方式：17/18 负/正限位开关，19-22 原点开关，33/34 索引脉冲，35/37 当前位置（CiA 402 编号）
tbl-servo-homing-speed-switch = 寻找开关时的回原点速度
tbl-servo-homing-speed-zero = 寻找零点时的回原点速度
tbl-servo-homing-offset-mode = Kinco 原点偏移模式：0 原点为位置 0，1 原点为偏移值（仅保存；未确认）
tbl-servo-homing-acceleration = 回原点加速度
tbl-servo-following-error-actual = 实际跟随误差（仿真为速度 x 2 ms）
tbl-servo-digital-inputs = 开关量输入：位 0 负限位，位 1 正限位，位 2 原点，位 3 硬件锁
tbl-servo-digital-outputs = 开关量输出（DS402 物理输出；仅保存）
tbl-servo-target-velocity = 速度模式 3 和 -3 的目标速度
tbl-servo-brake-resistor = 制动电阻阻值
tbl-servo-brake-resistor-power = 制动电阻功率
tbl-servo-brake-resistor-time = 制动电阻时间常数
tbl-servo-velocity-kp = 速度环比例增益（仅保存）
tbl-servo-velocity-ki = 速度环积分增益（仅保存）
tbl-servo-position-kp = 位置环比例增益（仅保存）
tbl-servo-drive-id = RS232 设备站号（默认 1；重启后生效）
tbl-servo-din-polarity = 开关量输入极性（仅保存）
tbl-servo-din-simulate = 模拟开关量输入（仅保存）
tbl-servo-din1-function = DIN1 功能（仅保存；据一个公开的 C++ 客户端，0x10 正限位，0x20 负限位，未确认）
tbl-servo-din2-function = DIN2 功能（仅保存）
tbl-servo-din3-function = DIN3 功能（仅保存）
tbl-servo-din4-function = DIN4 功能（仅保存）
tbl-servo-din-real = 实际接线的开关量输入（仿真器映射 60FD.00 的位 0-2）
tbl-servo-dout1-function = DOUT1 功能（仅保存）
tbl-servo-dout2-function = DOUT2 功能（仅保存）
tbl-servo-dout-real = 实际驱动的开关量输出
tbl-servo-gear-factor = 电子齿轮分子（脉冲模式 -4）
tbl-servo-gear-divider = 电子齿轮分母（脉冲模式 -4；不接受 0）
tbl-servo-pulse-mode = 脉冲输入模式：0 CW/CCW，1 脉冲+方向，2 A/B（4倍频，未确认）
tbl-servo-pulse-filter = 脉冲输入滤波（仅保存）
tbl-servo-pulse-frequency-control = 脉冲频率控制
tbl-servo-master-speed = 脉冲输入频率（单位未确认；仿真器：脉冲/ms）
tbl-servo-error-state = Kinco 故障状态（位含义未确认；故障时仿真器置位 0）
tbl-servo-baud-code = RS232 波特率代码：1080 = 9600，540 = 19200，270 = 38400（默认），90 = 115200；重启后生效
tbl-servo-store-parameters = 写 1 保存全部参数
tbl-servo-store-motor-data = 写 1 保存电机数据
tbl-servo-display-select = 数码管显示设定
tbl-servo-target-speed-rpm = 以 rpm 为单位的目标速度（FD5P 手册的 RS232 示例用 4 字节写入 600，再以 2 字节回复 4B 读回；仿真器保存该值）
tbl-servo-user-password = 用户密码
tbl-servo-encoder-resolution = DEC 公式使用的反馈精度（编码器分辨率），每圈增量数

## Servo engineering units (src/servo/units.rs; kinco-servo.md §4)

tbl-unit-bad-resolution = 反馈精度 `{ $text }` 不是 1…{ $max } 内的整数（每圈增量数，例如 10000 或 65536）
tbl-unit-unknown-speed = 此处不识别单位 `{ $unit }`；速度请写 rpm 或 dec（驱动器单位）：{ $number }rpm
tbl-unit-unknown-accel = 此处不识别单位 `{ $unit }`；加速度请写 rps/s 或 dec（驱动器单位）：{ $number }rps/s
tbl-unit-unknown-position = 此处不识别单位 `{ $unit }`；位置请写 rev 或 inc：{ $number }rev
tbl-unit-not-a-number = `{ $number }` 不是数字（请写作例如 300{ $suffix }）
tbl-unit-takes = 此对象接受 { $raw } 或 { $eng }，不接受 { $suffix }
tbl-unit-takes-plain = 此对象只接受普通数字，不接受 { $suffix }
tbl-unit-not-whole = { $number }{ $suffix } 不是整数个 { $suffix }

## K2 model catalogue (src/k2/catalog.rs; K2 manual §1.2, §2.1.2, §2.2.6, §3.4)

tbl-model-unknown = 未知的 K2 型号 `{ $name }`
tbl-model-unknown-hint = 目录中的型号：{ $models }
tbl-model-k204et-1-what = HSC2/HSC3 最高频率
tbl-model-k204et-1-chosen = 单相和 AB 相均为 200 kHz（§2.2.6）
tbl-model-k204et-1-other = §2.1.2 在 CPU204 一栏列出单相 20 kHz / AB 相 10 kHz（该栏似乎错位：与 §2.2.6 中 CPU209EA 一行相符）
tbl-model-k204et-2-what = Q0.4 最高频率
tbl-model-k204et-2-chosen = 200 kHz（§2.2.6，§3.4）
tbl-model-k204et-2-other = §2.1.2 在 CPU204 一栏列出 10 kHz
tbl-model-k209ea-1-what = Q0.4 最高频率
tbl-model-k209ea-1-chosen = 10 kHz（§2.2.6，§3.4）
tbl-model-k209ea-1-other = §2.1.2 在 CPU209EA 一栏列出 Q0.0、Q0.1、Q0.4 为 200 kHz，并有第四个输出 Q0.5（似乎是错位的 CPU209M 条目）
tbl-model-k209ea-2-what = 高速计数器数量
tbl-model-k209ea-2-chosen = 4（§2.2.6 给出了 K209EA 的 HSC2/HSC3 频率）
tbl-model-k209ea-2-other = §2.1.2 在 CPU209EA 一栏印为 2（似乎是错位的 CPU209M 条目）
tbl-model-k205ea-1-what = HSC 和脉冲输出频率
tbl-model-k205ea-1-chosen = 所有通道 200 kHz（§2.1.2 是唯一列出 CPU205EA 的表）
tbl-model-k205ea-1-other = §2.2.6 和 §3.4 未列出 CPU205EA

## Servo drive state machine (src/servo/ds402.rs; CiA 402 as the Kinco manual follows it). The CiA 402
## state and command names (operation enabled, switch on …) stay as they are: JSON reports carry them.

tbl-ds402-does-not-fit = { $value } 超出 { $name } 的范围（{ $lo }…{ $hi }）
tbl-ds402-or = { $a } 或 { $b }
tbl-ds402-step-stuck = { $what }（controlword 16#{ $cw }）未到达 { $want }：statusword 16#{ $sw } = { $state }
tbl-ds402-step-stuck-unknown = { $what }（controlword 16#{ $cw }）未到达 { $want }：statusword 16#{ $sw } = 未知状态
tbl-ds402-in-fault-hint = 驱动器处于故障：请执行 servo fault-reset
tbl-ds402-check-status-hint = 请查看 servo status
tbl-ds402-in-fault = 驱动器处于故障（statusword 16#{ $sw }）
tbl-ds402-in-fault-enable-hint = 请执行 servo fault-reset，再执行 servo enable
tbl-ds402-mode-readback = 写入工作模式 { $mode } 后读回 { $got }
tbl-ds402-not-enabled = { $what ->
    [move] 无法运动
    [jog] 无法点动
    [home] 无法回原点
    [halt] 无法暂停（halt）
    [release-halt] 无法解除暂停（halt）
   *[other] 无法执行 { $what }
}：驱动器处于“{ $state }”（statusword 16#{ $sw }）
tbl-ds402-not-enabled-unknown = { $what ->
    [move] 无法运动
    [jog] 无法点动
    [home] 无法回原点
    [halt] 无法暂停（halt）
    [release-halt] 无法解除暂停（halt）
   *[other] 无法执行 { $what }
}：驱动器处于未知状态（statusword 16#{ $sw }）
tbl-ds402-not-enabled-hint = 请先执行 servo enable
tbl-ds402-buffer-full = 驱动器的设定点缓冲区持续满 { $seconds } 秒（statusword 16#{ $sw }，位 12 为 1 而位 4 为 0）
tbl-ds402-buffer-full-hint = 等待正在进行的运动结束（servo wait target），再重新运动
tbl-ds402-no-ack = 驱动器未确认设定点（statusword 16#{ $sw }，位 12 为 0）
tbl-ds402-fault-while-waiting = 等待期间驱动器进入故障（statusword 16#{ $sw }）
tbl-ds402-fault-while-waiting-hint = servo status 显示状态；servo fault-reset 清除故障
tbl-ds402-homing-error = 回原点以回原点错误结束（statusword 16#{ $sw }，位 13）
tbl-ds402-homing-error-hint = 请检查回原点方式（6098.00）和开关；servo status 显示各位
tbl-ds402-target-timeout = { $seconds } 秒内未到达目标（statusword 16#{ $sw }）
tbl-ds402-target-timeout-at = { $seconds } 秒内未到达目标（statusword 16#{ $sw }，position_actual { $position }）
tbl-ds402-target-timeout-hint = 加长 timeout=，或用 servo status 查看原因

## The sandbox of graded and confined runs (src/confine.rs): bench actions a lab grants by name, and refusals

tbl-bench-refused = 被评分的提交不能使用 `{ $what }`：该操作改变实验台本身，而不是控制它（{ $why }）
tbl-bench-refused-hint = 提交像程序在真实设备上那样控制实验设备；需要此操作的实验可在 lab.toml 中授权：grants = ["{ $what }"]
tbl-bench-other = 改变实验台
tbl-confine-no-write = 沙箱运行中不允许写入 { $path }
tbl-confine-no-write-hint = 为运行指定文件目录：plcsh run --sandbox --write-dir DIR
tbl-confine-write-outside = 写入的 { $path } 在 { $dir } 之外
tbl-confine-write-outside-hint = 沙箱运行只写入其 --write-dir 之下
tbl-confine-real-device = { $url } 是真实设备：沙箱运行只打开仿真设备
tbl-confine-real-device-hint = 在沙箱中请使用 sim:MODEL、sim-servo:、sim-umpk:MODEL 或 sim-fx:MODEL
tbl-confine-read-outside = 读取的 { $path } 在沙箱的目录之外
tbl-confine-read-outside-hint = 沙箱运行只读取 { $folders } 之下的文件
tbl-confine-named-snapshot = 命名快照 `{ $name }` 位于用户数据目录，沙箱运行不能访问该目录
tbl-confine-named-snapshot-hint = 请给出写入目录下的文件路径，例如 out/start.json
tbl-confine-no-folder = 无目录
tbl-bench-sim-clock = 显示或更改仿真器的时钟模式
tbl-bench-sim-input = 驱动仿真的输入信号
tbl-bench-sim-quad = 驱动仿真的编码器
tbl-bench-sim-inputs = 列出仿真的输入信号
tbl-bench-sim-retain = 更改电池供电保持的范围
tbl-bench-sim-program = 装入、卸载或读取 PLC 的程序
tbl-bench-sim-cpu = 运行或停止 PLC 的 CPU
tbl-bench-sim-stop = 使 PLC 的 CPU 进入 STOP
tbl-bench-sim-pause = 暂停 PLC 的 CPU
tbl-bench-sim-switch = 拨动 PLC 的 RUN/STOP 开关
tbl-bench-sim-scan = 手动执行 PLC 扫描
tbl-bench-sim-break = 在 PLC 程序中设置断点
tbl-bench-sim-stepi = 单步执行 PLC 程序
tbl-bench-sim-stepn = 单步执行 PLC 程序
tbl-bench-sim-wire = 连接仿真设备
tbl-bench-sim-wires = 列出接线
tbl-bench-sim-unwire = 拆除接线
tbl-bench-sim-snapshot = 恢复已保存的仿真状态
tbl-bench-sim-snapshots = 列出已保存的状态
tbl-bench-sim-fault = 注入或清除故障
tbl-bench-sim-faults = 列出已注入的故障
tbl-bench-servo-sim = 控制仿真驱动器
tbl-bench-umpk-sim = 控制仿真 UMPK
tbl-bench-connect = 打开设备
tbl-bench-close = 关闭设备
tbl-bench-rtc-sync = 用计算机的时钟设置 PLC 的时钟
tbl-bench-paths = 显示用户的目录

## FX instruction subset and its load errors (src/fx/program.rs; FX programming manual ch. 2, 4, 5)

tbl-fx-unknown = 未知的 FX 指令 { $m }
tbl-fx-foreign-hint = { $m } 不是 FX 助记符：在 FX 上请写作 { $how }（docs/il.md，The FX family）
tbl-fx-unknown-near = 是否要输入 { $near }？（docs/il.md 列出了 FX 指令子集）
tbl-fx-unknown-hint = docs/il.md 列出了仿真器执行的 FX 指令
tbl-fx-operand-count = { $m } 需要 { $want } 个操作数，实际为 { $found } 个
tbl-fx-operand-range = { $m } 需要 { $lo } 到 { $hi } 个操作数，实际为 { $found } 个
tbl-fx-needs-preset = OUT { $t } 需要设定值：OUT { $t } K10（常数）或 OUT { $t } D10（寄存器）
tbl-fx-bad-preset = { $k }：设定值应为常数 K… 或数据寄存器 D…
tbl-fx-hsc-not-simulated = { $t }：不仿真高速计数器（C235–C255）
tbl-fx-hsc-not-simulated-hint = 请使用 C0–C199（16 位）或 C200–C234（32 位增/减计数）
tbl-fx-out-one-operand = OUT { $t } 只需一个操作数（设定值只用于计时器和计数器）
tbl-fx-rst-target = RST { $t }：复位 Y、M、S、D、计时器 T 或计数器 C
tbl-fx-input-written = { $m } { $t }：程序不能写输入 X
tbl-fx-input-written-hint = 请写 Y、M、S（如 KnY0 …）、D，或计时器、计数器的值
tbl-fx-coil-target = { $m } { $t }：此处程序只驱动 Y、M 和 S 位
tbl-fx-coil-target-hint = 输入 X 来自现场；OUT T0 K10 / OUT C0 K5 驱动计时器和计数器
tbl-fx-system-driven = { $m } { $t }：{ $operand } 由 PLC 驱动
tbl-fx-not-on-model = { $model } 上没有 { $t }
tbl-fx-no-blocks = 此处的 FX 指令表没有标号或程序块
tbl-fx-no-blocks-hint = 每行写一条指令：LD X0 / OUT Y0 … END
tbl-fx-element-by-out = { $text }：FX 计时器和计数器由 OUT 驱动
tbl-fx-element-by-out-hint = OUT T0 K50（计时器），OUT C0 K10（计数器），RST T0 / RST C0
tbl-fx-foreign-ton = 带设定值的计时器线圈：LD X0 / OUT T0 K20（T0–T199 以 100 ms 计时）
tbl-fx-foreign-tof = 用计时器线圈和 LDI 实现断开延时：LDI X0 / OUT T0 K20（T0–T199 以 100 ms 计时）
tbl-fx-foreign-tonr = 积算计时器线圈：OUT T250 K20（T250–T255 保持当前值；RST T250 将其清除）
tbl-fx-foreign-tp = 用计时器线圈及其触点产生脉冲：OUT T0 K20（T0–T199 以 100 ms 计时）
tbl-fx-foreign-ctu = 带设定值的计数器线圈：LD X0 / OUT C0 K10（RST C0 将其清除）
tbl-fx-foreign-ctd = 用 32 位计数器减计数：OUT C200 K10，并使 M8200 为 ON
tbl-fx-foreign-code = { $code }
tbl-fx-ld = 以常开触点开始一个块
tbl-fx-ldi = 以常闭触点开始一个块
tbl-fx-ldp = 开始一个块：位的上升沿时接通一个扫描周期
tbl-fx-ldf = 开始一个块：位的下降沿时接通一个扫描周期
tbl-fx-and = 串联常开触点
tbl-fx-ani = 串联常闭触点
tbl-fx-andp = 串联上升沿触点
tbl-fx-andf = 串联下降沿触点
tbl-fx-or = 并联常开触点
tbl-fx-ori = 并联常闭触点
tbl-fx-orp = 并联上升沿触点
tbl-fx-orf = 并联下降沿触点
tbl-fx-anb = 将最后两个块串联（AND）
tbl-fx-orb = 将最后两个块并联（OR）
tbl-fx-mps = 将运算结果压入堆栈
tbl-fx-mrd = 读出已压入的结果
tbl-fx-mpp = 弹出已压入的结果
tbl-fx-inv = 运算结果取反
tbl-fx-out = OUT Y/M/S：线圈 := 结果；OUT Tn K|D：带设定值的计时器线圈；OUT Cn K|D：计数器线圈
tbl-fx-set = 结果为 ON 时：置位 Y/M/S（保持 ON）
tbl-fx-rst = 结果为 ON 时：复位 Y/M/S，清零 D，复位计时器或计数器（当前值 0，触点断开）
tbl-fx-pls = 结果上升沿后 Y/M 接通一个扫描周期
tbl-fx-plf = 结果下降沿后 Y/M 接通一个扫描周期
tbl-fx-mov = MOV S D：D := S（16 位）
tbl-fx-movp = 结果上升沿时执行 MOV
tbl-fx-dmov = 32 位 MOV（D0 = D0 低位，D1 高位）
tbl-fx-dmovp = 上升沿时执行 32 位 MOV
tbl-fx-add = ADD S1 S2 D：D := S1 + S2（16 位，溢出回绕）
tbl-fx-addp = 上升沿时执行 ADD
tbl-fx-dadd = 32 位 ADD
tbl-fx-sub = SUB S1 S2 D：D := S1 − S2（16 位，溢出回绕）
tbl-fx-subp = 上升沿时执行 SUB
tbl-fx-dsub = 32 位 SUB
tbl-fx-inc = 结果为 ON 的每个扫描周期 D := D + 1
tbl-fx-incp = 上升沿时 D := D + 1
tbl-fx-dec = 结果为 ON 的每个扫描周期 D := D − 1
tbl-fx-decp = 上升沿时 D := D − 1
tbl-fx-ld-eq = 开始一个块：S1 = S2（16 位）
tbl-fx-ld-gt = 开始一个块：S1 > S2
tbl-fx-ld-lt = 开始一个块：S1 < S2
tbl-fx-ld-ne = 开始一个块：S1 ≠ S2
tbl-fx-ld-le = 开始一个块：S1 ≤ S2
tbl-fx-ld-ge = 开始一个块：S1 ≥ S2
tbl-fx-and-eq = 串联触点：S1 = S2
tbl-fx-and-gt = 串联触点：S1 > S2
tbl-fx-and-lt = 串联触点：S1 < S2
tbl-fx-and-ne = 串联触点：S1 ≠ S2
tbl-fx-and-le = 串联触点：S1 ≤ S2
tbl-fx-and-ge = 串联触点：S1 ≥ S2
tbl-fx-or-eq = 并联触点：S1 = S2
tbl-fx-or-gt = 并联触点：S1 > S2
tbl-fx-or-lt = 并联触点：S1 < S2
tbl-fx-or-ne = 并联触点：S1 ≠ S2
tbl-fx-or-le = 并联触点：S1 ≤ S2
tbl-fx-or-ge = 并联触点：S1 ≥ S2
tbl-fx-ldd-eq = 32 位：开始一个块：S1 = S2
tbl-fx-ldd-gt = 32 位：开始一个块：S1 > S2
tbl-fx-ldd-lt = 32 位：开始一个块：S1 < S2
tbl-fx-andd-eq = 32 位串联触点：S1 = S2
tbl-fx-ord-eq = 32 位并联触点：S1 = S2
tbl-fx-nop = 无操作
tbl-fx-end = 程序结束：其后的内容不被扫描

## The K2's Modbus map (src/k2/modbus_map.rs; K2 manual §3.2.1). Modbus table names stay as they are.

tbl-modbus-word-order = `word_order={ $value }` 不是字顺序
tbl-modbus-word-order-hint = 请使用 word_order=high-first（S7 顺序，默认）或 word_order=low-first
tbl-modbus-not-in-map = { $operand } 不在 K2 的 Modbus 映射中：K2 通过 Modbus 只开放 I、Q、M、V、AI 和 AQ（手册 §3.2.1）；无法访问 { $area }（{ $meaning }）
tbl-modbus-not-in-map-sm-hint = 在 PLC 中安装 plcsh 辅助程序（lib/k2_agent.il，docs/agent.md），并用 …&agent=VB3400 连接；仿真器（sim:MODEL）可直接访问 SM
tbl-modbus-not-in-map-tc-hint = 在 PLC 程序中把定时器和计数器复制到 V 区，再读取 V 字；仿真器（sim:MODEL）可直接访问 T 和 C
tbl-modbus-past-end = { $operand } 超出 { $model } 上 { $area } 区的末尾
tbl-modbus-read-only = { $operand } 通过 Modbus 只读（{ $meaning } 属于 { $table }，Modbus 不能写；手册 §3.2.1）
tbl-modbus-read-only-hint = 输入由现场接线决定；请改写输出（Q、AQ）或存储区（M、V）

## FX timers and counters by class (src/fx/elements.rs; FX PM "Timers", "Counters")

tbl-element-timer = T{ $n }：{ $base } 计时器（T{ $first }–T{ $last }）；触点 T{ $n } = TS{ $n }，线圈 TC{ $n }，当前值 TN{ $n }；程序中写 `OUT T{ $n } K50`
tbl-element-timer-retentive = T{ $n }：{ $base } 积算计时器（RST 将其清除）（T{ $first }–T{ $last }）；触点 T{ $n } = TS{ $n }，线圈 TC{ $n }，当前值 TN{ $n }；程序中写 `OUT T{ $n } K50`
tbl-element-counter = C{ $n }：16 位增计数器（C0–C199）；触点 C{ $n } = CS{ $n }，线圈 CC{ $n }，当前值 CN{ $n }
tbl-element-counter32 = C{ $n }：32 位增/减计数器（C200–C234），M{ $relay } 为 ON 时减计数；触点 C{ $n } = CS{ $n }，当前值 CN{ $n }
tbl-element-hsc = C{ $n }：高速计数器（C235–C255；不仿真）

## The core IL instruction set (src/engine/isa.rs; K2 manual §3.4.3.1, K80S CPU chapter, IEC 61131-3, S7-200 convention)

tbl-il-ld = CR := 位（原 CR 压入堆栈）
tbl-il-ldn = CR := NOT 位
tbl-il-and = CR := CR AND 位
tbl-il-a = CR := CR AND 位
tbl-il-andn = CR := CR AND NOT 位
tbl-il-an = CR := CR AND NOT 位
tbl-il-or = CR := CR OR 位
tbl-il-o = CR := CR OR 位
tbl-il-orn = CR := CR OR NOT 位
tbl-il-on = CR := CR OR NOT 位
tbl-il-xor = CR := CR XOR 位
tbl-il-xorn = CR := CR XOR NOT 位
tbl-il-and-paren = 开括号：CR := CR AND ( … )
tbl-il-andn-paren = 开括号：CR := CR AND NOT ( … )
tbl-il-or-paren = 开括号：CR := CR OR ( … )
tbl-il-orn-paren = 开括号：CR := CR OR NOT ( … )
tbl-il-xor-paren = 开括号：CR := CR XOR ( … )
tbl-il-xorn-paren = 开括号：CR := CR XOR NOT ( … )
tbl-il-close = 关闭最内层括号
tbl-il-not = CR := NOT CR
tbl-il-st = 位 := CR
tbl-il-assign = 位 := CR
tbl-il-stn = 位 := NOT CR
tbl-il-s = CR 为 1 时：置位（`S bit, N` 置 N 位；T/C 置为 ON）
tbl-il-r = CR 为 1 时：复位（N 位）；定时器或计数器：当前值和位清零
tbl-il-ald = 逻辑堆栈顶部两层相 AND
tbl-il-old = 逻辑堆栈顶部两层相 OR
tbl-il-lps = 将 CR 的副本压入堆栈
tbl-il-lrd = CR := 堆栈第二层
tbl-il-lpp = 将堆栈弹出到 CR
tbl-il-r-trig = CR := 自上次执行本指令以来 CR 出现上升沿
tbl-il-eu = 上升沿（R_TRIG 的 S7-200 名称）
tbl-il-f-trig = CR := 自上次执行本指令以来 CR 出现下降沿
tbl-il-ed = 下降沿（F_TRIG 的 S7-200 名称）
tbl-il-move = CR 为 1 时：OUT := IN（按 OUT 的类型）
tbl-il-movb = 字节传送
tbl-il-movw = 字传送
tbl-il-movd = 双字传送
tbl-il-movr = REAL 传送
tbl-il-blkmove = CR 为 1 时：复制 N 个元素 IN… → OUT…
tbl-il-bmb = N 个字节的块传送
tbl-il-bmw = N 个字的块传送
tbl-il-bmd = N 个双字的块传送
tbl-il-fill = CR 为 1 时：从 OUT 起 N 个字 := IN
tbl-il-add = OUT := OUT + IN，或 OUT := IN1 + IN2
tbl-il-sub = OUT := OUT − IN，或 IN1 − IN2
tbl-il-mul = OUT := OUT × IN，或 IN1 × IN2
tbl-il-div = OUT := OUT ÷ IN，或 IN1 ÷ IN2（÷0：ENO = 0）
tbl-il-mod = 余数
tbl-il-add-i = INT 加法
tbl-il-sub-i = INT 减法
tbl-il-mul-i = INT 乘法
tbl-il-div-i = INT 除法
tbl-il-add-d = DINT 加法
tbl-il-sub-d = DINT 减法
tbl-il-mul-d = DINT 乘法
tbl-il-div-d = DINT 除法
tbl-il-add-r = REAL 加法
tbl-il-sub-r = REAL 减法
tbl-il-mul-r = REAL 乘法
tbl-il-div-r = REAL 除法
tbl-il-inc = CR 为 1 时：OUT := OUT + 1
tbl-il-dec = CR 为 1 时：OUT := OUT − 1
tbl-il-shl = OUT := OUT 左移 N 位
tbl-il-shr = OUT := OUT 右移 N 位（逻辑移位）
tbl-il-rol = OUT := OUT 循环左移 N 位
tbl-il-ror = OUT := OUT 循环右移 N 位
tbl-il-wand = OUT := OUT AND IN（按位）
tbl-il-andw = 按位 AND
tbl-il-wor = OUT := OUT OR IN（按位）
tbl-il-orw = 按位 OR
tbl-il-wxor = OUT := OUT XOR IN（按位）
tbl-il-xorw = 按位 XOR
tbl-il-inv = OUT := NOT OUT（按位）
tbl-il-sqrt = CR 为 1 时：OUT := √IN（REAL）；IN < 0 或 NaN：ENO = 0，SM1.1，OUT 不变；+inf：OUT = +inf，ENO = 0
tbl-il-abs = CR 为 1 时：OUT := |IN|（按 OUT 的类型）；−32768 / −2³¹ 保持原值，置 SM1.1 且 ENO = 0；REAL NaN/inf：ENO = 0
tbl-il-swap = CR 为 1 时：交换字的高字节和低字节
tbl-il-for = FOR INDX, INIT, FINAL：CR 为 1 时，以 INDX = INIT … FINAL 执行到 NEXT 为止的指令（INT 或 DINT；INIT > FINAL：不执行；嵌套 ≤ 8）
tbl-il-next = FOR 循环结束：INDX + 1，INDX ≤ FINAL 时返回（重新读取 FINAL；到达类型最大值时循环结束）
tbl-il-i-di = INT → DINT
tbl-il-int-to-dint = INT → DINT
tbl-il-di-i = DINT → INT（超出范围：ENO = 0）
tbl-il-dint-to-int = DINT → INT
tbl-il-b-i = BYTE → INT
tbl-il-i-b = INT → BYTE（超出范围：ENO = 0）
tbl-il-di-r = DINT → REAL
tbl-il-round = REAL → DINT，四舍五入
tbl-il-trunc = REAL → DINT，截尾取整
tbl-il-i-bcd = INT 0…9999 → BCD（否则 ENO = 0）
tbl-il-bcd-i = BCD → INT（数字无效：ENO = 0）
tbl-il-jmp = 跳转到 LABEL
tbl-il-jmpc = CR 为 1 时跳转到 LABEL
tbl-il-jmpcn = CR 为 0 时跳转到 LABEL
tbl-il-cal = 调用子程序 NAME（按 K2 的 EN 约定，CR 为 1 时）
tbl-il-calc = CR 为 1 时调用子程序 NAME
tbl-il-calcn = CR 为 0 时调用子程序 NAME
tbl-il-ret = 从本 POU 返回
tbl-il-retc = CR 为 1 时返回
tbl-il-retcn = CR 为 0 时返回
tbl-il-cret = 条件返回（S7-200 名称）
tbl-il-ton = 接通延时定时器 Tn, PT（IN = CR；CR := Q）
tbl-il-tof = 断开延时定时器 Tn, PT
tbl-il-toff = 断开延时定时器（MASTER-K 名称）
tbl-il-tp = 脉冲定时器 Tn, PT
tbl-il-tmr = 积算定时器 Tn, PT [, 复位位]
tbl-il-tonr = 积算定时器（S7-200 名称）
tbl-il-tmon = 单稳态定时器 Tn, PT
tbl-il-trtg = 可重触发单稳态定时器 Tn, PT
tbl-il-ctu = 增计数器 Cn, PV [, 复位位]（CU = CR）
tbl-il-ctd = 减计数器 Cn, PV [, 装载位]（CD = CR）
tbl-il-ctud = 增/减计数器 Cn, PV, CD 位 [, 复位位]
tbl-il-ctr = 环形计数器 Cn, PV [, 复位位]
tbl-il-atch = 把中断服务子程序 INT_NAME 连接到中断事件 EVENT
tbl-il-dtch = 断开中断事件 EVENT
tbl-il-eni = 允许中断
tbl-il-disi = 禁止中断（事件等待）
tbl-il-wdt = 重新开始看门狗定时器计时
tbl-il-wdr = 重新开始看门狗定时器计时（S7-200 名称）
tbl-il-nop = 无操作
tbl-il-compare = 比较 IN1 与 IN2，并把结果装入 CR / 与 CR 相 AND / 相 OR
