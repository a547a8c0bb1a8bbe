<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="zh_CN">
<context>
    <name>ArmCalibration</name>
    <message>
        <source>no position was read from servo %1</source>
        <translation>未从舵机 %1 读到位置</translation>
    </message>
    <message>
        <source>servo %1 stopped answering during the recording: record again</source>
        <translation>舵机 %1 在记录过程中停止应答：请重新记录</translation>
    </message>
    <message>
        <source>the joint never moved (%1 steps; move it through its whole range)</source>
        <translation>该关节从未转动（%1 步；请让它转过整个行程）</translation>
    </message>
    <message>
        <source>the range of %1 steps is wider than the encoder allows (%2 steps: a turn less a safety margin of %3); is this a full-turn joint?</source>
        <translation>%1 步的范围超出编码器允许的宽度（%2 步：一圈减去 %3 的安全余量）；这是整圈关节吗？</translation>
    </message>
    <message>
        <source>the middle pose %1 is not a position of the encoder</source>
        <translation>中位姿态 %1 不是编码器的有效位置</translation>
    </message>
    <message>
        <source>from the middle pose, the range (%1 to %2) would cross the encoder&apos;s 0/4095 seam: take a middle pose nearer the middle of the joint&apos;s travel, or use ServoBench&apos;s order</source>
        <translation>从中位姿态出发，范围（%1 到 %2）会跨越编码器的 0/4095 分界点：请选取更接近关节行程中间的中位姿态，或使用 ServoBench 的顺序</translation>
    </message>
    <message>
        <source>the limits %1 to %2 are outside what the servo holds (at most %3 and %4)</source>
        <translation>限制 %1 到 %2 超出舵机可保存的范围（最多 %3 和 %4）</translation>
    </message>
    <message>
        <source>no middle pose was taken for this joint</source>
        <translation>未为此关节采集中位姿态</translation>
    </message>
    <message>
        <source>%1: wrote %2, the servo holds %3</source>
        <translation>%1：写入 %2，舵机保存的是 %3</translation>
    </message>
    <message>
        <source>nothing</source>
        <translation>无</translation>
    </message>
    <message>
        <source>%1: the file says %2, the servo holds %3</source>
        <translation>%1：文件中为 %2，舵机中为 %3</translation>
    </message>
    <message>
        <source>nothing readable</source>
        <translation>无法读取</translation>
    </message>
</context>
<context>
    <name>BatchResultDialog</name>
    <message>
        <source>Programming results</source>
        <translation>编程结果</translation>
    </message>
    <message numerus="yes">
        <source>%1 to %n servo(s): %2 written and verified, %3 unchanged, %4 failed.</source>
        <translation>
            <numerusform>将 %1 写入 %n 个舵机：%2 个已写入并验证，%3 个未更改，%4 个失败。</numerusform>
        </translation>
    </message>
    <message>
        <source>Servo</source>
        <translation>舵机</translation>
    </message>
    <message>
        <source>Status</source>
        <translation>状态</translation>
    </message>
    <message>
        <source>Registers written</source>
        <translation>已写入的寄存器</translation>
    </message>
    <message>
        <source>Error</source>
        <translation>错误</translation>
    </message>
    <message>
        <source>ID %1</source>
        <translation>ID %1</translation>
    </message>
</context>
<context>
    <name>BenchCases</name>
    <message>
        <source>Cut the selected servo&apos;s power</source>
        <translation>切断所选舵机的电源</translation>
    </message>
    <message>
        <source>Power the selected servo again</source>
        <translation>给所选舵机重新供电</translation>
    </message>
    <message>
        <source>Break the daisy chain after the selected servo</source>
        <translation>在所选舵机之后断开菊花链</translation>
    </message>
    <message>
        <source>Mend the daisy chain</source>
        <translation>修复菊花链</translation>
    </message>
    <message>
        <source>Block the selected servo&apos;s horn</source>
        <translation>卡住所选舵机的舵盘</translation>
    </message>
    <message>
        <source>Free the selected servo&apos;s horn</source>
        <translation>释放所选舵机的舵盘</translation>
    </message>
    <message>
        <source>Heat the selected servo (%1 °C/s)</source>
        <translation>加热所选舵机（%1 °C/s）</translation>
    </message>
    <message>
        <source>Stop heating the selected servo</source>
        <translation>停止加热所选舵机</translation>
    </message>
    <message>
        <source>Latch an overload on the selected servo</source>
        <translation>在所选舵机上锁存过载</translation>
    </message>
    <message>
        <source>Supply %1 V to the bus (too high for 7.4 V servos)</source>
        <translation>向总线供电 %1 V（对 7.4 V 舵机而言过高）</translation>
    </message>
    <message>
        <source>Supply %1 V to the bus (too low)</source>
        <translation>向总线供电 %1 V（过低）</translation>
    </message>
    <message>
        <source>Supply each servo its usual voltage</source>
        <translation>为每个舵机提供其常规电压</translation>
    </message>
    <message>
        <source>Servo #%1 has no power: it hears and answers nothing.</source>
        <translation>舵机 #%1 没有电源：它既收不到也不应答任何内容。</translation>
    </message>
    <message>
        <source>Servo #%1 has power again.</source>
        <translation>舵机 #%1 已重新通电。</translation>
    </message>
    <message>
        <source>The daisy chain is broken after servo #%1: the servos after it have neither signal nor power.</source>
        <translation>菊花链在舵机 #%1 之后断开：其后的舵机既没有信号也没有电源。</translation>
    </message>
    <message>
        <source>The daisy chain is whole again.</source>
        <translation>菊花链已恢复完整。</translation>
    </message>
    <message>
        <source>Servo #%1&apos;s horn is blocked: driven, its load rises and it stays put.</source>
        <translation>舵机 #%1 的舵盘被卡住：驱动时负载升高，位置保持不动。</translation>
    </message>
    <message>
        <source>Servo #%1&apos;s horn is free.</source>
        <translation>舵机 #%1 的舵盘已释放。</translation>
    </message>
    <message>
        <source>Servo #%1 warms steadily until it trips at its maximum temperature.</source>
        <translation>舵机 #%1 持续升温，直到在最高温度处触发保护。</translation>
    </message>
    <message>
        <source>Servo #%1 is no longer heated: it cools toward the room&apos;s temperature.</source>
        <translation>舵机 #%1 不再被加热：它会逐渐冷却到室温。</translation>
    </message>
    <message>
        <source>Servo #%1&apos;s overload is latched: its torque is gone until the bus is power-cycled.</source>
        <translation>舵机 #%1 的过载已锁存：在总线断电重启之前扭矩一直失效。</translation>
    </message>
    <message>
        <source>The bus has a %1 V supply.</source>
        <translation>总线电源为 %1 V。</translation>
    </message>
    <message>
        <source>Every servo has its usual supply again.</source>
        <translation>每个舵机都已恢复其常规电源。</translation>
    </message>
</context>
<context>
    <name>BusDoctor</name>
    <message>
        <source>You may not open %1. Add yourself to the dialout group (sudo usermod -aG dialout $USER, then log out and back in), or give the adapter a udev rule that lets your account use it.</source>
        <translation>您无权打开 %1。请将自己加入 dialout 组（sudo usermod -aG dialout $USER，然后注销并重新登录），或为适配器添加允许您的账户使用它的 udev 规则。</translation>
    </message>
    <message>
        <source>You may not open %1: ask for access to serial ports.</source>
        <translation>您无权打开 %1：请申请串口访问权限。</translation>
    </message>
    <message>
        <source>%1 is in use by %2. Close that program (or its connection to the port) and try again.</source>
        <translation>%1 正被 %2 占用。请关闭该程序（或它与该端口的连接）后重试。</translation>
    </message>
    <message>
        <source>%1 is in use by another program (a terminal, another ServoBench, a modem manager). Close it and try again.</source>
        <translation>%1 正被其他程序占用（终端、另一个 ServoBench、调制解调器管理器）。请关闭它后重试。</translation>
    </message>
    <message>
        <source>%1 does not exist. Plug the adapter in, or choose another port.</source>
        <translation>%1 不存在。请插入适配器，或选择其他端口。</translation>
    </message>
    <message>
        <source>%1 could not be used: %2.</source>
        <translation>无法使用 %1：%2。</translation>
    </message>
    <message>
        <source>Not a single byte came back at any rate. Check the servos&apos; power supply (the USB adapter does not power them), the wiring (signal and ground), the adapter&apos;s direction switch or jumper, and that a TTL servo (SCS, STS) is not on an RS485 adapter, or an RS485 servo on a TTL one.</source>
        <translation>在任何波特率下都没有收到一个字节。请检查舵机电源（USB 适配器不为舵机供电）、接线（信号线和地线）、适配器的方向开关或跳线，并确认 TTL 舵机（SCS、STS）没有接在 RS485 适配器上，RS485 舵机也没有接在 TTL 适配器上。</translation>
    </message>
    <message>
        <source>The adapter sends back what it sends, so it works: the servos do not answer.</source>
        <translation>适配器会回送它发出的数据，说明适配器工作正常：是舵机没有应答。</translation>
    </message>
    <message>
        <source>At %1, bytes came back but never a valid answer. A servo may be at another rate, the adapter may send back what it sends (try Echo On), or two servos may share one ID (connect them one at a time).</source>
        <translation>在 %1 下收到了字节，但始终不是有效的应答。可能有舵机处于其他波特率，适配器可能会回送它发出的数据（试试将回显设为“开”），或有两个舵机使用了同一 ID（请逐个连接）。</translation>
    </message>
    <message>
        <source>Servo %1 answers at %2, not at %3. Move it to %3.</source>
        <translation>舵机 %1 在 %2 下应答，而不是 %3。请将它改到 %3。</translation>
    </message>
    <message>
        <source>A servo (%1) answers at ID %2, %3: no servo is expected at that ID.</source>
        <translation>一个舵机（%1）以 ID %2（%3）应答：该 ID 上不应有舵机。</translation>
    </message>
    <message>
        <source>If it is the missing servo %1, move it to ID %1 at %2.</source>
        <translation>如果它就是缺失的舵机 %1，请将它改为 ID %1，波特率 %2。</translation>
    </message>
    <message>
        <source>If it is the missing servo %1, move it to ID %1.</source>
        <translation>如果它就是缺失的舵机 %1，请将它改为 ID %1。</translation>
    </message>
    <message>
        <source>Servo %1 does not answer</source>
        <translation>舵机 %1 无应答</translation>
    </message>
    <message>
        <source>Servos %1 do not answer</source>
        <translation>舵机 %1 无应答</translation>
    </message>
    <message>
        <source>%1, while every servo up to ID %2 in the chain does: check the cable after ID %2 (and its connectors at both ends).</source>
        <translation>%1，而链路中直到 ID %2 的每个舵机都有应答：请检查 ID %2 之后的电缆（及其两端的接头）。</translation>
    </message>
    <message>
        <source>Expected servo %1 does not answer</source>
        <translation>预期的舵机 %1 无应答</translation>
    </message>
    <message>
        <source>Expected servos %1 do not answer</source>
        <translation>预期的舵机 %1 无应答</translation>
    </message>
    <message>
        <source>%1. Check power and cables; a new servo is at ID 1 until it is set up (Set up motors, or servoctl feetech setup-motor).</source>
        <translation>%1。请检查电源和电缆；新舵机在完成设置前的 ID 为 1（“设置舵机”，或 servoctl feetech setup-motor）。</translation>
    </message>
    <message>
        <source>Servo %1 answers a PING but its registers come back garbled: two servos may share ID %1. Connect them one at a time and give each its own ID.</source>
        <translation>舵机 %1 应答了 PING，但读回的寄存器是乱码：可能有两个舵机共用 ID %1。请逐个连接，并为每个舵机分配各自的 ID。</translation>
    </message>
    <message>
        <source>%1–%2 V</source>
        <translation>%1–%2 V</translation>
    </message>
    <message>
        <source>its limits</source>
        <translation>其限值</translation>
    </message>
    <message>
        <source>%1 V</source>
        <translation>%1 V</translation>
    </message>
    <message>
        <source>an unknown voltage</source>
        <translation>未知电压</translation>
    </message>
    <message>
        <source>Servo %1 reports %2 and a voltage error; it accepts %3. Check the supply: a 12 V supply on a 7.4 V servo, or a supply too weak for the load.</source>
        <translation>舵机 %1 报告 %2 及电压错误；它可接受 %3。请检查电源：例如 7.4 V 舵机接了 12 V 电源，或电源不足以带动负载。</translation>
    </message>
    <message>
        <source>A PTK servo answers on %1, not a Feetech bus: connect the Feetech adapter, or use the PTK workspace.</source>
        <translation>%1 上应答的是 PTK 舵机，而不是 Feetech 总线：请连接 Feetech 适配器，或使用 PTK 工作区。</translation>
    </message>
    <message>
        <source>No servo answered at %1. Re-scan with the port probed: it listens at every rate and tells silence from bytes that never make an answer.</source>
        <translation>在 %1 下没有舵机应答。请在探测端口后重新扫描：探测会在每种波特率下监听，并区分完全无信号与收到字节却始终构不成应答的情况。</translation>
    </message>
    <message>
        <source>You may not open the port</source>
        <translation>无权打开端口</translation>
    </message>
    <message>
        <source>Another program has the port</source>
        <translation>端口被其他程序占用</translation>
    </message>
    <message>
        <source>The port is not there</source>
        <translation>端口不存在</translation>
    </message>
    <message>
        <source>The port could not be opened</source>
        <translation>无法打开端口</translation>
    </message>
    <message>
        <source>Nothing answers</source>
        <translation>没有任何应答</translation>
    </message>
    <message>
        <source>Bytes come back, but no answer</source>
        <translation>收到字节，但没有有效应答</translation>
    </message>
    <message>
        <source>A PTK servo, not a Feetech bus</source>
        <translation>是 PTK 舵机，不是 Feetech 总线</translation>
    </message>
    <message>
        <source>No servo found</source>
        <translation>未找到舵机</translation>
    </message>
    <message>
        <source>A servo at an unexpected ID</source>
        <translation>在意外的 ID 上发现舵机</translation>
    </message>
    <message>
        <source>A servo at another rate</source>
        <translation>有舵机处于其他波特率</translation>
    </message>
    <message>
        <source>The chain is broken</source>
        <translation>链路断开</translation>
    </message>
    <message>
        <source>Servos are missing</source>
        <translation>缺少舵机</translation>
    </message>
    <message>
        <source>Two servos may share an ID</source>
        <translation>可能有两个舵机共用一个 ID</translation>
    </message>
    <message>
        <source>The supply voltage is wrong</source>
        <translation>供电电压不正确</translation>
    </message>
</context>
<context>
    <name>BusShare</name>
    <message>
        <source>The bus is shared already, at %1.</source>
        <translation>总线已在共享中，路径为 %1。</translation>
    </message>
    <message>
        <source>The port is not open: connect to the bus first.</source>
        <translation>端口未打开：请先连接总线。</translation>
    </message>
    <message>
        <source>Name the path the other program opens.</source>
        <translation>请指定另一个程序要打开的路径。</translation>
    </message>
    <message>
        <source>%1 is the bus&apos;s own port: give the other program another path.</source>
        <translation>%1 是总线自身的端口：请给另一个程序另一个路径。</translation>
    </message>
    <message>
        <source>The program set %1 baud, which the port refuses; it stays at %2 baud.</source>
        <translation>该程序设置了 %1 波特率，端口拒绝了它；端口保持 %2 波特率。</translation>
    </message>
    <message>
        <source>The program set %1 baud; the port follows.</source>
        <translation>该程序设置了 %1 波特率；端口随之更改。</translation>
    </message>
    <message>
        <source>The adapter went away (%1): what the program sends is lost until it is back; the share waits for it.</source>
        <translation>适配器已断开（%1）：在它恢复之前，该程序发送的数据会丢失；共享会等待它恢复。</translation>
    </message>
    <message>
        <source>The adapter is back: the share goes on.</source>
        <translation>适配器已恢复：共享继续。</translation>
    </message>
    <message>
        <source>The recording stopped after %1 line(s): %2. The share goes on.</source>
        <translation>记录在 %1 行后停止：%2。共享继续进行。</translation>
    </message>
    <message>
        <source>%1 frame(s) (%2 bytes) from the program, %3 frame(s) (%4 bytes) back to it; %5 request(s) unanswered, %6 garbled byte(s), %7 alert(s), %8 watch read(s), %9 request(s) not sent because the program had sent the next.</source>
        <translation>来自程序 %1 帧（%2 字节），返回给它 %3 帧（%4 字节）；%5 个请求无应答，%6 个乱码字节，%7 条警报，%8 次监视读取，%9 个请求因程序已发出下一个而未发送。</translation>
    </message>
</context>
<context>
    <name>CalibrationActions</name>
    <message>
        <source>&amp;Calibrate arm…</source>
        <translation>校准机械臂(&amp;C)…</translation>
    </message>
    <message>
        <source>Record each joint&apos;s range by hand and centre it on the encoder</source>
        <translation>手动记录每个关节的范围，并使其在编码器上居中</translation>
    </message>
    <message>
        <source>&amp;Save calibration…</source>
        <translation>保存校准(&amp;S)…</translation>
    </message>
    <message>
        <source>Save the servos&apos; offsets and limits as a LeRobot calibration file</source>
        <translation>将舵机的位置偏移和限制保存为 LeRobot 校准文件</translation>
    </message>
    <message>
        <source>&amp;Load calibration…</source>
        <translation>加载校准(&amp;L)…</translation>
    </message>
    <message>
        <source>Write a LeRobot calibration file to the servos, after showing what changes</source>
        <translation>先显示将要更改的内容，再将 LeRobot 校准文件写入舵机</translation>
    </message>
    <message>
        <source>Save calibration</source>
        <translation>保存校准</translation>
    </message>
    <message>
        <source>LeRobot calibration (*.json)</source>
        <translation>LeRobot 校准文件 (*.json)</translation>
    </message>
    <message>
        <source>Load calibration</source>
        <translation>加载校准</translation>
    </message>
    <message>
        <source>Close the motor set-up (%1) before calibrating: it changes the servos&apos; IDs and settings.</source>
        <translation>校准前请先关闭舵机设置（%1）：它会更改舵机的 ID 和参数。</translation>
    </message>
</context>
<context>
    <name>CalibrationFiles</name>
    <message>
        <source>LeRobot calibration (*.json)</source>
        <translation>LeRobot 校准文件 (*.json)</translation>
    </message>
    <message>
        <source>The arm&apos;s name, as LeRobot&apos;s --robot.id (or --teleop.id) gives it; it names the file:</source>
        <translation>机械臂的名称，与 LeRobot 的 --robot.id（或 --teleop.id）相同；文件以它命名：</translation>
    </message>
</context>
<context>
    <name>CalibrationJointsPage</name>
    <message>
        <source>Choose the joints to calibrate. ServoBench records how far each joint turns, then sets its position offset so that the middle of that range reads 2048, and its angle limits to the range: no joint&apos;s range crosses the encoder&apos;s 0/4095 seam.</source>
        <translation>请选择要校准的关节。ServoBench 会记录每个关节的转动范围，然后设置其位置偏移，使该范围的中间读数为 2048，并将其角度限制设为该范围：任何关节的范围都不会跨越编码器的 0/4095 分界点。</translation>
    </message>
    <message>
        <source>No template (joints named by ID)</source>
        <translation>无模板（按 ID 命名关节）</translation>
    </message>
    <message>
        <source>Names the joints whose IDs the arm&apos;s template has</source>
        <translation>按机械臂模板中的 ID 为关节命名</translation>
    </message>
    <message>
        <source>Robot:</source>
        <translation>机器人：</translation>
    </message>
    <message>
        <source>Calibrate</source>
        <translation>校准</translation>
    </message>
    <message>
        <source>ID</source>
        <translation>ID</translation>
    </message>
    <message>
        <source>Model</source>
        <translation>型号</translation>
    </message>
    <message>
        <source>Joint</source>
        <translation>关节</translation>
    </message>
    <message>
        <source>Full turn</source>
        <translation>整圈</translation>
    </message>
    <message>
        <source>Order</source>
        <translation>顺序</translation>
    </message>
    <message>
        <source>ServoBench: record each joint&apos;s range, then centre it on the encoder (recommended)</source>
        <translation>ServoBench：先记录每个关节的范围，再使其在编码器上居中（推荐）</translation>
    </message>
    <message>
        <source>LeRobot: put the arm in its middle pose first (it reads 2047), then record the ranges</source>
        <translation>LeRobot：先将机械臂摆到中位姿态（读数为 2047），再记录范围</translation>
    </message>
    <message>
        <source>&amp;Next</source>
        <translation>下一步(&amp;N)</translation>
    </message>
    <message>
        <source>Check the choice, then switch torque off</source>
        <translation>检查所选内容，然后关闭扭矩</translation>
    </message>
    <message>
        <source>%1 (no position offset)</source>
        <translation>%1（无位置偏移）</translation>
    </message>
    <message>
        <source>This servo has no position offset register: it cannot be calibrated</source>
        <translation>此舵机没有位置偏移寄存器：无法校准</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a joint name: use letters, digits and _, a letter first (LeRobot&apos;s motor names, such as shoulder_pan).</source>
        <translation>“%1”不是有效的关节名：请使用字母、数字和 _，并以字母开头（LeRobot 的电机名称，例如 shoulder_pan）。</translation>
    </message>
    <message>
        <source>Two joints are named &quot;%1&quot;: give each its own name.</source>
        <translation>有两个关节都名为“%1”：请为每个关节取不同的名称。</translation>
    </message>
    <message>
        <source>Servo %1 (%2) has no position offset on a 4096-step encoder: it cannot be calibrated. Leave it out.</source>
        <translation>舵机 %1（%2）没有 4096 步编码器上的位置偏移：无法校准。请将其排除。</translation>
    </message>
    <message>
        <source>%1 (ID %2)</source>
        <translation>%1 (ID %2)</translation>
    </message>
    <message>
        <source>Choose at least one joint to calibrate.</source>
        <translation>请至少选择一个要校准的关节。</translation>
    </message>
</context>
<context>
    <name>CalibrationResultsPage</name>
    <message>
        <source>Each joint&apos;s new position offset and angle limits (in steps, in the new coordinates), or why it is refused. Nothing has been written yet.</source>
        <translation>每个关节新的位置偏移和角度限制（单位为步，采用新坐标），或被拒绝的原因。目前尚未写入任何内容。</translation>
    </message>
    <message>
        <source>Joint</source>
        <translation>关节</translation>
    </message>
    <message>
        <source>Offset</source>
        <translation>偏移</translation>
    </message>
    <message>
        <source>Min limit</source>
        <translation>最小限制</translation>
    </message>
    <message>
        <source>Max limit</source>
        <translation>最大限制</translation>
    </message>
    <message>
        <source>Status</source>
        <translation>状态</translation>
    </message>
    <message>
        <source>&amp;Write to the servos</source>
        <translation>写入舵机(&amp;W)</translation>
    </message>
    <message>
        <source>Write the offsets and limits to EEPROM and verify them</source>
        <translation>将位置偏移和限制写入 EEPROM 并验证</translation>
    </message>
    <message>
        <source>&amp;Save LeRobot file…</source>
        <translation>保存 LeRobot 文件(&amp;S)…</translation>
    </message>
    <message>
        <source>Save the written calibration as LeRobot&apos;s JSON file</source>
        <translation>将已写入的校准保存为 LeRobot 的 JSON 文件</translation>
    </message>
    <message>
        <source>&amp;Record again</source>
        <translation>重新记录(&amp;R)</translation>
    </message>
    <message>
        <source>Forget this recording and record the ranges again</source>
        <translation>放弃此次记录，重新记录范围</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>To write</source>
        <translation>待写入</translation>
    </message>
    <message>
        <source>Refused, nothing written: %1</source>
        <translation>已拒绝，未写入任何内容：%1</translation>
    </message>
    <message>
        <source>Written and verified</source>
        <translation>已写入并验证</translation>
    </message>
    <message>
        <source>Writing each joint&apos;s offset and limits to its EEPROM and reading them back…</source>
        <translation>正在将每个关节的偏移和限制写入其 EEPROM 并回读…</translation>
    </message>
    <message>
        <source>Every joint&apos;s offset and limits were written to its EEPROM and read back as written.</source>
        <translation>每个关节的偏移和限制都已写入其 EEPROM，回读结果与写入一致。</translation>
    </message>
    <message>
        <source>No joint&apos;s calibration was written and verified: the status column says why.</source>
        <translation>没有任何关节的校准被写入并验证：原因见状态列。</translation>
    </message>
    <message numerus="yes">
        <source>%1 of %n joint(s) were written and verified; the status column says what became of the others.</source>
        <translation>
            <numerusform>%n 个关节中有 %1 个已写入并验证；其余关节的情况见状态列。</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>CalibrationSaver</name>
    <message>
        <source>Servo %1 could not be read: %2; nothing was saved.</source>
        <translation>无法读取舵机 %1：%2；未保存任何内容。</translation>
    </message>
    <message>
        <source>Servo %1 holds the limits %2 to %3, which are no calibrated range; nothing was saved.</source>
        <translation>舵机 %1 的限制为 %2 到 %3，不是校准过的范围；未保存任何内容。</translation>
    </message>
    <message numerus="yes">
        <source>Saved the calibration of %n joint(s) to %1.</source>
        <translation>
            <numerusform>已将 %n 个关节的校准保存到 %1。</numerusform>
        </translation>
    </message>
    <message>
        <source>No servo on the bus has a position offset to save.</source>
        <translation>总线上没有舵机具有可保存的位置偏移。</translation>
    </message>
</context>
<context>
    <name>CalibrationSteps</name>
    <message>
        <source>The bus was disconnected.</source>
        <translation>总线已断开。</translation>
    </message>
    <message>
        <source>The bus is not connected.</source>
        <translation>总线未连接。</translation>
    </message>
    <message>
        <source>Written and verified.</source>
        <translation>已写入并验证。</translation>
    </message>
    <message>
        <source>Verification failed: %1</source>
        <translation>验证失败：%1</translation>
    </message>
</context>
<context>
    <name>CalibrationWizard</name>
    <message>
        <source>Calibrate the arm</source>
        <translation>校准机械臂</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <source>Torque is off, but the recording could not start: %1</source>
        <translation>扭矩已关闭，但无法开始记录：%1</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>关闭</translation>
    </message>
    <message>
        <source>Support the arm: torque goes off on these joints, and the arm will fall under its own weight if nothing holds it.

%1</source>
        <translation>请扶住机械臂：这些关节的扭矩将被关闭，如果没有支撑，机械臂会因自重而落下。

%1</translation>
    </message>
    <message>
        <source>Reading the joints and switching torque off…</source>
        <translation>正在读取关节并关闭扭矩…</translation>
    </message>
    <message>
        <source>Servo %1: %2</source>
        <translation>舵机 %1：%2</translation>
    </message>
    <message>
        <source>%1 (%2): %3</source>
        <translation>%1（%2）：%3</translation>
    </message>
    <message>
        <source>no reading yet</source>
        <translation>尚无读数</translation>
    </message>
    <message>
        <source>stopped answering</source>
        <translation>已停止应答</translation>
    </message>
    <message>
        <source>min %1 · present %2 · max %3</source>
        <translation>最小 %1 · 当前 %2 · 最大 %3</translation>
    </message>
    <message>
        <source>No position has come from %1 (ID %2) yet: check that it answers.</source>
        <translation>尚未从 %1（ID %2）收到位置：请检查它是否应答。</translation>
    </message>
    <message>
        <source>Check the results, then write them to the servos.</source>
        <translation>请检查结果，然后将其写入舵机。</translation>
    </message>
    <message>
        <source>No joint can be calibrated from this recording: press Record again and move every joint through its range.</source>
        <translation>此次记录无法校准任何关节：请按“重新记录”，并让每个关节转过其整个范围。</translation>
    </message>
    <message>
        <source>No joint was written: there is nothing to save.</source>
        <translation>没有关节被写入：没有可保存的内容。</translation>
    </message>
    <message>
        <source>Save LeRobot calibration</source>
        <translation>保存 LeRobot 校准</translation>
    </message>
    <message>
        <source>Saved %1.</source>
        <translation>已保存 %1。</translation>
    </message>
    <message>
        <source>Nothing is written to the servos until you have seen the results and chosen to write them. Cancel at any point writes nothing (torque stays off).</source>
        <translation>在您查看结果并选择写入之前，不会向舵机写入任何内容。任何时候取消都不会写入任何内容（扭矩保持关闭）。</translation>
    </message>
    <message>
        <source>I am supporting the arm: switch torque &amp;off</source>
        <translation>我已扶住机械臂：关闭扭矩(&amp;O)</translation>
    </message>
    <message>
        <source>Switch torque off on the joints and start</source>
        <translation>关闭这些关节的扭矩并开始</translation>
    </message>
    <message>
        <source>&amp;Back</source>
        <translation>上一步(&amp;B)</translation>
    </message>
    <message>
        <source>Choose the joints again</source>
        <translation>重新选择关节</translation>
    </message>
    <message>
        <source>Move every joint to the middle of its travel (LeRobot&apos;s middle pose: the arm stretched out level, the gripper half open), then take the pose. Each joint&apos;s present position there will read 2047.</source>
        <translation>将每个关节移到其行程的中间（LeRobot 的中位姿态：机械臂水平伸直，夹爪半开），然后采集该姿态。此时每个关节的当前位置将读数为 2047。</translation>
    </message>
    <message>
        <source>&amp;Take the middle pose</source>
        <translation>采集中位姿态(&amp;T)</translation>
    </message>
    <message>
        <source>Keep the present positions as the middle</source>
        <translation>将当前位置作为中位</translation>
    </message>
    <message>
        <source>Move every joint slowly through its whole range, to both end stops, and back to the middle. Turn a full-turn joint as far as you want it to go. The bars show one turn of the encoder: the filled part is the range recorded so far, the line the present position, the dashed line the middle the range will be centred on.</source>
        <translation>将每个关节缓慢地转过其整个范围，到达两端的限位，再回到中间。整圈关节请转到您希望它能到达的位置。进度条表示编码器的一圈：填充部分是目前已记录的范围，实线是当前位置，虚线是范围将要居中的中位。</translation>
    </message>
    <message>
        <source>&amp;Finish recording</source>
        <translation>完成记录(&amp;F)</translation>
    </message>
    <message>
        <source>Stop recording and compute the calibration</source>
        <translation>停止记录并计算校准</translation>
    </message>
    <message>
        <source>%1 (%2)%3</source>
        <translation>%1 (%2)%3</translation>
    </message>
    <message>
        <source>, full turn</source>
        <translation>，整圈</translation>
    </message>
    <message>
        <source>Calibrate the new %1 servo</source>
        <translation>校准新的 %1 舵机</translation>
    </message>
    <message>
        <source>&amp;Save into %1</source>
        <translation>保存到 %1(&amp;S)</translation>
    </message>
    <message>
        <source>Update %1: this joint&apos;s offset and range replaced, the other joints kept</source>
        <translation>更新 %1：替换此关节的偏移和范围，保留其他关节</translation>
    </message>
    <message>
        <source>Save the joint into %1: the file&apos;s other joints stay as they are.</source>
        <translation>将该关节保存到 %1：文件中的其他关节保持不变。</translation>
    </message>
    <message>
        <source>Saving LeRobot&apos;s file keeps only the joints written and verified.</source>
        <translation>保存 LeRobot 文件时只保留已写入并验证的关节。</translation>
    </message>
    <message>
        <source>Save LeRobot&apos;s file if you use LeRobot with this arm.</source>
        <translation>如果您在此机械臂上使用 LeRobot，请保存 LeRobot 文件。</translation>
    </message>
    <message>
        <source>Servo ID %1 is being calibrated: close the calibration wizard first.</source>
        <translation>舵机 ID %1 正在校准：请先关闭校准向导。</translation>
    </message>
</context>
<context>
    <name>ConnectionBar</name>
    <message>
        <source>Connection</source>
        <translation>连接</translation>
    </message>
    <message>
        <source>Port </source>
        <translation>端口 </translation>
    </message>
    <message>
        <source>The serial port of the USB programmer, or a simulated servo</source>
        <translation>USB 编程器的串口，或模拟舵机</translation>
    </message>
    <message>
        <source>Baud </source>
        <translation>波特率 </translation>
    </message>
    <message>
        <source>PTK servos talk at 115200 baud. On a Feetech bus this is the rate the port opens at; a scan visits the rates it is asked to.</source>
        <translation>PTK 舵机以 115200 波特率通信。在 Feetech 总线上，这是打开端口时使用的波特率；扫描会依次尝试所要求的各个波特率。</translation>
    </message>
    <message>
        <source>Protocol </source>
        <translation>协议 </translation>
    </message>
    <message>
        <source>Auto</source>
        <translation>自动</translation>
    </message>
    <message>
        <source>PTK RC servo</source>
        <translation>PTK RC 舵机</translation>
    </message>
    <message>
        <source>Feetech bus</source>
        <translation>Feetech 总线</translation>
    </message>
    <message>
        <source>Auto: ServoBench asks the port who is there (it only asks, it writes nothing) and opens the right workspace at the right rate. PTK: one RC servo on a USB programmer. Feetech: SCS, STS, SMS and HLS servos on a serial bus.</source>
        <translation>自动：ServoBench 向端口询问连接的设备（只询问，不写入任何内容），并以正确的波特率打开相应的工作区。PTK：USB 编程器上的单个 RC 舵机。Feetech：串行总线上的 SCS、STS、SMS 和 HLS 舵机。</translation>
    </message>
    <message>
        <source>Echo </source>
        <translation>回显 </translation>
    </message>
    <message>
        <source>On</source>
        <translation>开</translation>
    </message>
    <message>
        <source>Off</source>
        <translation>关</translation>
    </message>
    <message>
        <source>Single-wire programmers send every byte back. Auto detects it.</source>
        <translation>单线编程器会回送每个字节。“自动”可检测到这一点。</translation>
    </message>
    <message>
        <source>Connect</source>
        <translation>连接</translation>
    </message>
    <message>
        <source>Disconnect</source>
        <translation>断开</translation>
    </message>
    <message>
        <source>Simulated PTK servo</source>
        <translation>模拟 PTK 舵机</translation>
    </message>
    <message>
        <source>Simulated Feetech bus</source>
        <translation>模拟 Feetech 总线</translation>
    </message>
    <message>
        <source>Simulated SO-101 arm</source>
        <translation>模拟 SO-101 机械臂</translation>
    </message>
    <message>
        <source>Choose a port</source>
        <translation>选择端口</translation>
    </message>
    <message>
        <source>Choose a serial port or a simulated servo first</source>
        <translation>请先选择串口或模拟舵机</translation>
    </message>
</context>
<context>
    <name>ConnectionController</name>
    <message>
        <source>Choose a serial port first.</source>
        <translation>请先选择一个串口。</translation>
    </message>
    <message>
        <source>The simulated servos could not start: %1</source>
        <translation>模拟舵机无法启动：%1</translation>
    </message>
    <message>
        <source>simulated SO-101 arm</source>
        <translation>模拟 SO-101 机械臂</translation>
    </message>
    <message>
        <source>simulated Feetech bus</source>
        <translation>模拟 Feetech 总线</translation>
    </message>
    <message>
        <source>simulated PTK servo</source>
        <translation>模拟 PTK 舵机</translation>
    </message>
    <message>
        <source>Enter a baud rate.</source>
        <translation>请输入波特率。</translation>
    </message>
    <message>
        <source>Auto-detection cancelled; nothing was connected.</source>
        <translation>自动检测已取消；未建立任何连接。</translation>
    </message>
    <message>
        <source>A PTK servo answers at 115,200 bps.</source>
        <translation>PTK 舵机在 115,200 bps 下应答。</translation>
    </message>
    <message>
        <source>Nothing answers on %1: the Doctor panel says what to check.</source>
        <translation>%1 上没有任何应答：“诊断”面板会说明需要检查什么。</translation>
    </message>
</context>
<context>
    <name>ControlPage</name>
    <message>
        <source>Servo ID %1</source>
        <translation>舵机 ID %1</translation>
    </message>
    <message>
        <source>Damping: the horn can be turned by hand against a resistance (torque enable 2).</source>
        <translation>阻尼：可以用手转动舵盘，但会感到阻力（扭矩开关 2）。</translation>
    </message>
    <message>
        <source>%1 servos have no damping mode.</source>
        <translation>%1 舵机没有阻尼模式。</translation>
    </message>
    <message>
        <source>Stored in EEPROM: the servo keeps it when powered off.</source>
        <translation>保存在 EEPROM 中：舵机断电后仍保留。</translation>
    </message>
    <message>
        <source>%1 servos have no operating mode register: they hold positions.</source>
        <translation>%1 舵机没有运行模式寄存器：它们保持位置。</translation>
    </message>
    <message>
        <source>Goals are limited to the servo&apos;s angle limits, %1 to %2 steps.</source>
        <translation>目标被限制在舵机的角度限制内，即 %1 到 %2 步。</translation>
    </message>
    <message>
        <source>The servo has no angle limits (multi-turn) or they are not read yet: goals are limited to the register&apos;s range, %1 to %2.</source>
        <translation>该舵机没有角度限制（多圈）或尚未读取：目标被限制在寄存器的范围内，即 %1 到 %2。</translation>
    </message>
    <message>
        <source>Torque state not read yet.</source>
        <translation>尚未读取扭矩状态。</translation>
    </message>
    <message>
        <source>Off: the horn turns freely.</source>
        <translation>关：舵盘可自由转动。</translation>
    </message>
    <message>
        <source>On: the servo holds its goal position.</source>
        <translation>开：舵机保持其目标位置。</translation>
    </message>
    <message>
        <source>Damping: the horn resists being turned.</source>
        <translation>阻尼：舵盘在被转动时会产生阻力。</translation>
    </message>
    <message>
        <source>Torque enable is %1.</source>
        <translation>扭矩开关为 %1。</translation>
    </message>
    <message>
        <source>Select a servo in the tree to control it.</source>
        <translation>在树中选择一个舵机以进行控制。</translation>
    </message>
    <message>
        <source>The bus is not connected: connect and scan to control servos.</source>
        <translation>总线未连接：请连接并扫描以控制舵机。</translation>
    </message>
    <message>
        <source>This servo&apos;s model is unknown: ServoBench does not move it.</source>
        <translation>该舵机型号未知：ServoBench 不会移动它。</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <source>No servo is selected.</source>
        <translation>未选择舵机。</translation>
    </message>
    <message>
        <source>The servo cannot be moved now: the bus is not connected or its model is unknown.</source>
        <translation>现在无法移动该舵机：总线未连接或其型号未知。</translation>
    </message>
    <message>
        <source>A test is moving %1: stop it first.</source>
        <translation>测试正在移动 %1：请先停止测试。</translation>
    </message>
    <message>
        <source>%1 has no goal position register.</source>
        <translation>%1 没有目标位置寄存器。</translation>
    </message>
    <message>
        <source>Goal %1 is outside %2, %3 to %4 steps: nothing was sent.</source>
        <translation>目标 %1 超出%2（%3 到 %4 步）：未发送任何内容。</translation>
    </message>
    <message>
        <source>the servo&apos;s angle limits</source>
        <translation>舵机的角度限制</translation>
    </message>
    <message>
        <source>the goal position range</source>
        <translation>目标位置范围</translation>
    </message>
    <message>
        <source>Torque is off: %1 keeps the goal but does not move until torque is on.</source>
        <translation>扭矩已关闭：%1 会保留目标，但在扭矩开启之前不会移动。</translation>
    </message>
    <message>
        <source>unknown</source>
        <translation>未知</translation>
    </message>
    <message>
        <source>Change the operating mode?</source>
        <translation>更改运行模式？</translation>
    </message>
    <message>
        <source>%1 will change from “%2” to “%3”.</source>
        <translation>%1 将从“%2”改为“%3”。</translation>
    </message>
    <message>
        <source>The servo will move differently from now on: in speed or PWM mode the goal registers make it turn continuously instead of holding a position. The mode is written to EEPROM and kept after power-off.</source>
        <translation>从现在起舵机的运动方式将不同：在速度或 PWM 模式下，目标寄存器会使舵机持续转动，而不是保持在某个位置。该模式写入 EEPROM，断电后仍保留。</translation>
    </message>
    <message>
        <source>Change mode</source>
        <translation>更改模式</translation>
    </message>
    <message>
        <source>Writing to servo ID %1 failed: %2</source>
        <translation>写入舵机 ID %1 失败：%2</translation>
    </message>
    <message>
        <source>Off: All torque off was sent to every servo.</source>
        <translation>关：已向每个舵机发送“全部关闭扭矩”。</translation>
    </message>
    <message>
        <source>The bus is shared with another program: ServoBench neither reads nor moves this servo meanwhile. Stop sharing (Link › Share this bus…) to control it here.</source>
        <translation>总线正与另一个程序共享：在此期间 ServoBench 既不读取也不移动此舵机。请停止共享（连接 › 共享此总线…）后在此控制它。</translation>
    </message>
    <message>
        <source>All torque off was sent to every servo of the bus; each one&apos;s torque is read back to confirm it.</source>
        <translation>已向总线上的每个舵机发送全部关闭扭矩；将逐一读回每个舵机的扭矩以确认。</translation>
    </message>
</context>
<context>
    <name>Decoder</name>
    <message>
        <source>ID %1 (broadcast)</source>
        <translation>ID %1（广播）</translation>
    </message>
    <message>
        <source>ID %1</source>
        <translation>ID %1</translation>
    </message>
    <message>
        <source>status from %1: %2</source>
        <translation>来自 %1 的应答：%2</translation>
    </message>
    <message>
        <source>no error</source>
        <translation>无错误</translation>
    </message>
    <message>
        <source>error %1 (%2)</source>
        <translation>错误 %1（%2）</translation>
    </message>
    <message>
        <source>, data %1</source>
        <translation>，数据 %1</translation>
    </message>
    <message>
        <source>address %1 (%2), length %3</source>
        <translation>地址 %1（%2），长度 %3</translation>
    </message>
    <message>
        <source>address %1 (%2), data %3</source>
        <translation>地址 %1（%2），数据 %3</translation>
    </message>
    <message>
        <source>address %1 (%2), length %3, IDs %4</source>
        <translation>地址 %1（%2），长度 %3，ID %4</translation>
    </message>
    <message>
        <source>ID %1: %2</source>
        <translation>ID %1：%2</translation>
    </message>
    <message>
        <source>address %1 (%2), length %3; %4</source>
        <translation>地址 %1（%2），长度 %3；%4</translation>
    </message>
    <message>
        <source>current position becomes the middle</source>
        <translation>当前位置设为中位</translation>
    </message>
    <message>
        <source>current position becomes %1</source>
        <translation>当前位置设为 %1</translation>
    </message>
    <message>
        <source>parameters %1</source>
        <translation>参数 %1</translation>
    </message>
    <message numerus="yes">
        <source>incomplete frame (%n byte(s))</source>
        <translation>
            <numerusform>不完整的帧（%n 字节）</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n byte(s) that are not part of any frame</source>
        <translation>
            <numerusform>%n 字节不属于任何帧</numerusform>
        </translation>
    </message>
    <message>
        <source>query %1 (command %2) asks for %3</source>
        <translation>查询 %1（命令 %2）请求 %3</translation>
    </message>
    <message>
        <source>write %1 (command %2) %3</source>
        <translation>写入 %1（命令 %2）%3</translation>
    </message>
    <message>
        <source>with zero payload</source>
        <translation>数据为零</translation>
    </message>
    <message>
        <source>request with unknown command %1, payload %2 %3</source>
        <translation>未知命令 %1 的请求，数据 %2 %3</translation>
    </message>
    <message>
        <source>reply to %1: %2</source>
        <translation>对 %1 的应答：%2</translation>
    </message>
    <message>
        <source>reply (query unknown): words %1, %2</source>
        <translation>应答（查询未知）：字 %1，%2</translation>
    </message>
    <message>
        <source>PING</source>
        <comment>instruction</comment>
        <translation>PING（查询）</translation>
    </message>
    <message>
        <source>READ</source>
        <comment>instruction</comment>
        <translation>READ（读）</translation>
    </message>
    <message>
        <source>WRITE</source>
        <comment>instruction</comment>
        <translation>WRITE（写）</translation>
    </message>
    <message>
        <source>REG WRITE</source>
        <comment>instruction</comment>
        <translation>REG WRITE（异步写）</translation>
    </message>
    <message>
        <source>ACTION</source>
        <comment>instruction</comment>
        <translation>ACTION（执行异步写）</translation>
    </message>
    <message>
        <source>RECOVERY</source>
        <comment>instruction</comment>
        <translation>RECOVERY（恢复）</translation>
    </message>
    <message>
        <source>REBOOT</source>
        <comment>instruction</comment>
        <translation>REBOOT（重启）</translation>
    </message>
    <message>
        <source>BACKUP</source>
        <comment>instruction</comment>
        <translation>BACKUP（备份）</translation>
    </message>
    <message>
        <source>RESET</source>
        <comment>instruction</comment>
        <translation>RESET（复位）</translation>
    </message>
    <message>
        <source>CALIBRATE</source>
        <comment>instruction</comment>
        <translation>CALIBRATE（校准）</translation>
    </message>
    <message>
        <source>SYNC READ</source>
        <comment>instruction</comment>
        <translation>SYNC READ（同步读）</translation>
    </message>
    <message>
        <source>SYNC WRITE</source>
        <comment>instruction</comment>
        <translation>SYNC WRITE（同步写）</translation>
    </message>
</context>
<context>
    <name>DemoServos</name>
    <message>
        <source>Cannot create a folder for the simulated servos: %1</source>
        <translation>无法为模拟舵机创建文件夹：%1</translation>
    </message>
    <message>
        <source>Simulated PTK servo</source>
        <translation>模拟 PTK 舵机</translation>
    </message>
    <message>
        <source>Simulated Feetech bus</source>
        <translation>模拟 Feetech 总线</translation>
    </message>
    <message>
        <source>Simulated SO-101 arm</source>
        <translation>模拟 SO-101 机械臂</translation>
    </message>
    <message>
        <source>Simulated SO-101 leader arm</source>
        <translation>模拟 SO-101 主臂</translation>
    </message>
</context>
<context>
    <name>DoctorPanel</name>
    <message>
        <source>Move servo %1 (%2) to ID %3 at %4</source>
        <translation>将舵机 %1（%2）改为 ID %3，波特率 %4</translation>
    </message>
    <message>
        <source>Move servo %1 to ID %2</source>
        <translation>将舵机 %1 改为 ID %2</translation>
    </message>
    <message>
        <source>Move servo %1 to %2</source>
        <translation>将舵机 %1 改为 %2</translation>
    </message>
    <message>
        <source>Doctor</source>
        <translation>诊断</translation>
    </message>
    <message>
        <source>Scan a bus: when it comes back short, the doctor says why.</source>
        <translation>扫描总线：如果找到的舵机不全，诊断会说明原因。</translation>
    </message>
    <message>
        <source>The bus should hold:</source>
        <translation>总线上应有：</translation>
    </message>
    <message>
        <source>the servos found last time on this port</source>
        <translation>上次在此端口上找到的舵机</translation>
    </message>
    <message>
        <source>A robot template: its joints&apos; IDs in chain order, at its rate</source>
        <translation>机器人模板：按链路顺序排列的关节 ID，使用模板的波特率</translation>
    </message>
    <message>
        <source>Finding</source>
        <translation>问题</translation>
    </message>
    <message>
        <source>IDs</source>
        <translation>ID</translation>
    </message>
    <message>
        <source>What is wrong and what to do</source>
        <translation>问题所在及处理方法</translation>
    </message>
    <message>
        <source>Re-scan</source>
        <translation>重新扫描</translation>
    </message>
    <message>
        <source>Ask the port again and scan the rates that answer</source>
        <translation>重新询问端口，并扫描有应答的波特率</translation>
    </message>
    <message>
        <source>Move the servo</source>
        <translation>修正舵机地址</translation>
    </message>
    <message>
        <source>Looking at the bus on %1…</source>
        <translation>正在检查 %1 上的总线…</translation>
    </message>
    <message>
        <source>The bus on %1 holds what was expected.</source>
        <translation>%1 上的总线与预期一致。</translation>
    </message>
    <message numerus="yes">
        <source>The bus on %1: %n finding(s).</source>
        <translation>
            <numerusform>%1 上的总线：发现 %n 个问题。</numerusform>
        </translation>
    </message>
    <message>
        <source>Servo %1 is no longer on the bus; re-scan first.</source>
        <translation>舵机 %1 已不在总线上；请先重新扫描。</translation>
    </message>
    <message>
        <source>%1? Its EEPROM is written and read back.</source>
        <translation>%1？将写入其 EEPROM 并回读。</translation>
    </message>
    <message>
        <source>The servo moved to its new ID could not be found to change its rate; re-scan.</source>
        <translation>找不到已改为新 ID 的舵机，无法更改其波特率；请重新扫描。</translation>
    </message>
    <message>
        <source>Code</source>
        <translation>代码</translation>
    </message>
    <message>
        <source>%1 (code %2)</source>
        <translation>%1（代码 %2）</translation>
    </message>
    <message>
        <source>The finding&apos;s code, as servoctl doctor prints it</source>
        <translation>该问题的代码，与 servoctl doctor 输出的一致</translation>
    </message>
</context>
<context>
    <name>Faults</name>
    <message>
        <source>--faults: &quot;%1&quot; is not NAME=VALUE</source>
        <translation>--faults：“%1”不是 NAME=VALUE 格式</translation>
    </message>
    <message>
        <source>--faults: &quot;%1&quot; is not a number</source>
        <translation>--faults：“%1”不是数字</translation>
    </message>
    <message>
        <source>--faults: delay is in milliseconds, 0 to 60000</source>
        <translation>--faults：delay 以毫秒为单位，范围 0 到 60000</translation>
    </message>
    <message>
        <source>--faults: %1 is a probability from 0 to 1</source>
        <translation>--faults：%1 是 0 到 1 之间的概率</translation>
    </message>
    <message>
        <source>--faults: unknown fault &quot;%1&quot; (drop, corrupt, truncate, noise, delay, lost)</source>
        <translation>--faults：未知故障“%1”（drop、corrupt、truncate、noise、delay、lost）</translation>
    </message>
</context>
<context>
    <name>FeetechBusClient</name>
    <message>
        <source>The bus is not connected.</source>
        <translation>总线未连接。</translation>
    </message>
    <message>
        <source>No servo is selected.</source>
        <translation>未选择舵机。</translation>
    </message>
    <message>
        <source>Another operation is still running.</source>
        <translation>另一个操作仍在进行中。</translation>
    </message>
    <message>
        <source>This servo&apos;s model is unknown; its memory is shown read-only.</source>
        <translation>该舵机型号未知；其内存以只读方式显示。</translation>
    </message>
    <message>
        <source>ID %1 is already in use on this bus.</source>
        <translation>ID %1 已在此总线上使用。</translation>
    </message>
    <message>
        <source>This servo has no middle calibration (SCS servos have no offset register).</source>
        <translation>该舵机不支持中位校准（SCS 舵机没有偏移寄存器）。</translation>
    </message>
    <message>
        <source>Choose at least one servo to monitor.</source>
        <translation>请至少选择一个要监视的舵机。</translation>
    </message>
    <message>
        <source>The rate cannot be negative.</source>
        <translation>速率不能为负数。</translation>
    </message>
    <message>
        <source>Servo %1 is of an unknown model: its feedback cannot be decoded.</source>
        <translation>舵机 %1 型号未知：无法解码其反馈。</translation>
    </message>
    <message>
        <source>Nothing to write.</source>
        <translation>没有要写入的内容。</translation>
    </message>
    <message>
        <source>Nothing to move.</source>
        <translation>没有要移动的内容。</translation>
    </message>
    <message>
        <source>Servo %1 is of an unknown model; nothing is written to it.</source>
        <translation>舵机 %1 型号未知；不会向其写入任何内容。</translation>
    </message>
    <message>
        <source>Servo %1: %2</source>
        <translation>舵机 %1：%2</translation>
    </message>
    <message>
        <source>This servo has no status register: there is nothing to recover.</source>
        <translation>该舵机没有状态寄存器：无需恢复。</translation>
    </message>
    <message>
        <source>No servo to check: scan the bus first.</source>
        <translation>没有可检查的舵机：请先扫描总线。</translation>
    </message>
    <message>
        <source>The move test moves servo %1: it runs only once that is confirmed.</source>
        <translation>运动测试会移动舵机 %1：需确认后才会运行。</translation>
    </message>
    <message>
        <source>This servo has no goal position register: it cannot be moved.</source>
        <translation>该舵机没有目标位置寄存器：无法移动。</translation>
    </message>
    <message>
        <source>That is not a whole Feetech frame (header, length and checksum).</source>
        <translation>这不是完整的飞特帧（帧头、长度和校验和）。</translation>
    </message>
    <message>
        <source>%1 bps is not a Feetech baud rate.</source>
        <translation>%1 bps 不是飞特的波特率。</translation>
    </message>
    <message>
        <source>The recording moves servo %1, which the scan did not find: nothing was moved.</source>
        <translation>该记录会移动舵机 %1，但扫描未找到它：未移动任何舵机。</translation>
    </message>
    <message>
        <source>The servos to record answer at different baud rates: choose servos at one rate.</source>
        <translation>要记录的舵机在不同的波特率下应答：请选择同一波特率的舵机。</translation>
    </message>
    <message>
        <source>The bus is shared with another program: this would change the port&apos;s rate under it. Stop sharing first.</source>
        <translation>总线正与另一个程序共享：这会在该程序不知情的情况下更改端口的波特率。请先停止共享。</translation>
    </message>
    <message>
        <source>The bus is shared already.</source>
        <translation>总线已在共享中。</translation>
    </message>
    <message>
        <source>Name the path the other program opens.</source>
        <translation>请指定另一个程序要打开的路径。</translation>
    </message>
</context>
<context>
    <name>FeetechGuard</name>
    <message>
        <source>Servo %1 has no torque switch the guard could use.</source>
        <translation>舵机 %1 没有可供监护使用的扭矩开关。</translation>
    </message>
    <message>
        <source>Guard: torque off of servo %1</source>
        <translation>监护：关闭舵机 %1 的扭矩</translation>
    </message>
    <message>
        <source>Hold where it stands</source>
        <translation>保持在当前位置</translation>
    </message>
    <message>
        <source>Torque off</source>
        <translation>关闭扭矩</translation>
    </message>
    <message>
        <source>Servo ID %1</source>
        <translation>舵机 ID %1</translation>
    </message>
    <message>
        <source>its goal was set to where it stands (%1)</source>
        <translation>其目标已设为当前所在位置（%1）</translation>
    </message>
    <message>
        <source>its goal was set to where it stands</source>
        <translation>其目标已设为当前所在位置</translation>
    </message>
    <message>
        <source>its torque was switched off</source>
        <translation>其扭矩已关闭</translation>
    </message>
    <message>
        <source>temperature %1 °C, its maximum is %2 °C</source>
        <translation>温度 %1 °C，其上限为 %2 °C</translation>
    </message>
    <message>
        <source>current %1 mA above the guard&apos;s %2 mA</source>
        <translation>电流 %1 mA，高于监护限值 %2 mA</translation>
    </message>
    <message>
        <source>load %1 % above the guard&apos;s %2 %</source>
        <translation>负载 %1 %，高于监护限值 %2 %</translation>
    </message>
    <message>
        <source>%1: its own overload protection tripped (status bit Load is set); its torque is off. Use Recover to switch it off and on again.</source>
        <translation>%1：舵机自身的过载保护已触发（状态位 Load 已置位）；其扭矩已关闭。请使用“恢复”将扭矩关闭后再开启。</translation>
    </message>
    <message>
        <source>Guard warning: %1 is hot (%2); the guard acts at %3 °C.</source>
        <translation>监护警告：%1 过热（%2）；监护将在 %3 °C 时动作。</translation>
    </message>
    <message>
        <source>Guard warning: %1 is straining (%2); the guard acts if it lasts %3 s.</source>
        <translation>监护警告：%1 负载过大（%2）；若持续 %3 秒，监护将动作。</translation>
    </message>
    <message>
        <source>Guard: %1 (%2) could not be stopped: %3. Switch its torque off.</source>
        <translation>监护：无法停止 %1（%2）：%3。请关闭其扭矩。</translation>
    </message>
    <message>
        <source>Guard: %1 was too hot (%2): %3.</source>
        <translation>监护：%1 温度过高（%2）：%3。</translation>
    </message>
    <message>
        <source>Guard: %1 was overloaded for %2 s (%3): %4.</source>
        <translation>监护：%1 过载持续了 %2 秒（%3）：%4。</translation>
    </message>
    <message>
        <source>Guard: %1 is held but still loaded (%2): free the horn or switch its torque off before its own protection trips.</source>
        <translation>监护：%1 已保持位置但仍有负载（%2）：请在其自身保护触发前松开舵盘或关闭其扭矩。</translation>
    </message>
    <message>
        <source>%1: the overload protection is no longer tripped.</source>
        <translation>%1：过载保护已解除。</translation>
    </message>
    <message>
        <source>%1 has no torque, goal or status register to recover with.</source>
        <translation>%1 没有可用于恢复的扭矩、目标或状态寄存器。</translation>
    </message>
    <message>
        <source>Recovery: torque off</source>
        <translation>恢复：关闭扭矩</translation>
    </message>
    <message>
        <source>Recovery: torque on again</source>
        <translation>恢复：重新开启扭矩</translation>
    </message>
    <message>
        <source>The status of %1 could not be read.</source>
        <translation>无法读取 %1 的状态。</translation>
    </message>
    <message>
        <source>Recovery: torque off (still tripped)</source>
        <translation>恢复：关闭扭矩（仍处于保护状态）</translation>
    </message>
    <message>
        <source>The overload bit of servo ID %1 stays set after torque off and on: only a power cycle clears it.</source>
        <translation>舵机 ID %1 的过载位在关闭并重新开启扭矩后仍然置位：只有断电重启才能清除。</translation>
    </message>
    <message>
        <source>1. Free the horn: remove whatever blocks it or the load it holds.</source>
        <translation>1. 松开舵盘：移除阻挡它的物体或它所承受的负载。</translation>
    </message>
    <message>
        <source>2. Switch the servos&apos; power supply off (the USB adapter may stay connected).</source>
        <translation>2. 关闭舵机电源（USB 适配器可以保持连接）。</translation>
    </message>
    <message>
        <source>3. Wait five seconds, then switch the power on again.</source>
        <translation>3. 等待五秒，然后重新接通电源。</translation>
    </message>
    <message>
        <source>4. Check again: only the status is read; torque stays off until you switch it on.</source>
        <translation>4. 再次检查：只读取状态；在您开启扭矩之前扭矩保持关闭。</translation>
    </message>
</context>
<context>
    <name>FeetechParameters</name>
    <message>
        <source>Other EEPROM</source>
        <translation>其他 EEPROM</translation>
    </message>
    <message>
        <source>Other RAM</source>
        <translation>其他 RAM</translation>
    </message>
    <message>
        <source>Identity and link</source>
        <translation>身份与通信</translation>
    </message>
    <message>
        <source>Travel and mode</source>
        <translation>行程与模式</translation>
    </message>
    <message>
        <source>Control loop</source>
        <translation>控制环</translation>
    </message>
    <message>
        <source>Limits and protection</source>
        <translation>限制与保护</translation>
    </message>
    <message>
        <source>%1 is not a writable register of %2.</source>
        <translation>%1 不是 %2 的可写寄存器。</translation>
    </message>
    <message>
        <source>%1 = %2 is out of range (%3 to %4).</source>
        <translation>%1 = %2 超出范围（%3 到 %4）。</translation>
    </message>
    <message>
        <source>%1 = %2 does not fit the register.</source>
        <translation>%1 = %2 超出寄存器的容量。</translation>
    </message>
    <message>
        <source>baud_rate: %1 bps is not a Feetech baud rate.</source>
        <translation>baud_rate：%1 bps 不是 Feetech 支持的波特率。</translation>
    </message>
    <message>
        <source>%1: &quot;%2&quot; is not a number.</source>
        <translation>%1：“%2”不是数字。</translation>
    </message>
    <message>
        <source>%1: &quot;%2&quot; is not a whole number.</source>
        <translation>%1：“%2”不是整数。</translation>
    </message>
    <message>
        <source>bit %1</source>
        <translation>位 %1</translation>
    </message>
    <message>
        <source>none</source>
        <translation>无</translation>
    </message>
    <message>
        <source>%1: %2 is not a whole number of steps of %3: set to %4.</source>
        <translation>%1：%2 不是步长 %3 的整数倍：已设为 %4。</translation>
    </message>
</context>
<context>
    <name>FeetechRegister</name>
    <message>
        <source>HLS (HLSCL layer)</source>
        <translation>HLS（HLSCL 层）</translation>
    </message>
    <message>
        <source>Firmware major</source>
        <translation>固件主版本号</translation>
    </message>
    <message>
        <source>Firmware minor</source>
        <translation>固件次版本号</translation>
    </message>
    <message>
        <source>HLS firmware reports minor 40-59.</source>
        <translation>HLS 固件报告的次版本号为 40-59。</translation>
    </message>
    <message>
        <source>Byte order (END)</source>
        <translation>字节顺序（END）</translation>
    </message>
    <message>
        <source>Little-endian</source>
        <translation>小端序</translation>
    </message>
    <message>
        <source>Big-endian</source>
        <translation>大端序</translation>
    </message>
    <message>
        <source>Model major</source>
        <translation>型号主版本号</translation>
    </message>
    <message>
        <source>Model minor</source>
        <translation>型号次版本号</translation>
    </message>
    <message>
        <source>ID</source>
        <translation>ID</translation>
    </message>
    <message>
        <source>Baud rate</source>
        <translation>波特率</translation>
    </message>
    <message>
        <source>Codes 8-11 (19200/14400/9600/4800) appear only in the WIKI protocol index. LeRobot maps 5-7 to 57600/38400/19200; Feetech sources say 76800/57600/38400.</source>
        <translation>代码 8-11（19200/14400/9600/4800）仅出现在 WIKI 协议索引中。LeRobot 将 5-7 映射为 57600/38400/19200；Feetech 资料则为 76800/57600/38400。</translation>
    </message>
    <message>
        <source>1000000 bps</source>
        <translation>1000000 bps</translation>
    </message>
    <message>
        <source>500000 bps</source>
        <translation>500000 bps</translation>
    </message>
    <message>
        <source>250000 bps</source>
        <translation>250000 bps</translation>
    </message>
    <message>
        <source>128000 bps</source>
        <translation>128000 bps</translation>
    </message>
    <message>
        <source>115200 bps</source>
        <translation>115200 bps</translation>
    </message>
    <message>
        <source>76800 bps</source>
        <translation>76800 bps</translation>
    </message>
    <message>
        <source>57600 bps</source>
        <translation>57600 bps</translation>
    </message>
    <message>
        <source>38400 bps</source>
        <translation>38400 bps</translation>
    </message>
    <message>
        <source>Secondary ID</source>
        <translation>副 ID</translation>
    </message>
    <message>
        <source>Applies to WRITE, REG WRITE, ACTION, SYNC WRITE; writing the main ID also updates it.</source>
        <translation>适用于 WRITE、REG WRITE、ACTION、SYNC WRITE；写入主 ID 时也会更新它。</translation>
    </message>
    <message>
        <source>Response level</source>
        <translation>应答状态级别</translation>
    </message>
    <message>
        <source>READ and PING only</source>
        <translation>仅 READ 和 PING</translation>
    </message>
    <message>
        <source>All instructions</source>
        <translation>所有指令</translation>
    </message>
    <message>
        <source>Min angle limit</source>
        <translation>最小角度限制</translation>
    </message>
    <message>
        <source>Range per WIKI; the STS3215 sheet allows down to -32766. Min = max = 0 selects multi-turn / step mode.</source>
        <translation>范围依据 WIKI；STS3215 规格表允许低至 -32766。最小 = 最大 = 0 时选择多圈/步进模式。</translation>
    </message>
    <message>
        <source>step</source>
        <translation>步</translation>
    </message>
    <message>
        <source>Max angle limit</source>
        <translation>最大角度限制</translation>
    </message>
    <message>
        <source>WIKI range 1-4095; 0 allowed here because min = max = 0 selects multi-turn / step mode. The STS3215 sheet allows up to 32767.</source>
        <translation>WIKI 范围为 1-4095；此处允许 0，因为最小 = 最大 = 0 时选择多圈/步进模式。STS3215 规格表允许高达 32767。</translation>
    </message>
    <message>
        <source>Max temperature</source>
        <translation>最高温度</translation>
    </message>
    <message>
        <source>°C</source>
        <translation>°C</translation>
    </message>
    <message>
        <source>Max input voltage</source>
        <translation>最高输入电压</translation>
    </message>
    <message>
        <source>V</source>
        <translation>V</translation>
    </message>
    <message>
        <source>Min input voltage</source>
        <translation>最低输入电压</translation>
    </message>
    <message>
        <source>Max torque</source>
        <translation>最大扭矩</translation>
    </message>
    <message>
        <source>Copied to torque limit (48) at power-on.</source>
        <translation>上电时复制到扭矩限制（48）。</translation>
    </message>
    <message>
        <source>%</source>
        <translation>%</translation>
    </message>
    <message>
        <source>Phase (special functions)</source>
        <translation>相位（特殊功能）</translation>
    </message>
    <message>
        <source>Bit 0 encoder type from firmware 3.44.</source>
        <translation>位 0 为编码器类型，自固件 3.44 起。</translation>
    </message>
    <message>
        <source>Encoder type AS5600/MT6701</source>
        <translation>编码器类型 AS5600/MT6701</translation>
    </message>
    <message>
        <source>Current feedback direction</source>
        <translation>电流反馈方向</translation>
    </message>
    <message>
        <source>Bridge direction</source>
        <translation>桥方向</translation>
    </message>
    <message>
        <source>Full-angle (multi-turn) feedback</source>
        <translation>全角度（多圈）反馈</translation>
    </message>
    <message>
        <source>Bridge configuration</source>
        <translation>桥配置</translation>
    </message>
    <message>
        <source>PWM frequency</source>
        <translation>PWM 频率</translation>
    </message>
    <message>
        <source>Position direction</source>
        <translation>位置方向</translation>
    </message>
    <message>
        <source>Unload conditions</source>
        <translation>卸载条件</translation>
    </message>
    <message>
        <source>Voltage</source>
        <translation>电压</translation>
    </message>
    <message>
        <source>Encoder</source>
        <translation>编码器</translation>
    </message>
    <message>
        <source>Temperature</source>
        <translation>温度</translation>
    </message>
    <message>
        <source>Current</source>
        <translation>电流</translation>
    </message>
    <message>
        <source>LED alarm conditions</source>
        <translation>LED 报警条件</translation>
    </message>
    <message>
        <source>Position P gain</source>
        <translation>位置环 P 增益</translation>
    </message>
    <message>
        <source>Copied to RAM 50 at power-on.</source>
        <translation>上电时复制到 RAM 50。</translation>
    </message>
    <message>
        <source>Position D gain</source>
        <translation>位置环 D 增益</translation>
    </message>
    <message>
        <source>Copied to RAM 51 at power-on.</source>
        <translation>上电时复制到 RAM 51。</translation>
    </message>
    <message>
        <source>Position I gain</source>
        <translation>位置环 I 增益</translation>
    </message>
    <message>
        <source>Copied to RAM 52 at power-on.</source>
        <translation>上电时复制到 RAM 52。</translation>
    </message>
    <message>
        <source>Min startup force</source>
        <translation>最小启动力</translation>
    </message>
    <message>
        <source>Firmware dependent: newer WIKI-STS has 24 as 1 byte and 25 as integral limit (x4, 0 = off).</source>
        <translation>取决于固件：较新的 WIKI-STS 中 24 为 1 字节，25 为积分限幅（×4，0 = 关闭）。</translation>
    </message>
    <message>
        <source>CW dead zone</source>
        <translation>CW 不灵敏区</translation>
    </message>
    <message>
        <source>Range per WIKI; the STS3215 sheet allows 0-32.</source>
        <translation>范围依据 WIKI；STS3215 规格表允许 0-32。</translation>
    </message>
    <message>
        <source>CCW dead zone</source>
        <translation>CCW 不灵敏区</translation>
    </message>
    <message>
        <source>Protection current</source>
        <translation>保护电流</translation>
    </message>
    <message>
        <source>Copied to goal current (44) at power-on. Range per WIKI-STS.</source>
        <translation>上电时复制到目标电流（44）。范围依据 WIKI-STS。</translation>
    </message>
    <message>
        <source>mA</source>
        <translation>mA</translation>
    </message>
    <message>
        <source>Angular resolution</source>
        <translation>角度分辨率</translation>
    </message>
    <message>
        <source>Range per WIKI; the STS3215 sheet allows 1-3. Multiplies the step size in multi-turn use.</source>
        <translation>范围依据 WIKI；STS3215 规格表允许 1-3。在多圈使用时作为步长的倍数。</translation>
    </message>
    <message>
        <source>Position offset</source>
        <translation>位置偏移</translation>
    </message>
    <message>
        <source>Sign-magnitude, sign bit 15 on HLS.</source>
        <translation>符号-数值编码，HLS 上符号位为第 15 位。</translation>
    </message>
    <message>
        <source>Operating mode</source>
        <translation>运行模式</translation>
    </message>
    <message>
        <source>Position + current limit</source>
        <translation>位置 + 电流限制</translation>
    </message>
    <message>
        <source>Constant speed + current limit</source>
        <translation>恒速 + 电流限制</translation>
    </message>
    <message>
        <source>Constant current (torque)</source>
        <translation>恒流（扭矩）</translation>
    </message>
    <message>
        <source>PWM open loop</source>
        <translation>PWM 开环</translation>
    </message>
    <message>
        <source>Current loop P gain</source>
        <translation>电流环 P 增益</translation>
    </message>
    <message>
        <source>Current loop I gain</source>
        <translation>电流环 I 增益</translation>
    </message>
    <message>
        <source>Speed P gain</source>
        <translation>速度环 P 增益</translation>
    </message>
    <message>
        <source>Over-current protection time</source>
        <translation>过流保护时间</translation>
    </message>
    <message>
        <source>ms</source>
        <translation>ms</translation>
    </message>
    <message>
        <source>Speed I gain</source>
        <translation>速度环 I 增益</translation>
    </message>
    <message>
        <source>Torque enable</source>
        <translation>扭矩开关</translation>
    </message>
    <message>
        <source>128-calibration not supported per WIKI-PROTO (LINUX-FORK writes 128 anyway); prefer instruction 0x0B.</source>
        <translation>根据 WIKI-PROTO 不支持写 128 校准（LINUX-FORK 仍会写 128）；建议使用指令 0x0B。</translation>
    </message>
    <message>
        <source>Off</source>
        <translation>关闭</translation>
    </message>
    <message>
        <source>On</source>
        <translation>开启</translation>
    </message>
    <message>
        <source>Damping</source>
        <translation>阻尼</translation>
    </message>
    <message>
        <source>Acceleration</source>
        <translation>加速度</translation>
    </message>
    <message>
        <source>0 = maximum acceleration.</source>
        <translation>0 = 最大加速度。</translation>
    </message>
    <message>
        <source>step/s²</source>
        <translation>步/秒²</translation>
    </message>
    <message>
        <source>Goal position</source>
        <translation>目标位置</translation>
    </message>
    <message>
        <source>Goal current</source>
        <translation>目标电流</translation>
    </message>
    <message>
        <source>SDK name GOAL_TORQUE. Loaded from protection current (28) at power-on. In PWM mode (3): duty +/-1000 with direction bit 10.</source>
        <translation>SDK 名称为 GOAL_TORQUE。上电时从保护电流（28）载入。在 PWM 模式（3）下：占空比 +/-1000，方向位为第 10 位。</translation>
    </message>
    <message>
        <source>Goal speed</source>
        <translation>目标速度</translation>
    </message>
    <message>
        <source>Unit 0.732 rpm per WIKI-HLS; range undocumented. 0 = stop.</source>
        <translation>根据 WIKI-HLS，单位为 0.732 rpm；范围未见文档。0 = 停止。</translation>
    </message>
    <message>
        <source>rpm</source>
        <translation>rpm</translation>
    </message>
    <message>
        <source>Torque limit</source>
        <translation>扭矩限制</translation>
    </message>
    <message>
        <source>Loaded from max torque (16) at power-on.</source>
        <translation>上电时从最大扭矩（16）载入。</translation>
    </message>
    <message>
        <source>Live position P gain</source>
        <translation>实时位置环 P 增益</translation>
    </message>
    <message>
        <source>Loaded from 21 at power-on.</source>
        <translation>上电时从 21 载入。</translation>
    </message>
    <message>
        <source>Live position D gain</source>
        <translation>实时位置环 D 增益</translation>
    </message>
    <message>
        <source>Loaded from 22 at power-on.</source>
        <translation>上电时从 22 载入。</translation>
    </message>
    <message>
        <source>Live position I gain</source>
        <translation>实时位置环 I 增益</translation>
    </message>
    <message>
        <source>Loaded at power-on from 23 (per the EEPROM row) or 39 (per the RAM row); sources disagree.</source>
        <translation>上电时从 23（依据 EEPROM 行）或 39（依据 RAM 行）载入；各资料说法不一。</translation>
    </message>
    <message>
        <source>EEPROM lock</source>
        <translation>锁标志</translation>
    </message>
    <message>
        <source>Power-on value 1 per WIKI/FDQT, 0 per the STS3215 sheet: write 0 before EEPROM writes and 1 afterwards.</source>
        <translation>根据 WIKI/FDQT 上电值为 1，根据 STS3215 规格表为 0：写 EEPROM 前写入 0，写完后写入 1。</translation>
    </message>
    <message>
        <source>Unlocked</source>
        <translation>已解锁</translation>
    </message>
    <message>
        <source>Locked</source>
        <translation>已上锁</translation>
    </message>
    <message>
        <source>Present position</source>
        <translation>当前位置</translation>
    </message>
    <message>
        <source>In step mode (3): remaining steps.</source>
        <translation>在步进模式（3）下：剩余步数。</translation>
    </message>
    <message>
        <source>Present speed</source>
        <translation>当前速度</translation>
    </message>
    <message>
        <source>step/s</source>
        <translation>步/秒</translation>
    </message>
    <message>
        <source>Present load</source>
        <translation>当前负载</translation>
    </message>
    <message>
        <source>Present voltage</source>
        <translation>当前电压</translation>
    </message>
    <message>
        <source>Present temperature</source>
        <translation>当前温度</translation>
    </message>
    <message>
        <source>Async write flag</source>
        <translation>异步写标志</translation>
    </message>
    <message>
        <source>Servo status</source>
        <translation>舵机状态</translation>
    </message>
    <message>
        <source>Moving</source>
        <translation>移动标志</translation>
    </message>
    <message>
        <source>Above speed threshold</source>
        <translation>超过速度阈值</translation>
    </message>
    <message>
        <source>Target not reached</source>
        <translation>未到达目标</translation>
    </message>
    <message>
        <source>Current goal position</source>
        <translation>当前目标位置</translation>
    </message>
    <message>
        <source>WIKI; LeRobot instead names 71-72 &quot;Goal_Position_2&quot;. Sign encoding undocumented.</source>
        <translation>依据 WIKI；LeRobot 则将 71-72 命名为 &quot;Goal_Position_2&quot;。符号编码未见文档。</translation>
    </message>
    <message>
        <source>Present current</source>
        <translation>当前电流</translation>
    </message>
    <message>
        <source>Current zero offset</source>
        <translation>电流零点偏移</translation>
    </message>
    <message>
        <source>vFk</source>
        <translation>vFk</translation>
    </message>
    <message>
        <source>vKgI</source>
        <translation>vKgI</translation>
    </message>
    <message>
        <source>pFk</source>
        <translation>pFk</translation>
    </message>
    <message>
        <source>Moving speed threshold</source>
        <translation>移动速度阈值</translation>
    </message>
    <message>
        <source>DTs</source>
        <translation>DTs</translation>
    </message>
    <message>
        <source>eFk</source>
        <translation>eFk</translation>
    </message>
    <message>
        <source>Vk</source>
        <translation>Vk</translation>
    </message>
    <message>
        <source>Max speed limit</source>
        <translation>最大速度限制</translation>
    </message>
    <message>
        <source>Max acceleration</source>
        <translation>最大加速度</translation>
    </message>
    <message>
        <source>Acceleration multiplier</source>
        <translation>加速度倍率</translation>
    </message>
    <message>
        <source>SCS (SCSCL layer)</source>
        <translation>SCS（SCSCL 层）</translation>
    </message>
    <message>
        <source>May be absent on old SCS firmware.</source>
        <translation>旧版 SCS 固件上可能不存在。</translation>
    </message>
    <message>
        <source>Factory 1 Mbps or 500 kbps depending on model. Codes 8-11 (19200/14400/9600/4800) appear only in the WIKI protocol index. LeRobot maps 5-7 to 57600/38400/19200; Feetech sources say 76800/57600/38400.</source>
        <translation>出厂值因型号而异，为 1 Mbps 或 500 kbps。代码 8-11（19200/14400/9600/4800）仅出现在 WIKI 协议索引中。LeRobot 将 5-7 映射为 57600/38400/19200；Feetech 资料则为 76800/57600/38400。</translation>
    </message>
    <message>
        <source>Return delay</source>
        <translation>返回延时</translation>
    </message>
    <message>
        <source>May be unsupported: WIKI-SCS lists this address as undefined; LeRobot and FDQT (default 250) use it as return delay.</source>
        <translation>可能不受支持：WIKI-SCS 将此地址列为未定义；LeRobot 和 FDQT（默认 250）将其用作返回延时。</translation>
    </message>
    <message>
        <source>µs</source>
        <translation>µs</translation>
    </message>
    <message>
        <source>Min = max = 0 selects motor (PWM) mode.</source>
        <translation>最小 = 最大 = 0 时选择电机（PWM）模式。</translation>
    </message>
    <message>
        <source>Documented range 1-1023; 0 allowed here because min = max = 0 selects motor (PWM) mode.</source>
        <translation>文档范围为 1-1023；此处允许 0，因为最小 = 最大 = 0 时选择电机（PWM）模式。</translation>
    </message>
    <message>
        <source>Max = min = 0 disables the voltage check.</source>
        <translation>最大 = 最小 = 0 时禁用电压检查。</translation>
    </message>
    <message>
        <source>Copied to the torque limit at power-on.</source>
        <translation>上电时复制到扭矩限制。</translation>
    </message>
    <message>
        <source>Direction</source>
        <translation>方向</translation>
    </message>
    <message>
        <source>Speed 0 = stop/max</source>
        <translation>速度 0 = 停止/最大</translation>
    </message>
    <message>
        <source>PWM phase</source>
        <translation>PWM 相位</translation>
    </message>
    <message>
        <source>Voltage sampling</source>
        <translation>电压采样</translation>
    </message>
    <message>
        <source>Load</source>
        <translation>负载</translation>
    </message>
    <message>
        <source>May be unsupported: WIKI-SCS lists this address as undefined; LeRobot names it I coefficient.</source>
        <translation>可能不受支持：WIKI-SCS 将此地址列为未定义；LeRobot 将其命名为 I 系数。</translation>
    </message>
    <message>
        <source>FDQT default 2.</source>
        <translation>FDQT 默认值为 2。</translation>
    </message>
    <message>
        <source>Holding torque</source>
        <translation>保持扭矩</translation>
    </message>
    <message>
        <source>Protection time</source>
        <translation>保护时间</translation>
    </message>
    <message>
        <source>Overload torque</source>
        <translation>过载扭矩</translation>
    </message>
    <message>
        <source>No 128 calibration on SCS.</source>
        <translation>SCS 不支持 128 校准。</translation>
    </message>
    <message>
        <source>Off (free)</source>
        <translation>关闭（自由）</translation>
    </message>
    <message>
        <source>May be unsupported: WIKI-SCS lists this address as undefined; LeRobot and LINUX-FORK name it Acceleration.</source>
        <translation>可能不受支持：WIKI-SCS 将此地址列为未定义；LeRobot 和 LINUX-FORK 将其命名为 Acceleration。</translation>
    </message>
    <message>
        <source>Goal time / PWM</source>
        <translation>运行时间 / PWM</translation>
    </message>
    <message>
        <source>Time is used when goal speed = 0. In motor mode (min = max angle = 0) this is PWM duty, 0.1 % units, +/-1000 with direction bit 10.</source>
        <translation>目标速度 = 0 时使用时间。在电机模式下（最小 = 最大角度 = 0）此值为 PWM 占空比，单位 0.1 %，+/-1000，方向位为第 10 位。</translation>
    </message>
    <message>
        <source>Factory value = the model&apos;s max speed.</source>
        <translation>出厂值 = 该型号的最大速度。</translation>
    </message>
    <message>
        <source>Unsigned on SCS (no sign decoding in the SDKs).</source>
        <translation>SCS 上为无符号（各 SDK 均不做符号解码）。</translation>
    </message>
    <message>
        <source>Read by the C++ SDK feedback block (56-70); absent from WIKI-SCS and FDQT tables. Units undocumented.</source>
        <translation>由 C++ SDK 的反馈块（56-70）读取；WIKI-SCS 和 FDQT 表中没有。单位未见文档。</translation>
    </message>
    <message>
        <source>PWM mode max step</source>
        <translation>PWM 模式最大步长</translation>
    </message>
    <message>
        <source>Factory area at LeRobot&apos;s decimal addresses 78-83; the WIKI hex column is off by one.</source>
        <translation>出厂区位于 LeRobot 的十进制地址 78-83；WIKI 的十六进制列差了一位。</translation>
    </message>
    <message>
        <source>Min speed limit</source>
        <translation>最小速度限制</translation>
    </message>
    <message>
        <source>Factory acceleration</source>
        <translation>出厂加速度</translation>
    </message>
    <message>
        <source>SMS (SMS_STS layer, RS485)</source>
        <translation>SMS（SMS_STS 层，RS485）</translation>
    </message>
    <message>
        <source>Valid values 0 or 50-253 (WIKI-SMS); values below 50 act as 50 (100 µs). Factory value 0 per WIKI-SMS, 250 per LeRobot/FDQT: read it, don&apos;t assume.</source>
        <translation>有效值为 0 或 50-253（WIKI-SMS）；低于 50 的值按 50（100 µs）处理。出厂值依据 WIKI-SMS 为 0，依据 LeRobot/FDQT 为 250：请读取，不要假定。</translation>
    </message>
    <message>
        <source>Driver direction</source>
        <translation>驱动方向</translation>
    </message>
    <message>
        <source>Bridge brushed/none</source>
        <translation>桥：有刷/无</translation>
    </message>
    <message>
        <source>Speed unit 0.732/0.0146 rpm</source>
        <translation>速度单位 0.732/0.0146 rpm</translation>
    </message>
    <message>
        <source>Voltage sampling 1.5k/1k</source>
        <translation>电压采样 1.5k/1k</translation>
    </message>
    <message>
        <source>PWM 24/16 kHz</source>
        <translation>PWM 24/16 kHz</translation>
    </message>
    <message>
        <source>Position feedback direction</source>
        <translation>位置反馈方向</translation>
    </message>
    <message>
        <source>Range per WIKI (STS3215 sheet: 0-511).</source>
        <translation>范围依据 WIKI（STS3215 规格表：0-511）。</translation>
    </message>
    <message>
        <source>LeRobot: present = actual - offset. WIKI describes a 0-8191 encoding.</source>
        <translation>LeRobot：当前值 = 实际值 - 偏移。WIKI 描述的是 0-8191 编码。</translation>
    </message>
    <message>
        <source>WIKI-SMS table range 0-2; its text still lists 3 = step mode.</source>
        <translation>WIKI-SMS 表中范围为 0-2；其正文仍列出 3 = 步进模式。</translation>
    </message>
    <message>
        <source>Position</source>
        <translation>位置</translation>
    </message>
    <message>
        <source>Constant speed (wheel)</source>
        <translation>恒速（轮式）</translation>
    </message>
    <message>
        <source>Torque after an overload trip.</source>
        <translation>过载保护触发后的扭矩。</translation>
    </message>
    <message>
        <source>No damping value on SMS. Calibration by 128 for SMS fw &lt;= 2.54; instruction 0x0B unsupported.</source>
        <translation>SMS 没有阻尼值。SMS 固件 &lt;= 2.54 可写 128 校准；不支持指令 0x0B。</translation>
    </message>
    <message>
        <source>Calibrate middle (2048)</source>
        <translation>校准中位（2048）</translation>
    </message>
    <message>
        <source>In step mode (3): relative steps.</source>
        <translation>在步进模式（3）下：相对步数。</translation>
    </message>
    <message>
        <source>In PWM mode (2): duty +/-1000 with direction bit 10. SMS_STS position writes put 0 here.</source>
        <translation>在 PWM 模式（2）下：占空比 +/-1000，方向位为第 10 位。SMS_STS 的位置写入会在此写 0。</translation>
    </message>
    <message>
        <source>50 step/s = 0.732 rpm. 0 = maximum speed unless Phase bit 3. Sign used in wheel mode.</source>
        <translation>50 步/秒 = 0.732 rpm。0 = 最大速度，除非设置了相位第 3 位。轮式模式下使用符号。</translation>
    </message>
    <message>
        <source>Documented maximum 500 (3250 mA).</source>
        <translation>文档最大值为 500（3250 mA）。</translation>
    </message>
    <message>
        <source>Speed unit factor</source>
        <translation>速度单位系数</translation>
    </message>
    <message>
        <source>Hts</source>
        <translation>Hts</translation>
    </message>
    <message>
        <source>Valid for SMS firmware &gt;= 2.54.</source>
        <translation>适用于 SMS 固件 &gt;= 2.54。</translation>
    </message>
    <message>
        <source>ns</source>
        <translation>ns</translation>
    </message>
    <message>
        <source>Read-only per WIKI; LeRobot nevertheless writes 254 here on STS.</source>
        <translation>根据 WIKI 为只读；但 LeRobot 在 STS 上仍会在此写入 254。</translation>
    </message>
    <message>
        <source>Used when acceleration = 0.</source>
        <translation>加速度 = 0 时使用。</translation>
    </message>
    <message>
        <source>STS (SMS_STS layer)</source>
        <translation>STS（SMS_STS 层）</translation>
    </message>
    <message>
        <source>WIKI-STS marks address 7 &quot;Reserved&quot;; ST3215, LeRobot and FDQT use it as return delay. Factory value 0 (ST3215 sheet) or 250 = 500 µs (LeRobot, FDQT): read it, don&apos;t assume.</source>
        <translation>WIKI-STS 将地址 7 标为“保留”；ST3215、LeRobot 和 FDQT 将其用作返回延时。出厂值为 0（ST3215 规格表）或 250 = 500 µs（LeRobot、FDQT）：请读取，不要假定。</translation>
    </message>
    <message>
        <source>80 = 8.0 V on the 7.4 V STS3215; FDQT default 140.</source>
        <translation>在 7.4 V 的 STS3215 上 80 = 8.0 V；FDQT 默认值为 140。</translation>
    </message>
    <message>
        <source>LeRobot clears bit 4 on STS3215.</source>
        <translation>LeRobot 在 STS3215 上清除第 4 位。</translation>
    </message>
    <message>
        <source>Bridge brushless/brushed</source>
        <translation>桥：无刷/有刷</translation>
    </message>
    <message>
        <source>FDQT default 37.</source>
        <translation>FDQT 默认值为 37。</translation>
    </message>
    <message>
        <source>Default 500 and range 0-511 per STS3215 sheet; WIKI: default 511, range 0-2047.</source>
        <translation>依据 STS3215 规格表默认值为 500、范围 0-511；WIKI：默认值 511，范围 0-2047。</translation>
    </message>
    <message>
        <source>Step</source>
        <translation>步进</translation>
    </message>
    <message>
        <source>In PWM mode (2): duty +/-1000 with direction bit 10. Default 0 per STS3215 sheet, 1000 per WIKI. SMS_STS position writes put 0 here.</source>
        <translation>在 PWM 模式（2）下：占空比 +/-1000，方向位为第 10 位。依据 STS3215 规格表默认值为 0，依据 WIKI 为 1000。SMS_STS 的位置写入会在此写 0。</translation>
    </message>
    <message>
        <source>WIKI-STS; LeRobot names 83 &quot;Hts&quot;.</source>
        <translation>依据 WIKI-STS；LeRobot 将 83 命名为 &quot;Hts&quot;。</translation>
    </message>
</context>
<context>
    <name>FeetechServoList</name>
    <message>
        <source>ID</source>
        <translation>ID</translation>
    </message>
    <message>
        <source>Rate</source>
        <translation>波特率</translation>
    </message>
    <message>
        <source>Model</source>
        <translation>型号</translation>
    </message>
    <message>
        <source>Family</source>
        <translation>系列</translation>
    </message>
    <message>
        <source>Firmware</source>
        <translation>固件</translation>
    </message>
</context>
<context>
    <name>FeetechSession</name>
    <message>
        <source>The EEPROM lock could not be closed again: the servo&apos;s EEPROM may be left open. Read the servo again and lock it when it answers.</source>
        <translation>无法重新关闭 EEPROM 锁标志：舵机的 EEPROM 可能仍处于解锁状态。请重新读取舵机，并在其应答时将其上锁。</translation>
    </message>
    <message>
        <source>Nothing to write.</source>
        <translation>没有要写入的内容。</translation>
    </message>
    <message>
        <source>ID %1 is already in use on this bus.</source>
        <translation>ID %1 已在此总线上使用。</translation>
    </message>
    <message>
        <source>Servo %1 is of an unknown model; its memory is shown read-only and nothing is written to it.</source>
        <translation>舵机 %1 型号未知；其内存以只读方式显示，不会向其写入任何内容。</translation>
    </message>
    <message>
        <source>The ID and the baud rate change how the servo is reached; use Change ID or Change baud rate.</source>
        <translation>ID 和波特率决定了如何访问舵机；请使用“更改 ID”或“更改波特率”。</translation>
    </message>
    <message>
        <source>The EEPROM lock is opened and closed by ServoBench around each EEPROM write; it is not written by hand.</source>
        <translation>EEPROM 锁标志由 ServoBench 在每次写入 EEPROM 前后自动解锁和上锁；不能手动写入。</translation>
    </message>
    <message>
        <source>Torque enable 128 recalibrates the middle; use Calibrate middle.</source>
        <translation>扭矩开关写入 128 会重新校准中位；请使用“中位校准”。</translation>
    </message>
    <message>
        <source>Writing address %1</source>
        <translation>正在写入地址 %1</translation>
    </message>
    <message>
        <source>Written and read back.</source>
        <translation>已写入并回读。</translation>
    </message>
    <message numerus="yes">
        <source>no reply after %n attempt(s)</source>
        <translation>
            <numerusform>尝试 %n 次后仍无应答</numerusform>
        </translation>
    </message>
    <message>
        <source>the port is closed</source>
        <translation>端口已关闭</translation>
    </message>
    <message>
        <source>cancelled</source>
        <translation>已取消</translation>
    </message>
    <message>
        <source>Reading %1 bytes at address %2: %3</source>
        <translation>从地址 %2 读取 %1 字节：%3</translation>
    </message>
    <message>
        <source>servo %1 at %2</source>
        <translation>舵机 %1，波特率 %2</translation>
    </message>
    <message>
        <source>The port cannot be set to %1.</source>
        <translation>无法将端口设为 %1。</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <source>Writing %1</source>
        <translation>正在写入 %1</translation>
    </message>
    <message>
        <source>The servo&apos;s model has no known EEPROM lock register.</source>
        <translation>该舵机型号没有已知的 EEPROM 锁标志寄存器。</translation>
    </message>
    <message>
        <source>Locking the EEPROM</source>
        <translation>正在锁定 EEPROM</translation>
    </message>
    <message>
        <source>Unlocking the EEPROM</source>
        <translation>正在解锁 EEPROM</translation>
    </message>
    <message>
        <source>Reading the identity of servo %1: %2</source>
        <translation>读取舵机 %1 的身份信息：%2</translation>
    </message>
    <message>
        <source>Servo %1 does not answer.</source>
        <translation>舵机 %1 无应答。</translation>
    </message>
    <message>
        <source>Servo %1 answers at no baud rate; scan the bus to find it.</source>
        <translation>舵机 %1 在任何波特率下都无应答；请扫描总线以找到它。</translation>
    </message>
    <message numerus="yes">
        <source>Scan cancelled; %n servo(s) found before.</source>
        <translation>
            <numerusform>扫描已取消；此前找到 %n 个舵机。</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Scan complete: %n servo(s) found.</source>
        <translation>
            <numerusform>扫描完成：找到 %n 个舵机。</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 is not a Feetech baud rate.</source>
        <translation>%1 不是 Feetech 支持的波特率。</translation>
    </message>
    <message>
        <source>unknown (identity unreadable)</source>
        <translation>未知（无法读取身份信息）</translation>
    </message>
    <message>
        <source>%1 is back. Scan again if servos were changed while it was away.</source>
        <translation>%1 已恢复。如果断开期间更换过舵机，请重新扫描。</translation>
    </message>
    <message>
        <source>Not connected.</source>
        <translation>未连接。</translation>
    </message>
    <message>
        <source>Servo %1 answers.</source>
        <translation>舵机 %1 有应答。</translation>
    </message>
    <message>
        <source>Servo %1 does not answer: %2</source>
        <translation>舵机 %1 无应答：%2</translation>
    </message>
    <message>
        <source>Read %1.</source>
        <translation>已读取 %1。</translation>
    </message>
    <message>
        <source>Clearing the status</source>
        <translation>正在清除状态</translation>
    </message>
    <message>
        <source>Status of servo %1 cleared.</source>
        <translation>已清除舵机 %1 的状态。</translation>
    </message>
    <message>
        <source>Not sent: all torque off was asked for after this write.</source>
        <translation>未发送：此写入之后已请求全部关闭扭矩。</translation>
    </message>
    <message>
        <source>%1 is of an unknown model; its torque was not read back.</source>
        <translation>%1 型号未知；未回读其扭矩。</translation>
    </message>
    <message>
        <source>%1 did not confirm (no reply).</source>
        <translation>%1 未确认（无应答）。</translation>
    </message>
    <message>
        <source>%1 still has torque on.</source>
        <translation>%1 的扭矩仍处于开启状态。</translation>
    </message>
    <message>
        <source>Torque off at %1</source>
        <translation>在 %1 下关闭扭矩</translation>
    </message>
    <message numerus="yes">
        <source>Torque off: sent to the whole bus; %n servo(s) confirmed it.</source>
        <translation>
            <numerusform>关闭扭矩：已发送到整个总线；%n 个舵机已确认。</numerusform>
        </translation>
    </message>
    <message>
        <source>Torque off was sent to the whole bus, but: %1</source>
        <translation>已向整个总线发送关闭扭矩，但：%1</translation>
    </message>
    <message>
        <source>The SYNC WRITE does not fit in one packet.</source>
        <translation>SYNC WRITE 无法放入一个数据包。</translation>
    </message>
    <message>
        <source>SYNC WRITE at %1</source>
        <translation>在 %1 下执行 SYNC WRITE</translation>
    </message>
    <message numerus="yes">
        <source>Sent to %n servo(s) in one SYNC WRITE.</source>
        <translation>
            <numerusform>已通过一条 SYNC WRITE 发送到 %n 个舵机。</numerusform>
        </translation>
    </message>
    <message>
        <source>Servo ID %1: the overload bit is clear; switch its torque on when you are ready.</source>
        <translation>舵机 ID %1：过载位已清除；准备好后请开启其扭矩。</translation>
    </message>
    <message>
        <source>Servo ID %1 recovered: the overload bit is clear and it holds where it stands with torque on.</source>
        <translation>舵机 ID %1 已恢复：过载位已清除，扭矩已开启并保持在当前位置。</translation>
    </message>
    <message numerus="yes">
        <source>The health check was stopped after %1 of %n servo(s).</source>
        <translation>
            <numerusform>健康检查在检查了 %n 个舵机中的 %1 个后停止。</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n servo(s) checked.</source>
        <translation>
            <numerusform>已检查 %n 个舵机。</numerusform>
        </translation>
    </message>
    <message>
        <source>Servo %1&apos;s EEPROM is locked (read back).</source>
        <translation>舵机 %1 的 EEPROM 已锁定（已回读）。</translation>
    </message>
    <message>
        <source>Servo %1 still reads back unlocked after the lock was written.</source>
        <translation>写入锁标志后，舵机 %1 回读仍为未锁定。</translation>
    </message>
    <message numerus="yes">
        <source>%1 of %n joint(s) already set up.</source>
        <translation>
            <numerusform>%n 个关节中已有 %1 个设置完成。</numerusform>
        </translation>
    </message>
    <message>
        <source>Servo %1 is of an unknown model; its ID is not changed.</source>
        <translation>舵机 %1 型号未知；不更改其 ID。</translation>
    </message>
    <message>
        <source>ID %1 is out of range (0 to %2).</source>
        <translation>ID %1 超出范围（0 到 %2）。</translation>
    </message>
    <message>
        <source>The servo already has ID %1.</source>
        <translation>该舵机的 ID 已经是 %1。</translation>
    </message>
    <message>
        <source>ID %1 is already in use on this bus; nothing was written.</source>
        <translation>ID %1 已在此总线上使用；未写入任何内容。</translation>
    </message>
    <message>
        <source>Servo %1 now answers as ID %2.</source>
        <translation>舵机 %1 现在以 ID %2 应答。</translation>
    </message>
    <message>
        <source>The servo still has its old ID.</source>
        <translation>该舵机仍为原来的 ID。</translation>
    </message>
    <message>
        <source>Servo %1 is of an unknown model; its baud rate is not changed.</source>
        <translation>舵机 %1 型号未知；不更改其波特率。</translation>
    </message>
    <message>
        <source>%1 is not a baud rate this servo supports.</source>
        <translation>该舵机不支持波特率 %1。</translation>
    </message>
    <message>
        <source>The servo already runs at %1.</source>
        <translation>该舵机已经以 %1 运行。</translation>
    </message>
    <message>
        <source>The servo reports baud code %1 instead of %2.</source>
        <translation>舵机报告的波特率代码为 %1，而不是 %2。</translation>
    </message>
    <message>
        <source>Servo %1 now runs at %2 and answers there.</source>
        <translation>舵机 %1 现在以 %2 运行，并在该波特率下应答。</translation>
    </message>
    <message>
        <source>It still answers at %1.</source>
        <translation>它仍在 %1 下应答。</translation>
    </message>
    <message>
        <source>It answers at neither rate; scan all baud rates to find it.</source>
        <translation>它在两种波特率下都无应答；请扫描所有波特率以找到它。</translation>
    </message>
    <message>
        <source>Middle calibration is not available on this servo (SCS servos have no offset register).</source>
        <translation>该舵机不支持中位校准（SCS 舵机没有偏移寄存器）。</translation>
    </message>
    <message>
        <source>Middle calibration</source>
        <translation>中位校准</translation>
    </message>
    <message>
        <source>The present position is now the middle.</source>
        <translation>当前位置现已设为中位。</translation>
    </message>
    <message>
        <source>Servo %1 is of an unknown model; it is not reset.</source>
        <translation>舵机 %1 型号未知；不对其复位。</translation>
    </message>
    <message>
        <source>Factory reset</source>
        <translation>恢复出厂设置</translation>
    </message>
    <message>
        <source>Factory values restored; servo %1 answers at %2.</source>
        <translation>已恢复出厂值；舵机 %1 在 %2 下应答。</translation>
    </message>
    <message>
        <source>Torque off</source>
        <translation>关闭扭矩</translation>
    </message>
    <message>
        <source>Reboot</source>
        <translation>重启</translation>
    </message>
    <message>
        <source>Servo %1 restarted and answers again after %2 ms.</source>
        <translation>舵机 %1 已重启，%2 ms 后重新应答。</translation>
    </message>
    <message>
        <source>Servo %1 has not answered within %2 ms of the restart.</source>
        <translation>舵机 %1 在重启后 %2 ms 内没有应答。</translation>
    </message>
    <message>
        <source>The link closed.</source>
        <translation>连接已关闭。</translation>
    </message>
    <message>
        <source>%1 is of a model ServoBench does not move (%2): no move test.</source>
        <translation>%1 的型号是 ServoBench 不会移动的型号（%2）：不进行运动测试。</translation>
    </message>
    <message>
        <source>%1 does not answer: %2</source>
        <translation>%1 无应答：%2</translation>
    </message>
    <message>
        <source>%1 is not in position mode (mode %2): it is not moved.</source>
        <translation>%1 不在位置模式（模式 %2）：不移动它。</translation>
    </message>
    <message>
        <source>%1 holds torque enable %2, neither on nor off: it is not moved.</source>
        <translation>%1 的扭矩开关为 %2，既非开也非关：不移动它。</translation>
    </message>
    <message>
        <source>%1 stands at %2: its angle limits leave no room for a move of %3 steps.</source>
        <translation>%1 位于 %2：其角度限制没有留出移动 %3 步的空间。</translation>
    </message>
    <message>
        <source>%1 stopped answering: %2</source>
        <translation>%1 已停止应答：%2</translation>
    </message>
    <message>
        <source>The overload guard stopped the move test of %1; its goal stays where the guard held it.</source>
        <translation>过载监护停止了 %1 的运动测试；其目标保持在监护使其停住的位置。</translation>
    </message>
    <message>
        <source>All torque off: the move test of %1 was stopped.</source>
        <translation>全部关闭扭矩：已停止 %1 的运动测试。</translation>
    </message>
    <message>
        <source>%1 did not get back to %2 (it stands at %3).</source>
        <translation>%1 没有回到 %2（它位于 %3）。</translation>
    </message>
    <message>
        <source>%1 reads %2, not %3</source>
        <translation>%1 读数为 %2，而不是 %3</translation>
    </message>
    <message>
        <source>it could not be restored (%1); check its torque.</source>
        <translation>无法恢复其状态（%1）；请检查其扭矩。</translation>
    </message>
    <message>
        <source>it was not restored as it was: %1.</source>
        <translation>未能恢复原状：%1。</translation>
    </message>
    <message>
        <source>%1 moved from %2 to %3 and back; its torque is on, as it was.</source>
        <translation>%1 已从 %2 移动到 %3 并返回；其扭矩保持开启，与之前相同。</translation>
    </message>
    <message>
        <source>%1 moved from %2 to %3 and back; its torque is off, as it was.</source>
        <translation>%1 已从 %2 移动到 %3 并返回；其扭矩保持关闭，与之前相同。</translation>
    </message>
    <message>
        <source>%1 is of a model ServoBench does not move (%2); it cannot be identified.</source>
        <translation>%1 的型号是 ServoBench 不会移动的型号（%2）；无法识别它。</translation>
    </message>
    <message>
        <source>Identifying %1 was stopped; nothing was written.</source>
        <translation>已停止识别 %1；未写入任何内容。</translation>
    </message>
    <message>
        <source>%1 stands at %2, outside the goal positions it accepts: it is not moved.</source>
        <translation>%1 位于 %2，超出其可接受的目标位置范围：不移动它。</translation>
    </message>
    <message>
        <source>%1&apos;s angle limits leave no room to move it around %2.</source>
        <translation>%1 的角度限制没有留出在 %2 附近移动它的空间。</translation>
    </message>
    <message>
        <source>Identifying %1 was stopped.</source>
        <translation>已停止识别 %1。</translation>
    </message>
    <message>
        <source>All torque off: identifying %1 was stopped.</source>
        <translation>全部关闭扭矩：已停止识别 %1。</translation>
    </message>
    <message>
        <source>its registers could not be restored (%1); check its torque.</source>
        <translation>无法恢复其寄存器（%1）；请检查其扭矩。</translation>
    </message>
    <message>
        <source>%1 was moved, but %2</source>
        <translation>%1 已移动，但%2</translation>
    </message>
    <message>
        <source>%1 (%2) wiggled around %3 and is back; its torque is on, as it was.</source>
        <translation>%1（%2）在 %3 附近摆动后已返回；其扭矩保持开启，与之前相同。</translation>
    </message>
    <message>
        <source>%1 (%2) wiggled around %3 and is back; its torque is off, as it was.</source>
        <translation>%1（%2）在 %3 附近摆动后已返回；其扭矩保持关闭，与之前相同。</translation>
    </message>
    <message>
        <source>SYNC READ at %1: no answer in time from ID %2</source>
        <translation>在 %1 下执行 SYNC READ：ID %2 未及时应答</translation>
    </message>
    <message>
        <source>%1 answers again; it is back in the cycle.</source>
        <translation>%1 重新应答；已重新加入轮询周期。</translation>
    </message>
    <message>
        <source>%1 stopped answering; it is left out of the cycle and asked alone every %2 ms until it answers.</source>
        <translation>%1 已停止应答；它已被移出轮询周期，将每隔 %2 ms 单独询问一次，直到它应答。</translation>
    </message>
    <message>
        <source>%1 Torque stays off.</source>
        <translation>%1 扭矩保持关闭。</translation>
    </message>
    <message>
        <source>The operating mode could not be read.</source>
        <translation>无法读取运行模式。</translation>
    </message>
    <message>
        <source>Servo %1 is not in position mode (mode %2): its goal is not a position, so it cannot be held there.</source>
        <translation>舵机 %1 不在位置模式（模式 %2）：其目标不是位置，因此无法保持在该处。</translation>
    </message>
    <message>
        <source>The present position could not be read.</source>
        <translation>无法读取当前位置。</translation>
    </message>
    <message>
        <source>The goal cannot be set to the present position (%1).</source>
        <translation>无法将目标设为当前位置（%1）。</translation>
    </message>
    <message>
        <source>Setting the goal to the present position</source>
        <translation>正在将目标设为当前位置</translation>
    </message>
    <message>
        <source>Sent; its answers, if any, are in the packet log.</source>
        <translation>已发送；如有应答，见数据包日志。</translation>
    </message>
    <message>
        <source>Servo %1 answered.</source>
        <translation>舵机 %1 已应答。</translation>
    </message>
    <message>
        <source>Sent; servo %1 did not answer: %2</source>
        <translation>已发送；舵机 %1 无应答：%2</translation>
    </message>
    <message>
        <source>%1 stopped answering: check the power and the cable, then look again.</source>
        <translation>%1 已停止应答：请检查电源和电缆，然后重新查找。</translation>
    </message>
    <message>
        <source>There is nothing to replay.</source>
        <translation>没有可回放的内容。</translation>
    </message>
    <message>
        <source>%1 is of a model ServoBench does not move (%2): nothing was replayed.</source>
        <translation>%1 的型号是 ServoBench 不会移动的型号（%2）：未回放任何内容。</translation>
    </message>
    <message>
        <source>A servo does not answer: %1 Nothing was replayed.</source>
        <translation>有舵机无应答：%1 未回放任何内容。</translation>
    </message>
    <message>
        <source>Frame %1 (at %2 s) asks %3 for %4, outside the positions it accepts (%5 to %6): nothing was moved.</source>
        <translation>第 %1 帧（%2 秒处）要求 %3 移动到 %4，超出其可接受的位置（%5 到 %6）：未移动任何舵机。</translation>
    </message>
    <message>
        <source>The replay was stopped; nothing was moved.</source>
        <translation>回放已停止；未移动任何舵机。</translation>
    </message>
    <message>
        <source>The servos could not be held where they stand: %1</source>
        <translation>无法使舵机保持在当前位置：%1</translation>
    </message>
    <message numerus="yes">
        <source>Played %n frame(s)</source>
        <translation>
            <numerusform>已回放 %n 帧</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n time(s)</source>
        <translation>
            <numerusform>共 %n 遍</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 %2; the arm holds the last frame.</source>
        <translation>%1，%2；机械臂保持最后一帧的姿态。</translation>
    </message>
    <message>
        <source>%1 %2, but torque could not be switched off: %3</source>
        <translation>%1，%2，但无法关闭扭矩：%3</translation>
    </message>
    <message>
        <source>%1 %2; torque is off.</source>
        <translation>%1，%2；扭矩已关闭。</translation>
    </message>
    <message>
        <source>%1 cannot take goal %2 with the others in one SYNC WRITE.</source>
        <translation>%1 无法与其他舵机在同一条 SYNC WRITE 中接收目标 %2。</translation>
    </message>
    <message>
        <source>The replay stopped: %1</source>
        <translation>回放已中止：%1</translation>
    </message>
    <message>
        <source>All torque off: the replay was stopped.</source>
        <translation>全部关闭扭矩：回放已停止。</translation>
    </message>
    <message>
        <source>Loop %1 of %2: easing to the first frame</source>
        <translation>第 %1/%2 遍：正在平缓移动到第一帧</translation>
    </message>
    <message>
        <source>Loop %1 of %2: playing %3 frames over %4 s</source>
        <translation>第 %1/%2 遍：正在 %4 秒内播放 %3 帧</translation>
    </message>
    <message>
        <source>Loop %1 of %2: frame %3 of %4</source>
        <translation>第 %1/%2 遍：第 %3/%4 帧</translation>
    </message>
    <message>
        <source>while easing to the first frame (loop %1 of %2)</source>
        <translation>在平缓移动到第一帧期间（第 %1/%2 遍）</translation>
    </message>
    <message>
        <source>at %1 s of %2 s (loop %3 of %4)</source>
        <translation>在第 %1 秒（共 %2 秒，第 %3/%4 遍）</translation>
    </message>
    <message>
        <source>The replay was stopped %1; the arm holds where it stood.</source>
        <translation>回放已%1停止；机械臂保持在停止时的位置。</translation>
    </message>
    <message>
        <source>The replay was stopped %1, but the arm could not be held: %2</source>
        <translation>回放已%1停止，但无法使机械臂保持位置：%2</translation>
    </message>
    <message numerus="yes">
        <source>The settings of %n servo(s) read.</source>
        <translation>
            <numerusform>已读取 %n 个舵机的设置。</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%1 of %n setting(s) fixed and verified.</source>
        <translation>
            <numerusform>%n 项设置中已有 %1 项修复并验证。</numerusform>
        </translation>
    </message>
    <message>
        <source>Shared bus alert at ID %1: %2</source>
        <translation>共享总线警报，ID %1：%2</translation>
    </message>
    <message>
        <source>Shared bus: %1</source>
        <translation>共享总线：%1</translation>
    </message>
    <message>
        <source>Not while the bus is shared with another program: this would change the port&apos;s rate under it. Stop sharing first.</source>
        <translation>总线与另一个程序共享期间不能执行此操作：这会在该程序不知情的情况下更改端口的波特率。请先停止共享。</translation>
    </message>
    <message numerus="yes">
        <source> (%n position(s) a little past a joint&apos;s limit played at the limit)</source>
        <translation>
            <numerusform>（%n 个略超出关节限位的位置按限位值回放）</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>FeetechTelemetry</name>
    <message>
        <source>Position</source>
        <translation>位置</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>速度</translation>
    </message>
    <message>
        <source>Load</source>
        <translation>负载</translation>
    </message>
    <message>
        <source>Voltage</source>
        <translation>电压</translation>
    </message>
    <message>
        <source>Temperature</source>
        <translation>温度</translation>
    </message>
    <message>
        <source>Current</source>
        <translation>电流</translation>
    </message>
    <message>
        <source>none</source>
        <translation>无</translation>
    </message>
    <message>
        <source>Line %1: %2</source>
        <translation>第 %1 行：%2</translation>
    </message>
    <message>
        <source>not a ServoBench telemetry recording (unexpected header)</source>
        <translation>不是 ServoBench 遥测记录（文件头不符）</translation>
    </message>
    <message>
        <source>%1 cells instead of %2</source>
        <translation>有 %1 个单元格，应为 %2 个</translation>
    </message>
    <message>
        <source>the time is not a number</source>
        <translation>时间不是数字</translation>
    </message>
    <message>
        <source>the ID is not a servo ID</source>
        <translation>ID 不是有效的舵机 ID</translation>
    </message>
    <message>
        <source>%1 is not a number</source>
        <translation>%1 不是数字</translation>
    </message>
    <message>
        <source>the status is not a byte</source>
        <translation>状态不是一个字节</translation>
    </message>
    <message>
        <source>moving is neither 0 nor 1</source>
        <translation>moving 既不是 0 也不是 1</translation>
    </message>
</context>
<context>
    <name>FeetechWorkspace</name>
    <message>
        <source>Scan…</source>
        <translation>扫描…</translation>
    </message>
    <message>
        <source>Look for servos on the bus: choose IDs and baud rates</source>
        <translation>在总线上查找舵机：选择 ID 和波特率</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <source>Stop the scan</source>
        <translation>停止扫描</translation>
    </message>
    <message>
        <source>%v of %m IDs</source>
        <translation>%v / %m 个 ID</translation>
    </message>
    <message>
        <source>Connect, then scan to find the servos.</source>
        <translation>请先连接，再扫描以查找舵机。</translation>
    </message>
    <message>
        <source>All torque off  (Esc)</source>
        <translation>全部关闭扭矩  (Esc)</translation>
    </message>
    <message>
        <source>Switch the torque of every servo on the bus off at once, ahead of anything else (also: Esc, from any page)</source>
        <translation>优先于其他一切操作，立即关闭总线上所有舵机的扭矩（也可在任意页面按 Esc）</translation>
    </message>
    <message>
        <source>Change ID…</source>
        <translation>更改 ID…</translation>
    </message>
    <message>
        <source>Give the servo another ID; an ID in use is refused</source>
        <translation>为舵机分配其他 ID；已被使用的 ID 会被拒绝</translation>
    </message>
    <message>
        <source>Change baud rate…</source>
        <translation>更改波特率…</translation>
    </message>
    <message>
        <source>Move the servo to another baud rate and follow it there</source>
        <translation>将舵机改为其他波特率，并随之切换到该波特率</translation>
    </message>
    <message>
        <source>Calibrate middle…</source>
        <translation>中位校准…</translation>
    </message>
    <message>
        <source>Make the horn&apos;s present position the middle (2048)</source>
        <translation>将舵盘的当前位置设为中位（2048）</translation>
    </message>
    <message>
        <source>Factory reset…</source>
        <translation>恢复出厂设置…</translation>
    </message>
    <message>
        <source>Restore factory values (the ID is kept), after saving a backup profile</source>
        <translation>先保存备份配置文件，再恢复出厂值（保留 ID）</translation>
    </message>
    <message>
        <source>Reboot</source>
        <translation>重启</translation>
    </message>
    <message>
        <source>Torque off, restart the servo and wait until it answers again</source>
        <translation>关闭扭矩，重启舵机并等待其重新应答</translation>
    </message>
    <message>
        <source>Clear status</source>
        <translation>清除状态</translation>
    </message>
    <message>
        <source>Reset the servo&apos;s error status (instruction 0x0A)</source>
        <translation>复位舵机的错误状态（指令 0x0A）</translation>
    </message>
    <message>
        <source>The settings changed most, in real units. &lt;b&gt;EEPROM&lt;/b&gt; values are written with the lock opened and closed again and survive power-off. Changing the ID or the baud rate asks first, then follows the servo.</source>
        <translation>最常更改的设置，以实际单位显示。&lt;b&gt;EEPROM&lt;/b&gt; 值在写入时会先解锁再重新上锁，断电后仍保留。更改 ID 或波特率前会先询问，之后随舵机切换。</translation>
    </message>
    <message>
        <source>Settings</source>
        <translation>设置</translation>
    </message>
    <message>
        <source>Memory table</source>
        <translation>内存表</translation>
    </message>
    <message>
        <source>Control</source>
        <translation>控制</translation>
    </message>
    <message>
        <source>Monitor</source>
        <translation>监视</translation>
    </message>
    <message>
        <source>Joints</source>
        <translation>关节</translation>
    </message>
    <message>
        <source>Health</source>
        <translation>健康</translation>
    </message>
    <message>
        <source>Restarting the servo…</source>
        <translation>正在重启舵机…</translation>
    </message>
    <message>
        <source>Clearing the status…</source>
        <translation>正在清除状态…</translation>
    </message>
    <message>
        <source>Working…</source>
        <translation>正在处理…</translation>
    </message>
    <message>
        <source>Scanning at %1…</source>
        <translation>正在以 %1 扫描…</translation>
    </message>
    <message>
        <source>Connect to the bus before scanning.</source>
        <translation>扫描前请先连接总线。</translation>
    </message>
    <message>
        <source>servo %1 (%2)</source>
        <translation>舵机 %1（%2）</translation>
    </message>
    <message>
        <source>Choose a servo in the tree.</source>
        <translation>请在树中选择一个舵机。</translation>
    </message>
    <message>
        <source>No servo yet: connect to the bus and scan.</source>
        <translation>尚无舵机：请连接总线并扫描。</translation>
    </message>
    <message>
        <source>unknown family</source>
        <translation>未知系列</translation>
    </message>
    <message>
        <source>status not read yet</source>
        <translation>尚未读取状态</translation>
    </message>
    <message>
        <source>status OK</source>
        <translation>状态正常</translation>
    </message>
    <message>
        <source>&lt;span style=&apos;color:#b3261e&apos;&gt;status: %1&lt;/span&gt;</source>
        <translation>&lt;span style=&apos;color:#b3261e&apos;&gt;状态：%1&lt;/span&gt;</translation>
    </message>
    <message>
        <source>&lt;b&gt;ID %1 · %2&lt;/b&gt; &amp;nbsp; model %3 · %4 family · firmware %5 · %6 · %7</source>
        <translation>&lt;b&gt;ID %1 · %2&lt;/b&gt; &amp;nbsp; 型号 %3 · %4 系列 · 固件 %5 · %6 · %7</translation>
    </message>
    <message>
        <source>No register table is known for this model, so nothing is guessed: the Memory table shows its raw bytes, read-only.</source>
        <translation>此型号没有已知的寄存器表，因此不做任何猜测：内存表以只读方式显示其原始字节。</translation>
    </message>
    <message>
        <source>SCS servos have no offset register: not available</source>
        <translation>SCS 舵机没有偏移寄存器：不可用</translation>
    </message>
    <message>
        <source>its ID from %1 to %2</source>
        <translation>其 ID（从 %1 改为 %2）</translation>
    </message>
    <message>
        <source>its baud rate from %1 to %2</source>
        <translation>其波特率（从 %1 改为 %2）</translation>
    </message>
    <message>
        <source>Change how the servo is reached?</source>
        <translation>更改舵机的访问方式？</translation>
    </message>
    <message>
        <source>This changes %1.&lt;br&gt;&lt;br&gt;ServoBench writes it to EEPROM with the lock opened and closed again, then finds the servo at its new address and confirms it there. Other programs and robot code must use the new address afterwards.</source>
        <translation>此操作将更改%1。&lt;br&gt;&lt;br&gt;ServoBench 会先解锁再写入 EEPROM，然后重新上锁，再在新地址上找到舵机并在该处确认。之后其他程序和机器人代码必须使用新的地址。</translation>
    </message>
    <message>
        <source> and </source>
        <translation> 和 </translation>
    </message>
    <message>
        <source>Nothing was written: %1</source>
        <translation>未写入任何内容：%1</translation>
    </message>
    <message>
        <source>Change ID</source>
        <translation>更改 ID</translation>
    </message>
    <message>
        <source>New ID for %1 (IDs found on this bus: %2).
An ID in use is refused.</source>
        <translation>%1 的新 ID（此总线上已找到的 ID：%2）。
已被使用的 ID 会被拒绝。</translation>
    </message>
    <message>
        <source>ID %1 is already in use on this bus; nothing was written.</source>
        <translation>ID %1 已在此总线上使用；未写入任何内容。</translation>
    </message>
    <message>
        <source>Change baud rate</source>
        <translation>更改波特率</translation>
    </message>
    <message>
        <source>New baud rate for %1 (now %2). ServoBench follows the servo to the new rate and confirms it there.</source>
        <translation>%1 的新波特率（当前为 %2）。ServoBench 会随舵机切换到新波特率并在该处确认。</translation>
    </message>
    <message>
        <source>Calibrate middle</source>
        <translation>中位校准</translation>
    </message>
    <message>
        <source>The horn&apos;s present position becomes the middle (2048) of %1. Turn the horn to where the middle should be first; the new offset is stored in EEPROM.</source>
        <translation>舵盘的当前位置将成为 %1 的中位（2048）。请先将舵盘转到中位应在的位置；新的偏移保存在 EEPROM 中。</translation>
    </message>
    <message>
        <source>Calibrating the middle…</source>
        <translation>正在校准中位…</translation>
    </message>
    <message>
        <source>Factory reset</source>
        <translation>恢复出厂设置</translation>
    </message>
    <message>
        <source>First save a backup profile of %1; the reset only starts once it is saved.</source>
        <translation>请先保存 %1 的备份配置文件；保存完成后才会开始恢复出厂设置。</translation>
    </message>
    <message>
        <source>Backup saved to %1.&lt;br&gt;&lt;br&gt;Restore the factory values of %2? Everything but the ID returns to what the servo left the factory with, possibly including its baud rate; ServoBench looks for it at every rate afterwards.</source>
        <translation>备份已保存到 %1。&lt;br&gt;&lt;br&gt;要恢复 %2 的出厂值吗？除 ID 外的所有设置都将恢复为舵机出厂时的值，可能包括其波特率；之后 ServoBench 会在每种波特率下查找它。</translation>
    </message>
    <message>
        <source>Restoring factory values…</source>
        <translation>正在恢复出厂值…</translation>
    </message>
    <message>
        <source>Choose a servo first.</source>
        <translation>请先选择一个舵机。</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>已保存 %1</translation>
    </message>
    <message>
        <source>Only a servo of a known model can be saved as a profile.</source>
        <translation>只有已知型号的舵机才能保存为配置文件。</translation>
    </message>
    <message>
        <source>Choose a servo of a known model first.</source>
        <translation>请先选择一个已知型号的舵机。</translation>
    </message>
    <message>
        <source>Wait for the running operation to finish before loading a profile.</source>
        <translation>请等待当前操作完成后再加载配置文件。</translation>
    </message>
    <message>
        <source>No servo chosen. Scan the bus (Scan… at the top left), then choose a servo in the tree: its settings show here.</source>
        <translation>未选择舵机。请扫描总线（左上角的“扫描…”），然后在列表中选择一个舵机：其设置将显示在这里。</translation>
    </message>
    <message>
        <source>Press Scan… to find the servos on the bus.</source>
        <translation>按“扫描…”查找总线上的舵机。</translation>
    </message>
    <message>
        <source>No servo yet: scan the bus.</source>
        <translation>还没有舵机：请扫描总线。</translation>
    </message>
    <message>
        <source>Not connected: the servos listed are those of the last scan. Connect, then scan again.</source>
        <translation>未连接：列出的舵机来自上次扫描。请先连接，再重新扫描。</translation>
    </message>
    <message>
        <source>✓ Verified: %1</source>
        <translation>✓ 已验证：%1</translation>
    </message>
</context>
<context>
    <name>GuardBanner</name>
    <message>
        <source>Recover…</source>
        <translation>恢复…</translation>
    </message>
    <message>
        <source>Walks you through clearing the servo&apos;s overload trip: torque off and on, then a power cycle if needed.</source>
        <translation>引导您清除舵机的过载保护：先关闭再开启扭矩，必要时再断电重启。</translation>
    </message>
    <message>
        <source>Guard…</source>
        <translation>监护…</translation>
    </message>
    <message>
        <source>The overload and thermal guard&apos;s limits, hold time and action for each servo.</source>
        <translation>每个舵机的过载与过热监护的限值、持续时间和动作。</translation>
    </message>
    <message>
        <source>Guard on: an overloaded servo is stopped (held where it stands, or its torque switched off, as set under Guard…); a hot one has its torque switched off.</source>
        <translation>监护已开启：过载的舵机会被停止（保持在当前位置，或关闭其扭矩，取决于“监护…”中的设置）；过热的舵机会被关闭扭矩。</translation>
    </message>
    <message>
        <source>Guard off: nothing stops an overloaded servo but its own protection.</source>
        <translation>监护已关闭：除了舵机自身的保护，没有任何机制会停止过载的舵机。</translation>
    </message>
</context>
<context>
    <name>GuardSettingsDialog</name>
    <message>
        <source>Overload and thermal guard</source>
        <translation>过载与过热监护</translation>
    </message>
    <message>
        <source>While a servo is driven (torque on, a goal, a test, an identify), the guard watches its load and temperature. When the load stays above its limit for the hold time, or the temperature comes within the margin of its maximum, it warns and then holds the servo where it stands (or switches its torque off). It never moves a servo. The defaults come from each servo&apos;s overload torque, protection time and maximum temperature registers.</source>
        <translation>当舵机处于驱动状态（扭矩开启、有目标、正在测试或识别）时，监护会监视其负载和温度。当负载在持续时间内始终高于限值，或温度接近其上限到余量以内时，监护会先发出警告，然后让舵机保持在当前位置（或关闭其扭矩）。监护从不移动舵机。默认值来自每个舵机的过载扭矩、保护时间和最高温度寄存器。</translation>
    </message>
    <message>
        <source>Guard the servos of this bus (recommended)</source>
        <translation>监护此总线上的舵机（推荐）</translation>
    </message>
    <message>
        <source>Servo</source>
        <translation>舵机</translation>
    </message>
    <message>
        <source>Guarded</source>
        <translation>受监护</translation>
    </message>
    <message>
        <source>Load limit</source>
        <translation>负载限值</translation>
    </message>
    <message>
        <source>Hold time</source>
        <translation>持续时间</translation>
    </message>
    <message>
        <source>Max temperature</source>
        <translation>最高温度</translation>
    </message>
    <message>
        <source>Acts within</source>
        <translation>动作余量</translation>
    </message>
    <message>
        <source>Action</source>
        <translation>动作</translation>
    </message>
    <message>
        <source>ID %1 (%2)</source>
        <translation>ID %1（%2）</translation>
    </message>
    <message>
        <source> %</source>
        <translation> %</translation>
    </message>
    <message>
        <source> ms</source>
        <translation> ms</translation>
    </message>
    <message>
        <source> °C</source>
        <translation> °C</translation>
    </message>
    <message>
        <source>Restore defaults</source>
        <translation>恢复默认值</translation>
    </message>
</context>
<context>
    <name>Hand</name>
    <message>
        <source>servo #%1 (ID %2)</source>
        <translation>舵机 #%1（ID %2）</translation>
    </message>
    <message>
        <source>position %1 is out of range: %2 turns from 0 to %3</source>
        <translation>位置 %1 超出范围：%2 的转动范围是 0 到 %3</translation>
    </message>
    <message>
        <source>%1 has its torque on: it holds its position and the hand cannot turn it</source>
        <translation>%1 的扭矩已开启：它保持在当前位置，手无法转动它</translation>
    </message>
    <message>
        <source>a sweep takes more than 0 and at most %1 seconds</source>
        <translation>一次扫动的时间必须大于 0 且不超过 %1 秒</translation>
    </message>
    <message>
        <source>a sweep runs 0 (until released) to %1 times</source>
        <translation>扫动次数为 0（直到松手）到 %1 次</translation>
    </message>
    <message>
        <source>%1 is an SCS servo: it stops at 0 and %2, there is no seam to sweep across</source>
        <translation>%1 是 SCS 舵机：它止于 0 和 %2，没有可以扫过的分界点</translation>
    </message>
    <message>
        <source>the hand lets go: %1</source>
        <translation>手松开了：%1</translation>
    </message>
    <message numerus="yes">
        <source>the hand finished sweeping %1 (%n time(s))</source>
        <translation>
            <numerusform>手已完成对 %1 的扫动（%n 次）</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>HealthPage</name>
    <message>
        <source>Move test</source>
        <translation>运动测试</translation>
    </message>
    <message>
        <source>Checks each servo: firmware, voltage and temperature against its own limits, status bits, load, %1 reads for communication quality, position against its angle limits. It only reads; the move test moves a servo 100 steps and back, once you confirm.</source>
        <translation>检查每个舵机：固件，电压和温度是否在其自身限值内，状态位，负载，用 %1 次读取评估通信质量，位置是否在其角度限制内。该检查只读取；运动测试在您确认后会将舵机移动 100 步再返回。</translation>
    </message>
    <message>
        <source>Check</source>
        <translation>检查</translation>
    </message>
    <message>
        <source>Read every servo found and give each a verdict</source>
        <translation>读取找到的每个舵机，并为每个舵机给出结论</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <source>Stop the check before the next servo</source>
        <translation>在检查下一个舵机之前停止</translation>
    </message>
    <message>
        <source>Move test…</source>
        <translation>运动测试…</translation>
    </message>
    <message>
        <source>Move the selected servo a little and back, and measure how it follows</source>
        <translation>将所选舵机移动一小段再返回，并测量其跟随情况</translation>
    </message>
    <message>
        <source>Save report…</source>
        <translation>保存报告…</translation>
    </message>
    <message>
        <source>Save the verdicts as an HTML page or as JSON</source>
        <translation>将结论保存为 HTML 页面或 JSON</translation>
    </message>
    <message>
        <source>No servos scanned yet: scan the bus, then check their health here.</source>
        <translation>尚未扫描到舵机：请先扫描总线，然后在此检查其健康状况。</translation>
    </message>
    <message>
        <source>ID</source>
        <translation>ID</translation>
    </message>
    <message>
        <source>Model</source>
        <translation>型号</translation>
    </message>
    <message>
        <source>Firmware</source>
        <translation>固件</translation>
    </message>
    <message>
        <source>Verdict</source>
        <translation>结论</translation>
    </message>
    <message>
        <source>Reasons</source>
        <translation>原因</translation>
    </message>
    <message>
        <source>Voltage</source>
        <translation>电压</translation>
    </message>
    <message>
        <source>Temperature</source>
        <translation>温度</translation>
    </message>
    <message>
        <source>Load</source>
        <translation>负载</translation>
    </message>
    <message>
        <source>Communication</source>
        <translation>通信</translation>
    </message>
    <message numerus="yes">
        <source>Checking %n servo(s)…</source>
        <translation>
            <numerusform>正在检查 %n 个舵机…</numerusform>
        </translation>
    </message>
    <message>
        <source>Select the servo to move in the table first.</source>
        <translation>请先在表中选择要移动的舵机。</translation>
    </message>
    <message>
        <source>The move test was not confirmed: nothing moved.</source>
        <translation>运动测试未确认：没有移动任何舵机。</translation>
    </message>
    <message>
        <source>Servo %1 is no longer on the bus: nothing moved.</source>
        <translation>舵机 %1 已不在总线上：没有移动任何舵机。</translation>
    </message>
    <message>
        <source>Moving servo %1…</source>
        <translation>正在移动舵机 %1…</translation>
    </message>
    <message>
        <source>Save the report as .html or .json: %1 is neither.</source>
        <translation>请将报告保存为 .html 或 .json：%1 两者都不是。</translation>
    </message>
    <message>
        <source>Report saved to %1.</source>
        <translation>报告已保存到 %1。</translation>
    </message>
    <message>
        <source>Save health report</source>
        <translation>保存健康报告</translation>
    </message>
    <message>
        <source>HTML page (*.html);;JSON (*.json)</source>
        <translation>HTML 页面 (*.html);;JSON (*.json)</translation>
    </message>
    <message>
        <source>not checked</source>
        <translation>未检查</translation>
    </message>
    <message>
        <source>Settings</source>
        <translation>设置</translation>
    </message>
    <message>
        <source>%1 (ID %2)</source>
        <translation>%1（ID %2）</translation>
    </message>
    <message numerus="yes">
        <source>Of the %1, %n joint(s) did not answer the scan: %2. Check their cables and scan again.</source>
        <translation>
            <numerusform>%1 有 %n 个关节在扫描中未应答：%2。请检查其线缆后重新扫描。</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 (%2) will move %3 steps from where it stands and back, with its torque on meanwhile. Make sure nothing is in the way. Move it?</source>
        <translation>%1（%2）将从当前位置移动 %3 步再返回，期间扭矩开启。请确保没有障碍物。要移动吗？</translation>
    </message>
</context>
<context>
    <name>HealthReport</name>
    <message>
        <source>not read</source>
        <translation>未读取</translation>
    </message>
    <message>
        <source>Servo health report</source>
        <translation>舵机健康报告</translation>
    </message>
    <message>
        <source>Port %1, checked %2</source>
        <translation>端口 %1，检查时间 %2</translation>
    </message>
    <message>
        <source>No servo was checked.</source>
        <translation>未检查任何舵机。</translation>
    </message>
    <message>
        <source>ID</source>
        <translation>ID</translation>
    </message>
    <message>
        <source>Model</source>
        <translation>型号</translation>
    </message>
    <message>
        <source>Firmware</source>
        <translation>固件</translation>
    </message>
    <message>
        <source>Verdict</source>
        <translation>结论</translation>
    </message>
    <message>
        <source>Voltage</source>
        <translation>电压</translation>
    </message>
    <message>
        <source>Temperature</source>
        <translation>温度</translation>
    </message>
    <message>
        <source>Load</source>
        <translation>负载</translation>
    </message>
    <message>
        <source>Status</source>
        <translation>状态</translation>
    </message>
    <message>
        <source>Communication</source>
        <translation>通信</translation>
    </message>
    <message>
        <source>Move test</source>
        <translation>运动测试</translation>
    </message>
    <message>
        <source>Reasons</source>
        <translation>原因</translation>
    </message>
    <message>
        <source>not run</source>
        <translation>未运行</translation>
    </message>
    <message>
        <source>none</source>
        <translation>无</translation>
    </message>
    <message>
        <source>The report could not be saved to %1: %2</source>
        <translation>无法将报告保存到 %1：%2</translation>
    </message>
</context>
<context>
    <name>IdentifyQuestion</name>
    <message>
        <source>Identify a servo</source>
        <translation>识别舵机</translation>
    </message>
    <message>
        <source>Move it</source>
        <translation>移动</translation>
    </message>
    <message>
        <source>Identify moves %1: its torque comes on and it turns %2 steps each way, slowly and with little torque, then goes back where it was, its settings as before.

Keep hands and objects clear of the arm. Move it now?</source>
        <translation>识别将移动%1：开启其扭矩，以小扭矩缓慢地向两侧各转动 %2 步，然后回到原位，设置恢复原样。

请让手和物品远离机械臂。现在移动吗？</translation>
    </message>
</context>
<context>
    <name>InProcessPort</name>
    <message>
        <source>A simulated port needs a name.</source>
        <translation>模拟端口需要一个名称。</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1（%2）</translation>
    </message>
</context>
<context>
    <name>InProcessTransport</name>
    <message>
        <source>%1 is not running: its simulated servos have stopped.</source>
        <translation>%1 未运行：其模拟舵机已停止。</translation>
    </message>
    <message>
        <source>%1 is already open.</source>
        <translation>%1 已经打开。</translation>
    </message>
    <message>
        <source>%1 went away: its simulated servos have stopped.</source>
        <translation>%1 已消失：其模拟舵机已停止。</translation>
    </message>
</context>
<context>
    <name>Joint</name>
    <message>
        <source>shoulder_pan</source>
        <translation>肩部旋转</translation>
    </message>
    <message>
        <source>shoulder_lift</source>
        <translation>肩部抬升</translation>
    </message>
    <message>
        <source>elbow_flex</source>
        <translation>肘部弯曲</translation>
    </message>
    <message>
        <source>wrist_flex</source>
        <translation>腕部弯曲</translation>
    </message>
    <message>
        <source>wrist_roll</source>
        <translation>腕部旋转</translation>
    </message>
    <message>
        <source>gripper</source>
        <translation>夹爪</translation>
    </message>
</context>
<context>
    <name>JointNameDelegate</name>
    <message>
        <source>%1 (%2)</source>
        <translation>%1（%2）</translation>
    </message>
</context>
<context>
    <name>JointNames</name>
    <message>
        <source>ID %1</source>
        <translation>ID %1</translation>
    </message>
    <message>
        <source>%1 (ID %2)</source>
        <translation>%1 (ID %2)</translation>
    </message>
</context>
<context>
    <name>JointTable</name>
    <message>
        <source>Read positions</source>
        <translation>读取位置</translation>
    </message>
    <message>
        <source>Read every servo&apos;s registers now: positions, limits and torque</source>
        <translation>立即读取每个舵机的寄存器：位置、限制和扭矩</translation>
    </message>
    <message>
        <source>Identify</source>
        <translation>识别</translation>
    </message>
    <message>
        <source>Targets from present positions</source>
        <translation>以当前位置作为目标</translation>
    </message>
    <message>
        <source>Copy every servo&apos;s present position into its target</source>
        <translation>将每个舵机的当前位置复制到其目标</translation>
    </message>
    <message>
        <source>Move all</source>
        <translation>全部移动</translation>
    </message>
    <message>
        <source>Send every target at once: one SYNC WRITE per baud rate</source>
        <translation>一次发送所有目标：每个波特率一条 SYNC WRITE</translation>
    </message>
    <message>
        <source>Targets only move servos when you press Move all.</source>
        <translation>只有按下“全部移动”时，目标才会使舵机移动。</translation>
    </message>
    <message>
        <source>ID %1</source>
        <translation>ID %1</translation>
    </message>
    <message>
        <source>ID %1 (%2)</source>
        <translation>ID %1（%2）</translation>
    </message>
    <message>
        <source>Scan the bus to list its servos here.</source>
        <translation>扫描总线以在此列出其舵机。</translation>
    </message>
    <message>
        <source>&lt;b&gt;Live positions:&lt;/b&gt; the monitor is not running, so positions are the last values read (grey) and may be stale. Start the monitor to see live positions, or read them now.</source>
        <translation>&lt;b&gt;实时位置：&lt;/b&gt;监视未运行，因此显示的位置是最后读取的值（灰色），可能已过时。请启动监视以查看实时位置，或立即读取。</translation>
    </message>
    <message>
        <source>&lt;b&gt;Live positions&lt;/b&gt; from the monitor; servos it does not watch show the last value read, in grey.</source>
        <translation>来自监视的&lt;b&gt;实时位置&lt;/b&gt;；未被监视的舵机显示最后读取的值（灰色）。</translation>
    </message>
    <message>
        <source>&lt;b&gt;Live positions&lt;/b&gt; from the monitor.</source>
        <translation>来自监视的&lt;b&gt;实时位置&lt;/b&gt;。</translation>
    </message>
    <message>
        <source>Move all failed: %1</source>
        <translation>全部移动失败：%1</translation>
    </message>
    <message>
        <source>%1: torque was not switched %2: %3</source>
        <translation>%1：未能%2扭矩：%3</translation>
    </message>
    <message>
        <source>on</source>
        <translation>开启</translation>
    </message>
    <message>
        <source>off</source>
        <translation>关闭</translation>
    </message>
    <message>
        <source>That servo is no longer on the bus.</source>
        <translation>该舵机已不在总线上。</translation>
    </message>
    <message>
        <source>its model has no torque enable</source>
        <translation>其型号没有扭矩开关</translation>
    </message>
    <message>
        <source>%1: torque not switched %2: %3</source>
        <translation>%1：未%2扭矩：%3</translation>
    </message>
    <message>
        <source>The bus is not connected: nothing was sent.</source>
        <translation>总线未连接：未发送任何内容。</translation>
    </message>
    <message>
        <source>No servos: scan the bus first.</source>
        <translation>没有舵机：请先扫描总线。</translation>
    </message>
    <message>
        <source>%1 has no target: type one, load a pose or use “Targets from present positions”. Nothing was sent.</source>
        <translation>%1 没有目标：请输入目标、加载姿态或使用“以当前位置作为目标”。未发送任何内容。</translation>
    </message>
    <message>
        <source>%1: the target %2 is outside its range %3 to %4. Nothing was sent.</source>
        <translation>%1：目标 %2 超出其范围 %3 到 %4。未发送任何内容。</translation>
    </message>
    <message>
        <source>%1 is in %2 mode; a goal position only moves a servo in position mode. Nothing was sent.</source>
        <translation>%1 处于“%2”模式；目标位置只能在位置模式下移动舵机。未发送任何内容。</translation>
    </message>
    <message>
        <source>No servo here can be moved: their models are unknown.</source>
        <translation>这里没有可移动的舵机：它们的型号均未知。</translation>
    </message>
    <message>
        <source>Nothing was sent: %1</source>
        <translation>未发送任何内容：%1</translation>
    </message>
    <message>
        <source>Targets sent to IDs %1 in one SYNC WRITE.</source>
        <translation>已通过一条 SYNC WRITE 将目标发送到 ID %1。</translation>
    </message>
    <message>
        <source>, </source>
        <translation>、 </translation>
    </message>
    <message>
        <source>Targets sent to IDs %1 in %2 SYNC WRITEs, one per baud rate.</source>
        <translation>已通过 %2 条 SYNC WRITE（每个波特率一条）将目标发送到 ID %1。</translation>
    </message>
    <message>
        <source>Torque is off on %1: it will not move until torque is on.</source>
        <translation>%1 的扭矩已关闭：在扭矩开启之前它不会移动。</translation>
    </message>
    <message>
        <source>Not moved (unknown model): %1.</source>
        <translation>未移动（型号未知）：%1。</translation>
    </message>
    <message>
        <source>The bus is not connected.</source>
        <translation>总线未连接。</translation>
    </message>
    <message>
        <source>Reading %1 servos…</source>
        <translation>正在读取 %1 个舵机…</translation>
    </message>
    <message>
        <source>%1 cannot be identified now: %2</source>
        <translation>现在无法识别 %1：%2</translation>
    </message>
    <message>
        <source>Identifying %1: watch which horn moves…</source>
        <translation>正在识别 %1：请观察哪个舵盘在动…</translation>
    </message>
    <message>
        <source>Wiggle %1 slowly with little torque, then put it back as it was</source>
        <translation>以很小的扭矩缓慢摆动 %1，然后将其恢复原状</translation>
    </message>
    <message>
        <source>Targets set to the present positions of %1 servos.</source>
        <translation>已将 %1 个舵机的目标设为其当前位置。</translation>
    </message>
    <message>
        <source>Targets set for %1 servos. No position is known yet for %2: read the positions first.</source>
        <translation>已为 %1 个舵机设置目标。%2 的位置尚未知：请先读取位置。</translation>
    </message>
    <message numerus="yes">
        <source>Reading %n servo(s)…</source>
        <translation>
            <numerusform>正在读取 %n 个舵机…</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>JointTablePoses</name>
    <message>
        <source>Load pose…</source>
        <translation>加载姿态…</translation>
    </message>
    <message>
        <source>Fill the targets from a pose file; nothing moves until Move all</source>
        <translation>从姿态文件填入目标；在按下“全部移动”之前不会移动</translation>
    </message>
    <message>
        <source>Save pose…</source>
        <translation>保存姿态…</translation>
    </message>
    <message>
        <source>Save the targets as a pose file</source>
        <translation>将目标保存为姿态文件</translation>
    </message>
    <message>
        <source>No targets to save: set some first.</source>
        <translation>没有可保存的目标：请先设置目标。</translation>
    </message>
    <message>
        <source>Saved the pose “%1” with %2 targets to %3.</source>
        <translation>已将包含 %2 个目标的姿态“%1”保存到 %3。</translation>
    </message>
    <message>
        <source>Pose: %1</source>
        <translation>姿态：%1</translation>
    </message>
    <message>
        <source>Loaded the pose “%1”: %2 targets filled. Nothing moves until you press Move all.</source>
        <translation>已加载姿态“%1”：填入了 %2 个目标。在按下“全部移动”之前不会移动。</translation>
    </message>
    <message>
        <source>ID %1 at %2</source>
        <translation>ID %1，波特率 %2</translation>
    </message>
    <message>
        <source>Not on the bus: %1.</source>
        <translation>不在总线上：%1。</translation>
    </message>
    <message>
        <source>, </source>
        <translation>、 </translation>
    </message>
    <message>
        <source>Not in the pose (targets unchanged): %1.</source>
        <translation>不在姿态中（目标未更改）：%1。</translation>
    </message>
    <message>
        <source>Outside their range (shown in red): %1.</source>
        <translation>超出其范围（以红色显示）：%1。</translation>
    </message>
    <message>
        <source>pose.json</source>
        <translation>pose.json</translation>
    </message>
    <message>
        <source>Save pose</source>
        <translation>保存姿态</translation>
    </message>
    <message>
        <source>ServoBench poses (*.json);;All files (*)</source>
        <translation>ServoBench 姿态 (*.json);;所有文件 (*)</translation>
    </message>
    <message>
        <source>Load pose</source>
        <translation>加载姿态</translation>
    </message>
</context>
<context>
    <name>JointTableView</name>
    <message>
        <source>ID</source>
        <translation>ID</translation>
    </message>
    <message>
        <source>Model</source>
        <translation>型号</translation>
    </message>
    <message>
        <source>Baud rate</source>
        <translation>波特率</translation>
    </message>
    <message>
        <source>Target range</source>
        <translation>目标范围</translation>
    </message>
    <message>
        <source>Torque</source>
        <translation>扭矩</translation>
    </message>
    <message>
        <source>Motion</source>
        <translation>运动</translation>
    </message>
    <message>
        <source>Identify</source>
        <translation>识别</translation>
    </message>
    <message>
        <source>Present position: live while the monitor watches the servo, otherwise the last value read (grey)</source>
        <translation>当前位置：监视该舵机时为实时值，否则为最后读取的值（灰色）</translation>
    </message>
    <message>
        <source>Where Move all sends the servo: double-click or type to change it</source>
        <translation>“全部移动”会将舵机移动到的位置：双击或直接输入以更改</translation>
    </message>
    <message>
        <source>The servo&apos;s angle limits, or the goal register&apos;s range when the limits are unknown or both 0</source>
        <translation>舵机的角度限制；当限制未知或均为 0 时，为目标寄存器的范围</translation>
    </message>
    <message>
        <source>Tick to switch torque on, untick to switch it off</source>
        <translation>勾选以开启扭矩，取消勾选以关闭扭矩</translation>
    </message>
    <message>
        <source>Whether the servo reports that it is moving</source>
        <translation>舵机是否报告其正在运动</translation>
    </message>
    <message>
        <source>Wiggle the servo slowly with little torque, then put it back as it was: see which servo of the arm it is</source>
        <translation>以很小的扭矩缓慢摆动舵机，然后将其恢复原状：看看它是机械臂上的哪个舵机</translation>
    </message>
    <message>
        <source>%1 family, firmware %2</source>
        <translation>%1 系列，固件 %2</translation>
    </message>
    <message>
        <source>Unknown model: it cannot be moved from here</source>
        <translation>型号未知：无法从这里移动它</translation>
    </message>
    <message>
        <source>Switching on…</source>
        <translation>正在开启…</translation>
    </message>
    <message>
        <source>Switching off…</source>
        <translation>正在关闭…</translation>
    </message>
    <message>
        <source>Unknown</source>
        <translation>未知</translation>
    </message>
    <message>
        <source>Off</source>
        <translation>关</translation>
    </message>
    <message>
        <source>On</source>
        <translation>开</translation>
    </message>
    <message>
        <source>Damping</source>
        <translation>阻尼</translation>
    </message>
    <message>
        <source>Live, from the monitor</source>
        <translation>实时值，来自监视</translation>
    </message>
    <message>
        <source>Last value read: it may be stale</source>
        <translation>最后读取的值：可能已过时</translation>
    </message>
    <message>
        <source>Not read yet</source>
        <translation>尚未读取</translation>
    </message>
    <message>
        <source>Moving</source>
        <translation>移动标志</translation>
    </message>
    <message>
        <source>Still</source>
        <translation>静止</translation>
    </message>
    <message>
        <source>Unknown model: no goal register</source>
        <translation>型号未知：没有目标寄存器</translation>
    </message>
    <message>
        <source>%1 to %2</source>
        <translation>%1 到 %2</translation>
    </message>
    <message>
        <source>From the servo&apos;s angle limits</source>
        <translation>来自舵机的角度限制</translation>
    </message>
    <message>
        <source>The goal register&apos;s range: the angle limits are not read yet or both 0</source>
        <translation>目标寄存器的范围：角度限制尚未读取或均为 0</translation>
    </message>
    <message>
        <source>Outside the range %1 to %2: Move all will refuse it</source>
        <translation>超出范围 %1 到 %2：“全部移动”会拒绝它</translation>
    </message>
    <message>
        <source>No target yet: type one, load a pose or take the present position</source>
        <translation>尚无目标：请输入目标、加载姿态或采用当前位置</translation>
    </message>
    <message>
        <source>Position (%1)</source>
        <translation>位置（%1）</translation>
    </message>
    <message>
        <source>Target (%1)</source>
        <translation>目标（%1）</translation>
    </message>
</context>
<context>
    <name>LanguageMenu</name>
    <message>
        <source>&amp;Language</source>
        <translation>语言(&amp;L)</translation>
    </message>
    <message>
        <source>The system&apos;s language</source>
        <translation>系统语言</translation>
    </message>
    <message>
        <source>Language</source>
        <translation>语言</translation>
    </message>
    <message>
        <source>ServoBench shows the new language after it starts again.</source>
        <translation>ServoBench 重新启动后显示新的语言。</translation>
    </message>
    <message>
        <source>Restart now</source>
        <translation>立即重新启动</translation>
    </message>
    <message>
        <source>Later</source>
        <translation>稍后</translation>
    </message>
</context>
<context>
    <name>LeRobotCalibration</name>
    <message>
        <source>not a LeRobot calibration (the document is not a JSON object of motors by joint name)</source>
        <translation>不是 LeRobot 校准文件（文档不是以关节名称为键的电机 JSON 对象）</translation>
    </message>
    <message>
        <source>the calibration names no motor</source>
        <translation>校准文件中没有任何电机</translation>
    </message>
    <message>
        <source>a motor has an empty name</source>
        <translation>有电机的名称为空</translation>
    </message>
    <message>
        <source>motor &quot;%1&quot;: not a motor name (ASCII letters, digits and _, a letter first)</source>
        <translation>电机“%1”：不是有效的电机名称（ASCII 字母、数字和 _，以字母开头）</translation>
    </message>
    <message>
        <source>motor &quot;%1&quot;: not an object of id, drive_mode, homing_offset, range_min and range_max</source>
        <translation>电机“%1”：不是包含 id、drive_mode、homing_offset、range_min 和 range_max 的对象</translation>
    </message>
    <message>
        <source>motor &quot;%1&quot;: unknown field &quot;%2&quot;</source>
        <translation>电机“%1”：未知字段“%2”</translation>
    </message>
    <message>
        <source>motor &quot;%1&quot;: &quot;%2&quot; is missing</source>
        <translation>电机“%1”：缺少“%2”</translation>
    </message>
    <message>
        <source>motor &quot;%1&quot;: &quot;%2&quot; must be a whole number</source>
        <translation>电机“%1”：“%2”必须是整数</translation>
    </message>
    <message>
        <source>motor &quot;%1&quot;: &quot;%2&quot; is %3, outside %4 to %5</source>
        <translation>电机“%1”：“%2”为 %3，超出 %4 到 %5</translation>
    </message>
    <message>
        <source>motor &quot;%1&quot;: &quot;%2&quot; (%3) must be below &quot;%4&quot; (%5)</source>
        <translation>电机“%1”：“%2”（%3）必须小于“%4”（%5）</translation>
    </message>
    <message>
        <source>motor &quot;%1&quot;: ID %2 is used by another motor too</source>
        <translation>电机“%1”：ID %2 也被另一个电机使用</translation>
    </message>
    <message>
        <source>the file is too large for a calibration</source>
        <translation>文件过大，不可能是校准文件</translation>
    </message>
    <message>
        <source>no joint has ID %1 (%2): it is not this arm&apos;s file</source>
        <translation>没有关节的 ID 为 %1（%2）：这不是此机械臂的文件</translation>
    </message>
</context>
<context>
    <name>LinkSession</name>
    <message>
        <source>Disconnected.</source>
        <translation>已断开。</translation>
    </message>
    <message>
        <source>%1 Reconnecting when it comes back.</source>
        <translation>%1 待其恢复后将重新连接。</translation>
    </message>
</context>
<context>
    <name>LoadCalibrationDialog</name>
    <message>
        <source>Load calibration</source>
        <translation>加载校准</translation>
    </message>
    <message>
        <source>What %1 would change on each joint (now → file). Nothing is written until you press Write.</source>
        <translation>%1 将对每个关节做出的更改（当前 → 文件）。在按下“写入”之前不会写入任何内容。</translation>
    </message>
    <message>
        <source>Joint</source>
        <translation>关节</translation>
    </message>
    <message>
        <source>Offset</source>
        <translation>偏移</translation>
    </message>
    <message>
        <source>Min limit</source>
        <translation>最小限制</translation>
    </message>
    <message>
        <source>Max limit</source>
        <translation>最大限制</translation>
    </message>
    <message>
        <source>Status</source>
        <translation>状态</translation>
    </message>
    <message>
        <source>Reading the servos…</source>
        <translation>正在读取舵机…</translation>
    </message>
    <message>
        <source>&amp;Write</source>
        <translation>写入(&amp;W)</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>no answer</source>
        <translation>无应答</translation>
    </message>
    <message>
        <source>Written and verified</source>
        <translation>已写入并验证</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>关闭</translation>
    </message>
    <message>
        <source>Every change was written and verified.</source>
        <translation>所有更改均已写入并验证。</translation>
    </message>
    <message>
        <source>Not every change was written: see the status column.</source>
        <translation>并非所有更改都已写入：请查看状态列。</translation>
    </message>
    <message>
        <source>Servo %1 is not on the bus: nothing written</source>
        <translation>舵机 %1 不在总线上：未写入任何内容</translation>
    </message>
    <message>
        <source>Servo %1 could not be read (%2): nothing written</source>
        <translation>无法读取舵机 %1（%2）：未写入任何内容</translation>
    </message>
    <message>
        <source>%1 → %2</source>
        <translation>%1 → %2</translation>
    </message>
    <message>
        <source>Unchanged</source>
        <translation>未更改</translation>
    </message>
    <message>
        <source>Torque is on: the new offset would move the horn. Switch torque off (support the arm) and load again.</source>
        <translation>扭矩已开启：新的偏移会使舵盘移动。请关闭扭矩（并扶住机械臂）后重新加载。</translation>
    </message>
    <message>
        <source>To write</source>
        <translation>待写入</translation>
    </message>
    <message>
        <source>Not every servo could be read: those joints are not written.</source>
        <translation>并非所有舵机都能读取：这些关节不会被写入。</translation>
    </message>
    <message>
        <source>Nothing to write.</source>
        <translation>没有要写入的内容。</translation>
    </message>
    <message numerus="yes">
        <source>Write %n joint(s) to EEPROM (locked writes, verified)?</source>
        <translation>
            <numerusform>将 %n 个关节写入 EEPROM（解锁写入并验证）？</numerusform>
        </translation>
    </message>
    <message>
        <source>Writing to EEPROM and verifying…</source>
        <translation>正在写入 EEPROM 并验证…</translation>
    </message>
</context>
<context>
    <name>MainWindow</name>
    <message>
        <source>ServoBench</source>
        <translation>ServoBench</translation>
    </message>
    <message>
        <source>Not connected</source>
        <translation>未连接</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>文件(&amp;F)</translation>
    </message>
    <message>
        <source>&amp;Load profile…</source>
        <translation>加载配置文件(&amp;L)…</translation>
    </message>
    <message>
        <source>&amp;Save profile…</source>
        <translation>保存配置文件(&amp;S)…</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>退出(&amp;Q)</translation>
    </message>
    <message>
        <source>&amp;Link</source>
        <translation>连接(&amp;L)</translation>
    </message>
    <message>
        <source>&amp;Poll the servo</source>
        <translation>轮询舵机(&amp;P)</translation>
    </message>
    <message>
        <source>Keep reading the eight queries so the values stay live</source>
        <translation>持续读取八个查询，使数值保持实时</translation>
    </message>
    <message>
        <source>&amp;Fast polling (queries back to back)</source>
        <translation>快速轮询（查询连续发送）(&amp;F)</translation>
    </message>
    <message>
        <source>&amp;Scan the Feetech bus…</source>
        <translation>扫描 Feetech 总线(&amp;S)…</translation>
    </message>
    <message>
        <source>Disconnect from the PTK servo before scanning a Feetech bus.</source>
        <translation>扫描 Feetech 总线前，请先断开与 PTK 舵机的连接。</translation>
    </message>
    <message>
        <source>All &amp;torque off</source>
        <translation>全部关闭扭矩(&amp;T)</translation>
    </message>
    <message>
        <source>Switch the torque of every servo on the Feetech bus off</source>
        <translation>关闭 Feetech 总线上所有舵机的扭矩</translation>
    </message>
    <message>
        <source>Torque off: sent to every servo…</source>
        <translation>关闭扭矩：正在发送到每个舵机…</translation>
    </message>
    <message>
        <source>&amp;Robot</source>
        <translation>机器人(&amp;R)</translation>
    </message>
    <message>
        <source>Set up &amp;motors…</source>
        <translation>设置舵机(&amp;M)…</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>视图(&amp;V)</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>帮助(&amp;H)</translation>
    </message>
    <message>
        <source>&amp;About ServoBench</source>
        <translation>关于 ServoBench(&amp;A)</translation>
    </message>
    <message>
        <source>About &amp;Qt</source>
        <translation>关于 Qt(&amp;Q)</translation>
    </message>
    <message>
        <source>About ServoBench</source>
        <translation>关于 ServoBench</translation>
    </message>
    <message>
        <source>&lt;p&gt;&lt;b&gt;ServoBench %1&lt;/b&gt;&lt;/p&gt;&lt;p&gt;Programs and monitors PTK RC servos and Feetech serial-bus servos on Linux, Windows and macOS.&lt;/p&gt;&lt;p&gt;Built with Qt %2, running on Qt %3.&lt;/p&gt;&lt;p&gt;Free software under the GNU General Public License, version 3 or (at your option) any later version; it comes with no warranty.&lt;/p&gt;</source>
        <translation>&lt;p&gt;&lt;b&gt;ServoBench %1&lt;/b&gt;&lt;/p&gt;&lt;p&gt;在 Linux、Windows 和 macOS 上编程和监视 PTK RC 舵机与 Feetech 串行总线舵机。&lt;/p&gt;&lt;p&gt;使用 Qt %2 构建，运行于 Qt %3。&lt;/p&gt;&lt;p&gt;本软件是自由软件，依据 GNU 通用公共许可证第 3 版或（由您选择）任何更高版本发布；不提供任何担保。&lt;/p&gt;</translation>
    </message>
    <message>
        <source>Connecting to %1…</source>
        <translation>正在连接到 %1…</translation>
    </message>
    <message>
        <source>Open: %1</source>
        <translation>已打开：%1</translation>
    </message>
    <message>
        <source>Connected: %1 at %2 baud</source>
        <translation>已连接：%1，波特率 %2</translation>
    </message>
    <message>
        <source>No reply on %1</source>
        <translation>%1 上无应答</translation>
    </message>
    <message>
        <source>Disconnected: %1 went away, waiting for it to return</source>
        <translation>已断开：%1 已消失，正在等待其恢复</translation>
    </message>
    <message>
        <source>sent %1 · ok %2 · checksum errors %3 · timeouts %4 · retries %5 · discarded %6 B</source>
        <translation>已发送 %1 · 成功 %2 · 校验和错误 %3 · 超时 %4 · 重试 %5 · 丢弃 %6 B</translation>
    </message>
    <message>
        <source>%1 queries/s</source>
        <translation>%1 次查询/秒</translation>
    </message>
    <message>
        <source>Unapplied changes</source>
        <translation>未应用的更改</translation>
    </message>
    <message>
        <source>Some changes have not been written to the servos. Quit anyway?</source>
        <translation>有些更改尚未写入舵机。仍要退出吗？</translation>
    </message>
    <message>
        <source>Looking for servos on %1…</source>
        <translation>正在 %1 上查找舵机…</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <source>Auto-detection</source>
        <translation>自动检测</translation>
    </message>
    <message>
        <source>&amp;Reset layout</source>
        <translation>重置布局(&amp;R)</translation>
    </message>
    <message>
        <source>&amp;Keyboard shortcuts</source>
        <translation>键盘快捷键(&amp;K)</translation>
    </message>
    <message>
        <source>&amp;Recent profiles</source>
        <translation>最近的配置文件(&amp;R)</translation>
    </message>
    <message>
        <source>No profile opened or saved yet</source>
        <translation>尚未打开或保存过配置文件</translation>
    </message>
    <message>
        <source>Pac&amp;ket window…</source>
        <translation>数据包窗口(&amp;K)…</translation>
    </message>
    <message>
        <source>Wait until the port being probed answers, or Disconnect.</source>
        <translation>请等待正在探测的端口应答，或断开连接。</translation>
    </message>
    <message>
        <source>&lt;p&gt;Home: &lt;a href=&quot;%1&quot;&gt;%1&lt;/a&gt;&lt;/p&gt;</source>
        <translation>&lt;p&gt;项目主页：&lt;a href=&quot;%1&quot;&gt;%1&lt;/a&gt;&lt;/p&gt;</translation>
    </message>
    <message>
        <source>Record and &amp;replay…</source>
        <translation>记录与回放(&amp;R)…</translation>
    </message>
    <message>
        <source>Record joints moved by hand and play the motion back</source>
        <translation>记录手动移动的关节，并回放该动作</translation>
    </message>
    <message>
        <source>Shared bus, servo %1: %2</source>
        <translation>共享总线，舵机 %1：%2</translation>
    </message>
    <message>
        <source>Sharing the bus: the other program opens %1.</source>
        <translation>正在共享总线：另一个程序打开 %1。</translation>
    </message>
    <message>
        <source>The bus is not shared.</source>
        <translation>总线未在共享。</translation>
    </message>
    <message>
        <source>Share this &amp;bus…</source>
        <translation>共享此总线(&amp;B)…</translation>
    </message>
    <message>
        <source>Give another program a port of its own on this Feetech bus and watch its traffic</source>
        <translation>为另一个程序在此 Feetech 总线上提供专用端口，并监视其通信</translation>
    </message>
    <message>
        <source>Re&amp;place a motor…</source>
        <translation>更换舵机(&amp;P)…</translation>
    </message>
    <message>
        <source>Set up a new servo as one joint of an arm and calibrate that joint alone into the arm&apos;s LeRobot file</source>
        <translation>将新舵机设置为机械臂的某个关节，只校准该关节，并将结果写入机械臂的 LeRobot 文件</translation>
    </message>
    <message>
        <source>&amp;Teleoperate…</source>
        <translation>遥操作(&amp;T)…</translation>
    </message>
    <message>
        <source>Move this arm with a leader arm on another port</source>
        <translation>用另一个端口上的主臂操控此机械臂</translation>
    </message>
    <message>
        <source>Close the calibration wizard before setting up motors: a set-up changes the servos&apos; IDs and settings.</source>
        <translation>设置舵机前请先关闭校准向导：设置过程会更改舵机的 ID 和参数。</translation>
    </message>
    <message>
        <source>Ask skipped &amp;questions again</source>
        <translation>重新询问已跳过的问题(&amp;Q)</translation>
    </message>
    <message>
        <source>ServoBench asks again before anything moves.</source>
        <translation>ServoBench 会在任何部件移动前再次询问。</translation>
    </message>
    <message>
        <source>The questions you ticked &quot;Don&apos;t ask again&quot; on are asked again</source>
        <translation>勾选了“不再询问”的问题将重新询问</translation>
    </message>
    <message>
        <source> · stream missed %1</source>
        <translation> · 数据流丢失 %1</translation>
    </message>
    <message>
        <source>the simulated leader arm is not running</source>
        <translation>模拟主臂未在运行</translation>
    </message>
    <message>
        <source>the simulated leader arm has no joints</source>
        <translation>模拟主臂没有关节</translation>
    </message>
</context>
<context>
    <name>MemoryTablePage</name>
    <message>
        <source>Filter registers</source>
        <translation>筛选寄存器</translation>
    </message>
    <message>
        <source>Refresh RAM live</source>
        <translation>实时刷新 RAM</translation>
    </message>
    <message>
        <source>Read the RAM registers (present position, load, voltage…) several times a second while this table is shown</source>
        <translation>显示此表时，每秒多次读取 RAM 寄存器（当前位置、负载、电压…）</translation>
    </message>
    <message>
        <source>No servo chosen: scan the bus, then choose a servo in the tree; every register of its memory table shows here.</source>
        <translation>未选择舵机：请扫描总线，然后在列表中选择一个舵机；其内存表的每个寄存器将显示在这里。</translation>
    </message>
    <message>
        <source>Read</source>
        <translation>读取</translation>
    </message>
    <message>
        <source>Read every register of the servo</source>
        <translation>读取舵机的所有寄存器</translation>
    </message>
    <message>
        <source>Revert</source>
        <translation>还原</translation>
    </message>
    <message>
        <source>Drop every edit</source>
        <translation>放弃所有编辑</translation>
    </message>
    <message>
        <source>Apply</source>
        <translation>应用</translation>
    </message>
    <message>
        <source>Write the edited registers, then read them back</source>
        <translation>写入已编辑的寄存器，然后回读</translation>
    </message>
</context>
<context>
    <name>MonitorPage</name>
    <message>
        <source>There is no bus to monitor.</source>
        <translation>没有可监视的总线。</translation>
    </message>
    <message>
        <source>Tick at least one servo to monitor.</source>
        <translation>请至少勾选一个要监视的舵机。</translation>
    </message>
    <message>
        <source>Monitoring did not start: %1</source>
        <translation>监视未能启动：%1</translation>
    </message>
    <message>
        <source>Plot saved to %1.</source>
        <translation>曲线图已保存到 %1。</translation>
    </message>
    <message>
        <source>Recording stopped: the bus was disconnected.</source>
        <translation>记录已停止：总线已断开。</translation>
    </message>
    <message>
        <source>Export plot</source>
        <translation>导出曲线图</translation>
    </message>
    <message>
        <source>PNG images (*.png)</source>
        <translation>PNG 图像 (*.png)</translation>
    </message>
    <message>
        <source>Monitoring stopped: no servo is ticked.</source>
        <translation>监视已停止：没有勾选任何舵机。</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>停止</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>开始</translation>
    </message>
    <message>
        <source>Resume</source>
        <translation>继续</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>暂停</translation>
    </message>
    <message>
        <source>Streaming · %1 cycles/s · %2 samples/s · %3 missed · %4 late</source>
        <translation>数据流 · %1 周期/秒 · %2 采样/秒 · 丢失 %3 · 迟到 %4</translation>
    </message>
    <message>
        <source>Stopped</source>
        <translation>已停止</translation>
    </message>
    <message>
        <source> · plot paused (samples are still received)</source>
        <translation> · 曲线图已暂停（仍在接收采样）</translation>
    </message>
    <message>
        <source>Servos</source>
        <translation>舵机</translation>
    </message>
    <message>
        <source>Plot</source>
        <translation>绘图</translation>
    </message>
    <message>
        <source>Plot the %1 in %2</source>
        <translation>以 %2 为单位绘制%1曲线</translation>
    </message>
    <message>
        <source>Stream</source>
        <translation>数据流</translation>
    </message>
    <message>
        <source>Samples per second for each servo</source>
        <translation>每个舵机每秒的采样数</translation>
    </message>
    <message>
        <source>%1 Hz</source>
        <translation>%1 Hz</translation>
    </message>
    <message>
        <source>As fast as the bus allows</source>
        <translation>总线允许的最快速度</translation>
    </message>
    <message>
        <source>Rate:</source>
        <translation>速率：</translation>
    </message>
    <message>
        <source>Start or stop streaming the ticked servos&apos; feedback</source>
        <translation>开始或停止采集所勾选舵机的反馈数据流</translation>
    </message>
    <message>
        <source>View</source>
        <translation>视图</translation>
    </message>
    <message>
        <source>How many seconds of history the plot shows</source>
        <translation>曲线图显示多少秒的历史</translation>
    </message>
    <message>
        <source>%1 s</source>
        <translation>%1 秒</translation>
    </message>
    <message>
        <source>Window:</source>
        <translation>时间窗口：</translation>
    </message>
    <message>
        <source>Freeze the plot; samples are still received and recorded</source>
        <translation>冻结曲线图；仍会接收并记录采样</translation>
    </message>
    <message>
        <source>Reset zoom</source>
        <translation>重置缩放</translation>
    </message>
    <message>
        <source>Back to the live view over the whole window</source>
        <translation>返回覆盖整个时间窗口的实时视图</translation>
    </message>
    <message>
        <source>Export PNG…</source>
        <translation>导出 PNG…</translation>
    </message>
    <message>
        <source>Save the charts as they are shown as one PNG image</source>
        <translation>将当前显示的图表保存为一张 PNG 图像</translation>
    </message>
    <message>
        <source>Shared bus · showing the other program&apos;s reads, none of ServoBench&apos;s own</source>
        <translation>共享总线 · 显示另一个程序的读取，不含 ServoBench 自身的读取</translation>
    </message>
    <message>
        <source>The scan found no servo: monitoring stays stopped.</source>
        <translation>扫描未找到舵机：监视保持停止。</translation>
    </message>
    <message>
        <source>Monitoring again, after the scan.</source>
        <translation>扫描结束，已恢复监视。</translation>
    </message>
    <message>
        <source>The Monitor could not start again after the scan: %1</source>
        <translation>扫描后监视无法重新开始：%1</translation>
    </message>
    <message>
        <source>Monitoring paused while the bus is scanned; it starts again with the servos found.</source>
        <translation>扫描总线期间监视已暂停；扫描结束后将用找到的舵机重新开始。</translation>
    </message>
</context>
<context>
    <name>MonitorReadouts</name>
    <message>
        <source>Servo</source>
        <translation>舵机</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>Moving</source>
        <translation>运动中</translation>
    </message>
    <message>
        <source>Status</source>
        <translation>舵机状态</translation>
    </message>
    <message>
        <source>Samples/s</source>
        <translation>采样/秒</translation>
    </message>
    <message>
        <source>Missed</source>
        <translation>丢失</translation>
    </message>
    <message>
        <source>State</source>
        <translation>通信状态</translation>
    </message>
    <message>
        <source>The servo&apos;s protection bits that tripped (register 65)</source>
        <translation>舵机已触发的保护位（寄存器 65）</translation>
    </message>
    <message>
        <source>Cycles in which the servo was asked and did not answer</source>
        <translation>询问舵机但其未应答的周期数</translation>
    </message>
    <message>
        <source>—</source>
        <translation>—</translation>
    </message>
    <message>
        <source>ID %1</source>
        <translation>ID %1</translation>
    </message>
    <message>
        <source>yes</source>
        <translation>是</translation>
    </message>
    <message>
        <source>no</source>
        <translation>否</translation>
    </message>
    <message>
        <source>Not answering</source>
        <translation>无应答</translation>
    </message>
    <message>
        <source>Stopped</source>
        <translation>已停止</translation>
    </message>
    <message>
        <source>Waiting</source>
        <translation>等待中</translation>
    </message>
    <message>
        <source>OK</source>
        <translation>正常</translation>
    </message>
    <message>
        <source>ID %1 at %2</source>
        <translation>ID %1，波特率 %2</translation>
    </message>
    <message>
        <source>none</source>
        <translation>无</translation>
    </message>
</context>
<context>
    <name>MonitorRecording</name>
    <message>
        <source>Recording</source>
        <translation>记录</translation>
    </message>
    <message>
        <source>Record CSV…</source>
        <translation>记录 CSV…</translation>
    </message>
    <message>
        <source>Write every sample of the ticked servos to a CSV file</source>
        <translation>将所勾选舵机的每个采样写入 CSV 文件</translation>
    </message>
    <message numerus="yes">
        <source>%Ln row(s) saved to %1.</source>
        <translation>
            <numerusform>已将 %Ln 行保存到 %1。</numerusform>
        </translation>
    </message>
    <message>
        <source>Record telemetry</source>
        <translation>记录遥测数据</translation>
    </message>
    <message>
        <source>CSV files (*.csv)</source>
        <translation>CSV 文件 (*.csv)</translation>
    </message>
    <message>
        <source>Not recording.</source>
        <translation>未在记录。</translation>
    </message>
    <message numerus="yes">
        <source>Recording to %1: %Ln row(s).</source>
        <translation>
            <numerusform>正在记录到 %1：%Ln 行。</numerusform>
        </translation>
    </message>
    <message>
        <source>Stop recording</source>
        <translation>停止记录</translation>
    </message>
    <message numerus="yes">
        <source>Recording to %1 failed after %Ln row(s): %2</source>
        <translation>
            <numerusform>记录到 %1 时在 %Ln 行后失败：%2</numerusform>
        </translation>
    </message>
    <message>
        <source>Recording failed.</source>
        <translation>记录失败。</translation>
    </message>
</context>
<context>
    <name>MonitorServoList</name>
    <message>
        <source>The servos to stream; ticking or unticking one while streaming restarts the stream</source>
        <translation>要采集数据流的舵机；采集过程中勾选或取消勾选会重新启动数据流</translation>
    </message>
    <message>
        <source>unknown model</source>
        <translation>未知型号</translation>
    </message>
    <message>
        <source>Unknown model: its feedback cannot be decoded</source>
        <translation>未知型号：无法解码其反馈</translation>
    </message>
    <message>
        <source>Scan the bus to find servos.</source>
        <translation>扫描总线以查找舵机。</translation>
    </message>
    <message>
        <source>%1 · %2 · %3</source>
        <translation>%1 · %2 · %3</translation>
    </message>
</context>
<context>
    <name>MotionRecording</name>
    <message>
        <source>servo %1</source>
        <translation>舵机 %1</translation>
    </message>
    <message>
        <source>%1 (servo %2)</source>
        <translation>%1（舵机 %2）</translation>
    </message>
    <message>
        <source>the file is empty: a recording starts with a header line (time_s and one column per joint)</source>
        <translation>文件为空：记录应以表头行开始（time_s 及每个关节一列）</translation>
    </message>
    <message>
        <source>the first column of the header is &quot;%1&quot;, not time_s: this is not a motion recording</source>
        <translation>表头的第一列是 &quot;%1&quot;，而不是 time_s：这不是动作记录</translation>
    </message>
    <message>
        <source>column &quot;%1&quot; names no servo: a joint&apos;s column is id_N or NAME@N, N its servo&apos;s ID (0 to 253)</source>
        <translation>列 &quot;%1&quot; 未对应任何舵机：关节列名应为 id_N 或 NAME@N，N 为其舵机的 ID（0 到 253）</translation>
    </message>
    <message>
        <source>servo %1 has two columns</source>
        <translation>舵机 %1 有两列</translation>
    </message>
    <message>
        <source>the header names no joint after time_s</source>
        <translation>表头在 time_s 之后没有任何关节</translation>
    </message>
    <message>
        <source>line %1</source>
        <translation>第 %1 行</translation>
    </message>
    <message>
        <source>line %1 has %2 cells where the header has %3</source>
        <translation>第 %1 行有 %2 个单元格，而表头有 %3 个</translation>
    </message>
    <message>
        <source>line %1: the time &quot;%2&quot; is not a number of seconds from 0</source>
        <translation>第 %1 行：时间 &quot;%2&quot; 不是从 0 起的秒数</translation>
    </message>
    <message>
        <source>line %1: the time goes back, from %2 s to %3 s</source>
        <translation>第 %1 行：时间倒退，从 %2 秒退到 %3 秒</translation>
    </message>
    <message>
        <source>line %1: &quot;%2&quot; is no position of %3 (a number of steps)</source>
        <translation>第 %1 行：&quot;%2&quot; 不是 %3 的位置（应为步数）</translation>
    </message>
    <message>
        <source>the recording has a header but no frame</source>
        <translation>该记录只有表头，没有任何帧</translation>
    </message>
    <message>
        <source>the file is too large for a motion recording</source>
        <translation>文件太大，不可能是动作记录</translation>
    </message>
    <message>
        <source>nothing was recorded</source>
        <translation>未记录任何内容</translation>
    </message>
</context>
<context>
    <name>MotionTestPanel</name>
    <message>
        <source>Step and sweep tests</source>
        <translation>阶跃与往复测试</translation>
    </message>
    <message>
        <source>Goal speed of the test moves (0: the servo&apos;s maximum).</source>
        <translation>测试运动的目标速度（0：舵机的最大值）。</translation>
    </message>
    <message>
        <source>Acceleration of the test moves (0: the servo&apos;s maximum).</source>
        <translation>测试运动的加速度（0：舵机的最大值）。</translation>
    </message>
    <message>
        <source> s</source>
        <translation> 秒</translation>
    </message>
    <message>
        <source>Step test: how long the response is recorded after the step.</source>
        <translation>阶跃测试：阶跃后记录响应的时长。</translation>
    </message>
    <message>
        <source>Sweep: moves between the two positions, to and back counting as two.</source>
        <translation>往复：在两个位置之间来回运动，去和回算作两个行程。</translation>
    </message>
    <message>
        <source>From</source>
        <translation>起点</translation>
    </message>
    <message>
        <source>To</source>
        <translation>终点</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>速度</translation>
    </message>
    <message>
        <source>Acceleration</source>
        <translation>加速度</translation>
    </message>
    <message>
        <source>Record</source>
        <translation>记录时长</translation>
    </message>
    <message>
        <source>Sweep legs</source>
        <translation>往复行程数</translation>
    </message>
    <message>
        <source>Step test…</source>
        <translation>阶跃测试…</translation>
    </message>
    <message>
        <source>Move to From, then step to To and measure the response.</source>
        <translation>先移动到起点，然后阶跃到终点并测量响应。</translation>
    </message>
    <message>
        <source>Sweep…</source>
        <translation>往复…</translation>
    </message>
    <message>
        <source>Move back and forth between From and To.</source>
        <translation>在起点和终点之间来回运动。</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>停止</translation>
    </message>
    <message>
        <source>Stop the running test; the servo holds where it is.</source>
        <translation>停止正在运行的测试；舵机保持在当前位置。</translation>
    </message>
    <message>
        <source>From 10 % to 90 % of the step.</source>
        <translation>阶跃幅度的 10 % 到 90 %。</translation>
    </message>
    <message>
        <source>How far the peak went beyond the target, as a share of the step.</source>
        <translation>峰值超过目标的量，以阶跃幅度的比例表示。</translation>
    </message>
    <message>
        <source>From the step command until the position stays within the settling band.</source>
        <translation>从发出阶跃命令到位置保持在稳定带内的时间。</translation>
    </message>
    <message>
        <source>Target minus the mean position over the last tenth of the recording.</source>
        <translation>目标减去记录最后十分之一时间内的平均位置。</translation>
    </message>
    <message>
        <source>2 % of the step, at least 2 steps, either side of the target.</source>
        <translation>目标两侧各为阶跃幅度的 2 %，至少 2 步。</translation>
    </message>
    <message>
        <source>Rise time</source>
        <translation>上升时间</translation>
    </message>
    <message>
        <source>Overshoot</source>
        <translation>超调量</translation>
    </message>
    <message>
        <source>Settling time</source>
        <translation>调节时间</translation>
    </message>
    <message>
        <source>Steady-state error</source>
        <translation>稳态误差</translation>
    </message>
    <message>
        <source>Settling band</source>
        <translation>稳定带</translation>
    </message>
    <message>
        <source>Target</source>
        <translation>目标</translation>
    </message>
    <message>
        <source>Time since the step (ms)</source>
        <translation>阶跃后的时间（ms）</translation>
    </message>
    <message>
        <source>The horn of %1 will move to %2, then step to %3 and hold there.</source>
        <translation>%1 的舵盘将移动到 %2，然后阶跃到 %3 并保持在该处。</translation>
    </message>
    <message>
        <source>The horn of %1 will move to %2, then sweep %3 times between %2 and %4.</source>
        <translation>%1 的舵盘将移动到 %2，然后在 %2 和 %4 之间往复 %3 次。</translation>
    </message>
    <message>
        <source>The servo will move</source>
        <translation>舵机将会运动</translation>
    </message>
    <message>
        <source>Keep hands, cables and other parts clear of the horn, and detach any load it could damage or be damaged by. Stop or All torque off halts it.</source>
        <translation>请让手、电缆和其他部件远离舵盘，并拆下任何可能被它损坏或可能损坏它的负载。“停止”或“全部关闭扭矩”可使其停下。</translation>
    </message>
    <message>
        <source>Move the servo</source>
        <translation>移动舵机</translation>
    </message>
    <message>
        <source>Step test done: %1 samples over %2 s.</source>
        <translation>阶跃测试完成：%2 秒内采集 %1 个采样。</translation>
    </message>
    <message>
        <source>Sweep done: %1 of %2 legs reached their goal.</source>
        <translation>往复测试完成：%2 个行程中有 %1 个到达目标。</translation>
    </message>
    <message>
        <source>A leg took %1 ms on average.</source>
        <translation>每个行程平均耗时 %1 ms。</translation>
    </message>
    <message>
        <source>Stopped: %1</source>
        <translation>已停止：%1</translation>
    </message>
    <message>
        <source>No test run yet for this servo.</source>
        <translation>尚未对此舵机运行测试。</translation>
    </message>
    <message>
        <source>%1 ms</source>
        <translation>%1 ms</translation>
    </message>
    <message>
        <source>did not reach 90 % of the step</source>
        <translation>未达到阶跃幅度的 90 %</translation>
    </message>
    <message>
        <source>%1 %</source>
        <translation>%1 %</translation>
    </message>
    <message>
        <source>did not settle within %1 s</source>
        <translation>未在 %1 秒内稳定</translation>
    </message>
    <message>
        <source>%1 steps</source>
        <translation>%1 步</translation>
    </message>
    <message>
        <source>± %1 steps</source>
        <translation>± %1 步</translation>
    </message>
    <message>
        <source>Position (%1)</source>
        <translation>位置（%1）</translation>
    </message>
    <message>
        <source>Sweep ends</source>
        <translation>扫动两端</translation>
    </message>
</context>
<context>
    <name>MotionTestRefusal</name>
    <message>
        <source>A test is already running.</source>
        <translation>已有测试正在运行。</translation>
    </message>
    <message>
        <source>The bus is not connected.</source>
        <translation>总线未连接。</translation>
    </message>
    <message>
        <source>No servo is selected.</source>
        <translation>未选择舵机。</translation>
    </message>
    <message>
        <source>Servo ID %1 is being identified; wait until it is back.</source>
        <translation>正在识别舵机 ID %1；请等待它恢复原位。</translation>
    </message>
    <message>
        <source>This servo&apos;s model is unknown: ServoBench does not move it.</source>
        <translation>此舵机的型号未知：ServoBench 不会驱动它。</translation>
    </message>
    <message>
        <source>This servo has no goal position register.</source>
        <translation>此舵机没有目标位置寄存器。</translation>
    </message>
    <message>
        <source>Servo ID %1 is not in position mode: set its operating mode to position first.</source>
        <translation>舵机 ID %1 不在位置模式：请先将其运行模式设为位置模式。</translation>
    </message>
    <message>
        <source>the servo&apos;s angle limits</source>
        <translation>舵机的角度限制</translation>
    </message>
    <message>
        <source>the goal position range</source>
        <translation>目标位置范围</translation>
    </message>
    <message>
        <source>From (%1) and to (%2) must lie within %3, %4 to %5 steps.</source>
        <translation>起点（%1）和终点（%2）必须在%3之内：%4 到 %5 步。</translation>
    </message>
    <message>
        <source>From and to must be more than %1 steps apart.</source>
        <translation>起点和终点必须相距超过 %1 步。</translation>
    </message>
    <message>
        <source>%1 must lie between %2 and %3.</source>
        <translation>%1 必须介于 %2 和 %3 之间。</translation>
    </message>
    <message>
        <source>The recording must last more than 0 and at most %1 seconds.</source>
        <translation>记录时长必须大于 0 且不超过 %1 秒。</translation>
    </message>
    <message>
        <source>A sweep has 1 to %1 legs.</source>
        <translation>一次扫动包含 1 到 %1 段。</translation>
    </message>
    <message>
        <source>%1 is no longer on the bus.</source>
        <translation>%1 已不在总线上。</translation>
    </message>
    <message>
        <source>Servo ID %1</source>
        <translation>舵机 ID %1</translation>
    </message>
</context>
<context>
    <name>MotorFinder</name>
    <message>
        <source>this motor</source>
        <translation>此电机</translation>
    </message>
    <message>
        <source>Stopped; nothing was written.</source>
        <translation>已停止；未写入任何内容。</translation>
    </message>
    <message>
        <source>ID %1 at %2</source>
        <translation>ID %1，波特率 %2</translation>
    </message>
    <message>
        <source>several at %1 whose replies collide</source>
        <translation>%1 下有多个舵机，其应答相互冲突</translation>
    </message>
    <message>
        <source>No servo answers at any rate: check the power and the cable, and connect the next servo.</source>
        <translation>在任何波特率下都没有舵机应答：请检查电源和电缆，并连接下一个舵机。</translation>
    </message>
    <message>
        <source>Two servos answer at ID %1; connect them one at a time.</source>
        <translation>有两个舵机以 ID %1 应答；请逐个连接。</translation>
    </message>
    <message>
        <source>At least %1 servos answer (%2): connect one servo at a time.</source>
        <translation>至少有 %1 个舵机应答（%2）：请一次只连接一个舵机。</translation>
    </message>
    <message>
        <source>%1 servos answer (%2): connect one servo at a time.</source>
        <translation>有 %1 个舵机应答（%2）：请一次只连接一个舵机。</translation>
    </message>
    <message>
        <source>A reply at %1 looked like servo %2, which then did not answer: probably several servos whose replies collide. Connect one servo at a time.</source>
        <translation>%1 下的一个应答看起来来自舵机 %2，但随后它没有应答：可能是多个舵机的应答相互冲突。请一次只连接一个舵机。</translation>
    </message>
    <message>
        <source>%1 stopped answering: check the power and the cable, then look again.</source>
        <translation>%1 已停止应答：请检查电源和电缆，然后重新查找。</translation>
    </message>
    <message>
        <source>Found %1, model %2 (model number %3), which ServoBench has no register table for; nothing was written.</source>
        <translation>找到 %1，型号 %2（型号编号 %3），ServoBench 没有该型号的寄存器表；未写入任何内容。</translation>
    </message>
    <message>
        <source>Found %1, model %2, but %3 needs model %4. Nothing was written: connect a servo of model %4.</source>
        <translation>找到 %1，型号 %2，但 %3 需要型号 %4。未写入任何内容：请连接型号为 %4 的舵机。</translation>
    </message>
    <message>
        <source>Found one servo: %1, model %2.</source>
        <translation>找到一个舵机：%1，型号 %2。</translation>
    </message>
</context>
<context>
    <name>MotorSetup</name>
    <message>
        <source>ID %1 answers as model %2, not %3.</source>
        <translation>ID %1 应答的型号为 %2，而不是 %3。</translation>
    </message>
    <message>
        <source>ID %1 answers, but %2.</source>
        <translation>ID %1 有应答，但%2。</translation>
    </message>
    <message>
        <source>ID %1 is out of range (0 to %2).</source>
        <translation>ID %1 超出范围（0 到 %2）。</translation>
    </message>
    <message>
        <source>%1 is not a Feetech baud rate.</source>
        <translation>%1 不是 Feetech 支持的波特率。</translation>
    </message>
    <message>
        <source>Looking for the servo at every baud rate…</source>
        <translation>正在每种波特率下查找舵机…</translation>
    </message>
    <message>
        <source>Model %1 cannot run at %2; nothing was written.</source>
        <translation>型号 %1 不支持 %2；未写入任何内容。</translation>
    </message>
    <message>
        <source>The settings do not suit this servo (%1); nothing was written.</source>
        <translation>这些设置不适合此舵机（%1）；未写入任何内容。</translation>
    </message>
    <message>
        <source>Stopped before %1. The servo answers as %2; nothing more was written.</source>
        <translation>在%1 之前已停止。舵机以 %2 应答；未再写入任何内容。</translation>
    </message>
    <message>
        <source>giving it ID %1</source>
        <translation>为其分配 ID %1</translation>
    </message>
    <message>
        <source>Giving it ID %1…</source>
        <translation>正在为其分配 ID %1…</translation>
    </message>
    <message>
        <source>It already has ID %1.</source>
        <translation>它的 ID 已经是 %1。</translation>
    </message>
    <message>
        <source>moving it to %1</source>
        <translation>将其改为 %1</translation>
    </message>
    <message>
        <source>Moving it to %1…</source>
        <translation>正在将其改为 %1…</translation>
    </message>
    <message>
        <source>It already runs at %1.</source>
        <translation>它已经以 %1 运行。</translation>
    </message>
    <message>
        <source>writing its settings</source>
        <translation>写入其设置</translation>
    </message>
    <message numerus="yes">
        <source>Writing %n setting(s)…</source>
        <translation>
            <numerusform>正在写入 %n 项设置…</numerusform>
        </translation>
    </message>
    <message>
        <source>It already holds every setting.</source>
        <translation>它已具有所有设置。</translation>
    </message>
    <message>
        <source>Wrote %1 with the EEPROM unlocked, then locked it again.</source>
        <translation>已在 EEPROM 解锁状态下写入 %1，然后重新上锁。</translation>
    </message>
    <message>
        <source>Wrote %1.</source>
        <translation>已写入 %1。</translation>
    </message>
    <message>
        <source>Reading the settings back…</source>
        <translation>正在回读设置…</translation>
    </message>
    <message>
        <source>%1 should be %2 but reads %3</source>
        <translation>%1 应为 %2，但读数为 %3</translation>
    </message>
    <message>
        <source>nothing</source>
        <translation>无</translation>
    </message>
    <message>
        <source>Verification failed: %1.</source>
        <translation>验证失败：%1。</translation>
    </message>
    <message numerus="yes">
        <source>Read back: %n setting(s) hold their values.</source>
        <translation>
            <numerusform>回读：%n 项设置保持其值。</numerusform>
        </translation>
    </message>
    <message>
        <source>The servo</source>
        <translation>该舵机</translation>
    </message>
    <message numerus="yes">
        <source>%1 is set up: %2, %n setting(s) verified.</source>
        <translation>
            <numerusform>%1 已设置完成：%2，已验证 %n 项设置。</numerusform>
        </translation>
    </message>
    <message>
        <source>Asking ID %1 at %2…</source>
        <translation>正在以 %2 询问 ID %1…</translation>
    </message>
    <message>
        <source>%1 could not be read</source>
        <translation>无法读取 %1</translation>
    </message>
    <message>
        <source>%1 is %2, not %3</source>
        <translation>%1 为 %2，而不是 %3</translation>
    </message>
    <message>
        <source>%1 could not be read back</source>
        <translation>无法回读 %1</translation>
    </message>
    <message>
        <source>%1 reads %2, with bits 0x%3 still set</source>
        <translation>%1 读数为 %2，位 0x%3 仍处于置位状态</translation>
    </message>
    <message>
        <source>%1 is %2, with bits 0x%3 set</source>
        <translation>%1 为 %2，位 0x%3 已置位</translation>
    </message>
</context>
<context>
    <name>MotorSetupFlow</name>
    <message>
        <source>set up earlier, but ID %1 does not answer now</source>
        <translation>之前已设置，但 ID %1 现在无应答</translation>
    </message>
</context>
<context>
    <name>OverloadRecoveryDialog</name>
    <message>
        <source>Recover servo ID %1</source>
        <translation>恢复舵机 ID %1</translation>
    </message>
    <message>
        <source>The overload protection of servo ID %1 tripped: its torque is off.

First free the horn (remove what blocks it). Then ServoBench switches its torque off and on again, with the goal at the present position so nothing moves, and reads the overload bit.</source>
        <translation>舵机 ID %1 的过载保护已触发：其扭矩已关闭。

请先松开舵盘（移除阻挡它的物体）。然后 ServoBench 会在目标设为当前位置（因此不会移动）的情况下关闭并重新开启其扭矩，并读取过载位。</translation>
    </message>
    <message>
        <source>Torque off and on</source>
        <translation>关闭并重新开启扭矩</translation>
    </message>
    <message>
        <source>Servo ID %1 is no longer on the bus.</source>
        <translation>舵机 ID %1 已不在总线上。</translation>
    </message>
    <message>
        <source>Reading the status…</source>
        <translation>正在读取状态…</translation>
    </message>
    <message>
        <source>Torque off and on…</source>
        <translation>正在关闭并重新开启扭矩…</translation>
    </message>
    <message>
        <source>Check again</source>
        <translation>再次检查</translation>
    </message>
    <message>
        <source>The recovery failed: %1</source>
        <translation>恢复失败：%1</translation>
    </message>
</context>
<context>
    <name>PacketLogDock</name>
    <message>
        <source>Packet log</source>
        <translation>数据包日志</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>暂停</translation>
    </message>
    <message>
        <source>Freeze the log to read it; frames arriving meanwhile are kept and appear when you resume</source>
        <translation>冻结日志以便阅读；期间到达的帧会被保留，并在继续时显示</translation>
    </message>
    <message>
        <source>Clear</source>
        <translation>清除</translation>
    </message>
    <message>
        <source>Remove every frame from the log and reset the counts</source>
        <translation>从日志中移除所有帧并重置计数</translation>
    </message>
    <message>
        <source>Export…</source>
        <translation>导出…</translation>
    </message>
    <message>
        <source>Save the frames shown to a tab-separated text file</source>
        <translation>将显示的帧保存为制表符分隔的文本文件</translation>
    </message>
    <message>
        <source>Errors only</source>
        <translation>仅显示错误</translation>
    </message>
    <message>
        <source>Show only frames with an error (bad checksum, timeout, unexpected bytes)</source>
        <translation>仅显示有错误的帧（校验和错误、超时、意外字节）</translation>
    </message>
    <message>
        <source>Direction</source>
        <translation>方向</translation>
    </message>
    <message>
        <source>→ out</source>
        <translation>→ 发出</translation>
    </message>
    <message>
        <source>%1, %2</source>
        <translation>%1，%2</translation>
    </message>
    <message numerus="yes">
        <source>%n frame(s)</source>
        <translation>
            <numerusform>%n 帧</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n error(s)</source>
        <translation>
            <numerusform>%n 个错误</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 (paused)</source>
        <translation>%1（已暂停）</translation>
    </message>
    <message>
        <source>New frames are kept while paused and appear when you resume</source>
        <translation>暂停期间新帧会被保留，并在继续时显示</translation>
    </message>
    <message>
        <source>Export packet log</source>
        <translation>导出数据包日志</translation>
    </message>
    <message>
        <source>Tab-separated text (*.tsv *.txt);;All files (*)</source>
        <translation>制表符分隔文本 (*.tsv *.txt);;所有文件 (*)</translation>
    </message>
    <message>
        <source>Open recording…</source>
        <translation>打开记录…</translation>
    </message>
    <message>
        <source>Show a shared bus&apos;s recording (Link &gt; Share this bus…) with the meaning of each frame</source>
        <translation>显示共享总线的记录（连接 &gt; 共享此总线…）及每一帧的含义</translation>
    </message>
    <message>
        <source>Open a shared bus recording</source>
        <translation>打开共享总线记录</translation>
    </message>
    <message>
        <source>Share recordings (*.txt);;All files (*)</source>
        <translation>共享记录 (*.txt);;所有文件 (*)</translation>
    </message>
    <message>
        <source>Open recording</source>
        <translation>打开记录</translation>
    </message>
    <message numerus="yes">
        <source>The log keeps the newest %n frame(s), errors longer; older ones were dropped</source>
        <translation>
            <numerusform>日志保留最新的 %n 帧，错误保留更久；更早的已丢弃</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n older error(s) among them</source>
        <translation>
            <numerusform>其中包括 %n 个较早的错误</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>PacketSequence</name>
    <message>
        <source>not a ServoBench packet sequence (the document is not a JSON object)</source>
        <translation>不是 ServoBench 数据包序列（文档不是 JSON 对象）</translation>
    </message>
    <message>
        <source>not a ServoBench packet sequence (&quot;%1&quot; is not &quot;%2&quot;)</source>
        <translation>不是 ServoBench 数据包序列（“%1”不是“%2”）</translation>
    </message>
    <message>
        <source>the packet sequence has format version %1 and was written by a newer ServoBench; this version reads format version %2 and older</source>
        <translation>该数据包序列的格式版本为 %1，由更新的 ServoBench 写入；此版本只能读取格式版本 %2 及更早的版本</translation>
    </message>
    <message>
        <source>It writes to the PTK servo, outside the verified write sequence of its settings page.</source>
        <translation>它会写入 PTK 舵机，不经过设置页经过验证的写入流程。</translation>
    </message>
    <message>
        <source>every servo on the bus</source>
        <translation>总线上的所有舵机</translation>
    </message>
    <message>
        <source>servo %1</source>
        <translation>舵机 %1</translation>
    </message>
    <message>
        <source>It restores the factory values of %1 (its settings are lost).</source>
        <translation>它会恢复%1的出厂值（现有设置将丢失）。</translation>
    </message>
    <message>
        <source>It makes the present position the middle of %1 (written to EEPROM).</source>
        <translation>它会把%1的当前位置设为中位（写入 EEPROM）。</translation>
    </message>
    <message>
        <source>It asks %1 to store its settings (an EEPROM write).</source>
        <translation>它会让%1保存其设置（写入 EEPROM）。</translation>
    </message>
    <message>
        <source>It writes %1 of %2, in EEPROM: the servo keeps it when powered off, and a wrong ID or baud rate makes it answer elsewhere.</source>
        <translation>它会写入%2的 %1（EEPROM）：断电后舵机仍保留该值，错误的 ID 或波特率会使舵机在别处应答。</translation>
    </message>
    <message>
        <source>too large to be a packet sequence</source>
        <translation>太大，不可能是数据包序列</translation>
    </message>
    <message>
        <source>&quot;%1&quot; must be a list of frames</source>
        <translation>“%1”必须是帧列表</translation>
    </message>
    <message>
        <source>more than %1 frames</source>
        <translation>超过 %1 帧</translation>
    </message>
    <message>
        <source>frame %1 is not an object of protocol, hex and baud</source>
        <translation>第 %1 帧不是由 protocol、hex 和 baud 组成的对象</translation>
    </message>
    <message>
        <source>frame %1: its hex is not hexadecimal bytes</source>
        <translation>第 %1 帧：其 hex 不是十六进制字节</translation>
    </message>
    <message>
        <source>frame %1: the protocol must be feetech or ptk</source>
        <translation>第 %1 帧：协议必须是 feetech 或 ptk</translation>
    </message>
    <message>
        <source>frame %1 is not a whole %2 frame at a known rate</source>
        <translation>第 %1 帧不是已知波特率下完整的 %2 帧</translation>
    </message>
</context>
<context>
    <name>PacketSequenceFiles</name>
    <message>
        <source>The history is empty: there is nothing to save.</source>
        <translation>历史为空：没有可保存的内容。</translation>
    </message>
    <message>
        <source>Save packet sequence</source>
        <translation>保存数据包序列</translation>
    </message>
    <message>
        <source>ServoBench packet sequences (*.json)</source>
        <translation>ServoBench 数据包序列 (*.json)</translation>
    </message>
    <message numerus="yes">
        <source>Saved %n frame(s).</source>
        <translation>
            <numerusform>已保存 %n 帧。</numerusform>
        </translation>
    </message>
    <message>
        <source>Load packet sequence</source>
        <translation>加载数据包序列</translation>
    </message>
    <message>
        <source>Loaded into the history: select a frame and Resend, or Send all.</source>
        <translation>已加载到历史：选择一帧后点“重新发送”，或点“全部发送”。</translation>
    </message>
</context>
<context>
    <name>PacketWindow</name>
    <message>
        <source>Packet window</source>
        <translation>数据包窗口</translation>
    </message>
    <message>
        <source>Send this frame?</source>
        <translation>发送此帧？</translation>
    </message>
    <message>
        <source>Send it?</source>
        <translation>要发送吗？</translation>
    </message>
    <message>
        <source>Feetech</source>
        <translation>飞特</translation>
    </message>
    <message>
        <source>PTK</source>
        <translation>PTK</translation>
    </message>
    <message>
        <source>Send</source>
        <translation>发送</translation>
    </message>
    <message>
        <source>Time</source>
        <translation>时间</translation>
    </message>
    <message>
        <source>Frame</source>
        <translation>帧</translation>
    </message>
    <message>
        <source>Meaning</source>
        <translation>含义</translation>
    </message>
    <message>
        <source>Answer</source>
        <translation>应答</translation>
    </message>
    <message>
        <source>Resend</source>
        <translation>重新发送</translation>
    </message>
    <message>
        <source>Send all</source>
        <translation>全部发送</translation>
    </message>
    <message>
        <source>Send every frame of the history again, oldest first</source>
        <translation>按从旧到新的顺序重新发送历史中的每一帧</translation>
    </message>
    <message>
        <source>Save sequence…</source>
        <translation>保存序列…</translation>
    </message>
    <message>
        <source>Load sequence…</source>
        <translation>加载序列…</translation>
    </message>
    <message>
        <source>Clear</source>
        <translation>清空</translation>
    </message>
    <message>
        <source>History (double-click a frame to send it again):</source>
        <translation>历史（双击某帧可再次发送）：</translation>
    </message>
    <message>
        <source>The connection closed.</source>
        <translation>连接已关闭。</translation>
    </message>
    <message>
        <source>PING</source>
        <translation>PING（查询状态）</translation>
    </message>
    <message>
        <source>READ</source>
        <translation>READ（读数据）</translation>
    </message>
    <message>
        <source>WRITE</source>
        <translation>WRITE（写数据）</translation>
    </message>
    <message>
        <source>REG WRITE</source>
        <translation>REG WRITE（异步写）</translation>
    </message>
    <message>
        <source>ACTION</source>
        <translation>ACTION（执行异步写）</translation>
    </message>
    <message>
        <source>SYNC READ</source>
        <translation>SYNC READ（同步读）</translation>
    </message>
    <message>
        <source>SYNC WRITE</source>
        <translation>SYNC WRITE（同步写）</translation>
    </message>
    <message>
        <source>RECOVERY (factory values)</source>
        <translation>RECOVERY（恢复出厂值）</translation>
    </message>
    <message>
        <source>REBOOT</source>
        <translation>REBOOT（重启）</translation>
    </message>
    <message>
        <source>RESET (clear the status)</source>
        <translation>RESET（清除状态）</translation>
    </message>
    <message>
        <source>CALIBRATE (middle)</source>
        <translation>CALIBRATE（中位校准）</translation>
    </message>
    <message>
        <source>Another code</source>
        <translation>其他指令码</translation>
    </message>
    <message>
        <source>254 (0xFE) is the broadcast ID: every servo acts, none answers</source>
        <translation>254 (0xFE) 是广播 ID：所有舵机执行，均不应答</translation>
    </message>
    <message>
        <source>hex bytes, e.g. 00 08</source>
        <translation>十六进制字节，例如 00 08</translation>
    </message>
    <message>
        <source>e.g. 1,2,3 or 1-6</source>
        <translation>例如 1,2,3 或 1-6</translation>
    </message>
    <message>
        <source>%L1 bps</source>
        <translation>%L1 bps</translation>
    </message>
    <message>
        <source>Instruction:</source>
        <translation>指令：</translation>
    </message>
    <message>
        <source>Code:</source>
        <translation>指令码：</translation>
    </message>
    <message>
        <source>ID:</source>
        <translation>ID：</translation>
    </message>
    <message>
        <source>Address:</source>
        <translation>地址：</translation>
    </message>
    <message>
        <source>Length:</source>
        <translation>长度：</translation>
    </message>
    <message>
        <source>Data:</source>
        <translation>数据：</translation>
    </message>
    <message>
        <source>IDs:</source>
        <translation>ID 列表：</translation>
    </message>
    <message>
        <source>Baud rate:</source>
        <translation>波特率：</translation>
    </message>
    <message>
        <source>Query %1 (command %2)</source>
        <translation>查询 %1（命令 %2）</translation>
    </message>
    <message>
        <source>Write %1 (command %2)</source>
        <translation>写入 %1（命令 %2）</translation>
    </message>
    <message>
        <source>Another command</source>
        <translation>其他命令</translation>
    </message>
    <message>
        <source>Command:</source>
        <translation>命令：</translation>
    </message>
    <message>
        <source>First word:</source>
        <translation>第一个字：</translation>
    </message>
    <message>
        <source>Second word:</source>
        <translation>第二个字：</translation>
    </message>
    <message>
        <source>A query is answered with two words; the servo never acknowledges a write. PTK servos talk at 115200 baud.</source>
        <translation>查询的应答为两个字；舵机从不确认写入。PTK 舵机的波特率为 115200。</translation>
    </message>
    <message>
        <source>Data: %1</source>
        <translation>数据：%1</translation>
    </message>
    <message>
        <source>Data: give the bytes to write.</source>
        <translation>数据：请给出要写入的字节。</translation>
    </message>
    <message numerus="yes">
        <source>Data: %n byte(s) for each of the %1 servo(s), one after the other.</source>
        <translation>
            <numerusform>数据：%1 个舵机依次各 %n 字节。</numerusform>
        </translation>
    </message>
    <message>
        <source>Data: none, or the 2-byte position to make the middle.</source>
        <translation>数据：留空，或给出要设为中位的 2 字节位置。</translation>
    </message>
    <message>
        <source>The frame would be %1 bytes; a Feetech frame holds at most %2.</source>
        <translation>该帧将有 %1 字节；飞特帧最多 %2 字节。</translation>
    </message>
    <message>
        <source>The fields do not make a whole frame.</source>
        <translation>这些字段无法组成完整的帧。</translation>
    </message>
    <message>
        <source>Connect to a Feetech bus first</source>
        <translation>请先连接飞特总线</translation>
    </message>
    <message>
        <source>Connect to a PTK servo first</source>
        <translation>请先连接 PTK 舵机</translation>
    </message>
    <message>
        <source>Wait until the frames on their way are answered.</source>
        <translation>请等待已发送的帧得到应答。</translation>
    </message>
    <message>
        <source>There is nothing to send.</source>
        <translation>没有可发送的内容。</translation>
    </message>
    <message>
        <source>Connect to a Feetech bus first.</source>
        <translation>请先连接飞特总线。</translation>
    </message>
    <message>
        <source>Connect to a PTK servo first.</source>
        <translation>请先连接 PTK 舵机。</translation>
    </message>
    <message>
        <source>Nothing was sent.</source>
        <translation>未发送任何内容。</translation>
    </message>
    <message>
        <source>sending…</source>
        <translation>正在发送…</translation>
    </message>
    <message>
        <source>Choose a frame of the history first.</source>
        <translation>请先在历史中选择一帧。</translation>
    </message>
    <message>
        <source>loaded, not sent</source>
        <translation>已加载，未发送</translation>
    </message>
</context>
<context>
    <name>ParameterPage</name>
    <message>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <source> or </source>
        <translation> 或 </translation>
    </message>
    <message>
        <source>%1: %2 to %3%4</source>
        <translation>%1：%2 到 %3%4</translation>
    </message>
    <message>
        <source>—</source>
        <translation>—</translation>
    </message>
    <message>
        <source>Load profile…</source>
        <translation>加载配置文件…</translation>
    </message>
    <message>
        <source>Load parameter values from a profile file as edits</source>
        <translation>从配置文件加载参数值作为编辑</translation>
    </message>
    <message>
        <source>Save profile…</source>
        <translation>保存配置文件…</translation>
    </message>
    <message>
        <source>Save the servo&apos;s parameter values to a profile file</source>
        <translation>将舵机的参数值保存到配置文件</translation>
    </message>
    <message>
        <source>Read</source>
        <translation>读取</translation>
    </message>
    <message>
        <source>Read every parameter from the servo</source>
        <translation>从舵机读取所有参数</translation>
    </message>
    <message>
        <source>Revert</source>
        <translation>还原</translation>
    </message>
    <message>
        <source>Drop every edit and show the servo&apos;s values again</source>
        <translation>放弃所有编辑，重新显示舵机的值</translation>
    </message>
    <message>
        <source>Apply</source>
        <translation>应用</translation>
    </message>
    <message>
        <source>Write the edited parameters to the servo, then read them back to verify</source>
        <translation>将已编辑的参数写入舵机，然后回读以验证</translation>
    </message>
    <message>
        <source>%v of %m</source>
        <translation>%v / %m</translation>
    </message>
    <message>
        <source>&lt;b&gt;Device&lt;/b&gt; is what the servo reports. Edits are written only when you press &lt;b&gt;Apply&lt;/b&gt;, then read back and verified.</source>
        <translation>&lt;b&gt;设备&lt;/b&gt;是舵机报告的值。编辑只有在按下&lt;b&gt;应用&lt;/b&gt;时才会写入，然后回读并验证。</translation>
    </message>
    <message>
        <source>Device</source>
        <translation>设备</translation>
    </message>
    <message>
        <source>New value</source>
        <translation>新值</translation>
    </message>
    <message>
        <source>State</source>
        <translation>状态</translation>
    </message>
    <message>
        <source>EEPROM</source>
        <translation>EEPROM</translation>
    </message>
    <message>
        <source>Kept in the servo&apos;s EEPROM: written with the lock opened and closed again, and kept after power-off</source>
        <translation>保存在舵机的 EEPROM 中：写入时先解锁再重新上锁，断电后仍保留</translation>
    </message>
    <message>
        <source>Refused</source>
        <translation>已拒绝</translation>
    </message>
    <message>
        <source>Not read from the servo yet</source>
        <translation>尚未从舵机读取</translation>
    </message>
    <message>
        <source>Changed here; written to the servo when you press Apply</source>
        <translation>已在此处更改；按下“应用”时写入舵机</translation>
    </message>
    <message>
        <source>Being written to the servo</source>
        <translation>正在写入舵机</translation>
    </message>
    <message>
        <source>Written and read back with the same value</source>
        <translation>已写入并回读到相同的值</translation>
    </message>
    <message>
        <source>The value read back differs from the value written</source>
        <translation>回读的值与写入的值不同</translation>
    </message>
    <message>
        <source>The write did not take effect; the edit is kept so you can try again</source>
        <translation>写入未生效；编辑已保留，您可以重试</translation>
    </message>
    <message>
        <source>The write went out but no answer confirmed it, so whether the servo took it is not known; the next read settles it, and the edit is kept</source>
        <translation>写入已发出，但没有应答确认，因此无法得知舵机是否已接受；下次读取时会确定，编辑已保留</translation>
    </message>
</context>
<context>
    <name>PortAccess</name>
    <message>
        <source>process %1</source>
        <translation>进程 %1</translation>
    </message>
    <message>
        <source>%1 (process %2)</source>
        <translation>%1（进程 %2）</translation>
    </message>
</context>
<context>
    <name>PortProbe</name>
    <message>
        <source>Asking for a PTK servo at %1…</source>
        <translation>正在以 %1 查询 PTK 舵机…</translation>
    </message>
    <message>
        <source>Asking for Feetech servos at %1…</source>
        <translation>正在以 %1 查询 Feetech 舵机…</translation>
    </message>
    <message>
        <source>the port refused %1</source>
        <translation>端口拒绝了 %1</translation>
    </message>
</context>
<context>
    <name>Pose</name>
    <message>
        <source>not a JSON object</source>
        <translation>不是 JSON 对象</translation>
    </message>
    <message>
        <source>unknown entry &quot;%1&quot;</source>
        <translation>未知条目“%1”</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is missing</source>
        <translation>缺少“%1”</translation>
    </message>
    <message>
        <source>&quot;%1&quot;: %2 is not a servo ID (0 to %3)</source>
        <translation>“%1”：%2 不是有效的舵机 ID（0 到 %3）</translation>
    </message>
    <message>
        <source>&quot;%1&quot;: %2 is not a Feetech baud rate in bps</source>
        <translation>“%1”：%2 不是以 bps 为单位的 Feetech 波特率</translation>
    </message>
    <message>
        <source>&quot;%1&quot;: %2 is not an integer number of steps</source>
        <translation>“%1”：%2 不是整数步数</translation>
    </message>
    <message>
        <source>&quot;%1&quot;: %2 is out of range (%3 to %4)</source>
        <translation>“%1”：%2 超出范围（%3 到 %4）</translation>
    </message>
    <message>
        <source>&quot;%1&quot; must be text</source>
        <translation>“%1”必须是文本</translation>
    </message>
    <message>
        <source>the pose has no &quot;%1&quot; list</source>
        <translation>姿态中没有“%1”列表</translation>
    </message>
    <message>
        <source>servo entry %1: %2</source>
        <translation>舵机条目 %1：%2</translation>
    </message>
    <message>
        <source>servo entry %1: ID %2 at %3 bps is already in the pose</source>
        <translation>舵机条目 %1：波特率 %3 bps 下的 ID %2 已在姿态中</translation>
    </message>
    <message>
        <source>too large to be a pose</source>
        <translation>过大，不可能是姿态文件</translation>
    </message>
    <message>
        <source>not a ServoBench pose (the document is not a JSON object)</source>
        <translation>不是 ServoBench 姿态文件（文档不是 JSON 对象）</translation>
    </message>
    <message>
        <source>not a ServoBench pose (&quot;%1&quot; is not &quot;%2&quot;)</source>
        <translation>不是 ServoBench 姿态文件（“%1”不是“%2”）</translation>
    </message>
    <message>
        <source>the pose has format version %1 and was written by a newer ServoBench; this version reads format version %2 and older</source>
        <translation>该姿态文件的格式版本为 %1，由较新版本的 ServoBench 写入；此版本只能读取格式版本 %2 及更早的版本</translation>
    </message>
</context>
<context>
    <name>Profile</name>
    <message>
        <source>expected true or false</source>
        <translation>应为 true 或 false</translation>
    </message>
    <message>
        <source>expected a number</source>
        <translation>应为数字</translation>
    </message>
    <message>
        <source>%1 is out of range (%2 to %3)</source>
        <translation>%1 超出范围（%2 到 %3）</translation>
    </message>
    <message>
        <source>%1 is not a whole number</source>
        <translation>%1 不是整数</translation>
    </message>
    <message>
        <source>%1 is not a multiple of %2</source>
        <translation>%1 不是 %2 的倍数</translation>
    </message>
    <message>
        <source>unknown parameter &quot;%1&quot;</source>
        <translation>未知参数“%1”</translation>
    </message>
    <message>
        <source>%1: the raw value %2 cannot be kept in a profile</source>
        <translation>%1：原始值 %2 无法保存在配置文件中</translation>
    </message>
    <message>
        <source>the profile names no servo family</source>
        <translation>配置文件中没有指定舵机系列</translation>
    </message>
    <message>
        <source>the profile is for &quot;%1&quot; servos, not &quot;%2&quot;</source>
        <translation>该配置文件适用于“%1”舵机，而不是“%2”</translation>
    </message>
    <message>
        <source>&quot;%1&quot; must be text</source>
        <translation>“%1”必须是文本</translation>
    </message>
    <message>
        <source>&quot;%1&quot;: &quot;%2&quot; is not an ISO 8601 date and time</source>
        <translation>&quot;%1&quot;：&quot;%2&quot; 不是 ISO 8601 日期时间</translation>
    </message>
    <message>
        <source>the profile has no &quot;%1&quot; object</source>
        <translation>配置文件中没有 &quot;%1&quot; 对象</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <source>too large to be a profile</source>
        <translation>文件太大，不可能是配置文件</translation>
    </message>
    <message>
        <source>not a ServoBench profile (the document is not a JSON object)</source>
        <translation>不是 ServoBench 配置文件（文档不是 JSON 对象）</translation>
    </message>
    <message>
        <source>not a ServoBench profile (&quot;%1&quot; is not &quot;%2&quot;)</source>
        <translation>不是 ServoBench 配置文件（&quot;%1&quot; 不是 &quot;%2&quot;）</translation>
    </message>
    <message>
        <source>the profile has format version %1 and was written by a newer ServoBench; this version reads format version %2 and older</source>
        <translation>该配置文件的格式版本为 %1，由较新版本的 ServoBench 写入；本版本只能读取格式版本 %2 及更早版本</translation>
    </message>
</context>
<context>
    <name>ProfileActions</name>
    <message>
        <source>Save profile</source>
        <translation>保存配置文件</translation>
    </message>
    <message>
        <source>ServoBench profiles (*.json)</source>
        <translation>ServoBench 配置文件 (*.json)</translation>
    </message>
    <message>
        <source>Load profile</source>
        <translation>加载配置文件</translation>
    </message>
    <message>
        <source>Read the servo before saving a profile: not every value is known.</source>
        <translation>保存配置文件前请先读取舵机：并非所有值都已知。</translation>
    </message>
    <message>
        <source>The profile was not loaded: %1</source>
        <translation>配置文件未加载：%1</translation>
    </message>
    <message>
        <source>The servo already holds every value of this profile</source>
        <translation>舵机已包含此配置文件的所有值</translation>
    </message>
    <message>
        <source>Profile loaded as edits: review them, then Apply</source>
        <translation>配置文件已作为修改加载：请检查后再点击“应用”</translation>
    </message>
</context>
<context>
    <name>ProfileDiffDialog</name>
    <message>
        <source>Load profile</source>
        <translation>加载配置文件</translation>
    </message>
    <message numerus="yes">
        <source>%n parameter(s) in %1 differ from the servo. Loading makes them edits; nothing is written until you press Apply.</source>
        <translation>
            <numerusform>%1 中有 %n 个参数与舵机不同。加载后它们成为修改项；点击“应用”之前不会写入任何内容。</numerusform>
        </translation>
    </message>
    <message>
        <source>Parameter</source>
        <translation>参数</translation>
    </message>
    <message>
        <source>On the servo</source>
        <translation>舵机上</translation>
    </message>
    <message>
        <source>In the file</source>
        <translation>文件中</translation>
    </message>
    <message>
        <source>not read</source>
        <translation>未读取</translation>
    </message>
    <message>
        <source>Load as edits</source>
        <translation>作为修改加载</translation>
    </message>
</context>
<context>
    <name>PseudoTerminal</name>
    <message>
        <source>cannot open a pseudo-terminal: %1</source>
        <translation>无法打开伪终端：%1</translation>
    </message>
    <message>
        <source>cannot unlock the pseudo-terminal: %1</source>
        <translation>无法解锁伪终端：%1</translation>
    </message>
    <message>
        <source>cannot name the pseudo-terminal&apos;s slave</source>
        <translation>无法获取伪终端从设备的名称</translation>
    </message>
    <message>
        <source>cannot replace the old link %1: %2</source>
        <translation>无法替换旧链接 %1：%2</translation>
    </message>
    <message>
        <source>%1 exists and is not a symlink; choose another --link path</source>
        <translation>%1 已存在且不是符号链接；请另选一个 --link 路径</translation>
    </message>
    <message>
        <source>cannot create the link %1: %2</source>
        <translation>无法创建链接 %1：%2</translation>
    </message>
    <message>
        <source>Simulated servos need a pseudo-terminal, which this system does not have: they run on Linux and macOS.</source>
        <translation>模拟舵机需要伪终端，而本系统没有：模拟舵机可在 Linux 和 macOS 上运行。</translation>
    </message>
</context>
<context>
    <name>PtkClient</name>
    <message>
        <source>The servo is not connected.</source>
        <translation>舵机未连接。</translation>
    </message>
    <message>
        <source>A read or write is already running.</source>
        <translation>已有读取或写入正在进行。</translation>
    </message>
    <message>
        <source>There are no changes to apply.</source>
        <translation>没有需要应用的更改。</translation>
    </message>
    <message>
        <source>%1 has not been read yet.</source>
        <translation>%1 尚未读取。</translation>
    </message>
    <message>
        <source>Wait until the servo&apos;s read or Apply has finished.</source>
        <translation>请等待舵机的读取或应用完成。</translation>
    </message>
</context>
<context>
    <name>PtkSession</name>
    <message>
        <source>Disconnected during Apply; the servo may hold only part of the new values.</source>
        <translation>应用过程中连接断开；舵机可能只保存了部分新值。</translation>
    </message>
    <message>
        <source>The link went down during Apply: %1</source>
        <translation>应用过程中链路断开：%1</translation>
    </message>
    <message>
        <source>Disconnected during the read.</source>
        <translation>读取过程中连接断开。</translation>
    </message>
    <message>
        <source>Not connected.</source>
        <translation>未连接。</translation>
    </message>
    <message>
        <source>Busy: a read or write is already running.</source>
        <translation>忙：已有读取或写入正在进行。</translation>
    </message>
    <message>
        <source>No answer to the query for %1.</source>
        <translation>查询 %1 时无应答。</translation>
    </message>
    <message>
        <source>Written, but not verified. %1</source>
        <translation>已写入，但未验证。%1</translation>
    </message>
    <message>
        <source>The link went down before the values could be read back.</source>
        <translation>在回读数值之前链路已断开。</translation>
    </message>
    <message>
        <source>The link went down.</source>
        <translation>链路已断开。</translation>
    </message>
    <message>
        <source>%1 has not been read yet; nothing was written.</source>
        <translation>%1 尚未读取；未写入任何内容。</translation>
    </message>
    <message>
        <source>%1; nothing was written.</source>
        <translation>%1；未写入任何内容。</translation>
    </message>
    <message>
        <source>The link went down while writing %1; the servo may hold only part of the new values.</source>
        <translation>写入 %1 时链路断开；舵机可能只保存了部分新值。</translation>
    </message>
    <message>
        <source>The port is open but the servo does not answer. Check that it is powered and plugged into the programmer.</source>
        <translation>端口已打开，但舵机没有应答。请检查舵机是否已通电并已插入编程器。</translation>
    </message>
    <message>
        <source>The frame was not sent: the link is down.</source>
        <translation>帧未发送：连接已断开。</translation>
    </message>
    <message>
        <source>Sent.</source>
        <translation>已发送。</translation>
    </message>
    <message>
        <source>The servo answered.</source>
        <translation>舵机已应答。</translation>
    </message>
    <message>
        <source>Sent; the servo did not answer.</source>
        <translation>已发送；舵机无应答。</translation>
    </message>
</context>
<context>
    <name>PtkWorkspace</name>
    <message>
        <source>Read all parameters</source>
        <translation>读取全部参数</translation>
    </message>
    <message>
        <source>Read failed: %1</source>
        <translation>读取失败：%1</translation>
    </message>
    <message>
        <source>Nothing was written: %1</source>
        <translation>未写入任何内容：%1</translation>
    </message>
    <message>
        <source>Writing N1…N12, then reading back…</source>
        <translation>正在写入 N1…N12，然后回读…</translation>
    </message>
    <message>
        <source>The servo did not take every value: the fields marked Mismatch hold something else than was written.</source>
        <translation>舵机未接受所有值：标记为“不一致”的字段中的值与写入的值不同。</translation>
    </message>
    <message>
        <source>Written and verified</source>
        <translation>已写入并验证</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>已保存 %1</translation>
    </message>
    <message>
        <source>Wait for the running read or Apply to finish before loading a profile.</source>
        <translation>请等待正在进行的读取或应用完成后再加载配置文件。</translation>
    </message>
</context>
<context>
    <name>RecordReplayDialog</name>
    <message>
        <source>Record and replay</source>
        <translation>记录与回放</translation>
    </message>
    <message>
        <source>Joints to record</source>
        <translation>要记录的关节</translation>
    </message>
    <message>
        <source>&amp;Open…</source>
        <translation>打开(&amp;O)…</translation>
    </message>
    <message>
        <source>&amp;Save…</source>
        <translation>保存(&amp;S)…</translation>
    </message>
    <message>
        <source>Recording</source>
        <translation>记录</translation>
    </message>
    <message>
        <source>Nothing recorded yet.</source>
        <translation>尚未记录任何内容。</translation>
    </message>
    <message>
        <source>Replay</source>
        <translation>回放</translation>
    </message>
    <message>
        <source> ×</source>
        <translation> ×</translation>
    </message>
    <message>
        <source>2 plays twice as fast, 0.5 at half speed</source>
        <translation>2 表示以两倍速度播放，0.5 表示以一半速度播放</translation>
    </message>
    <message>
        <source>Between two loops the arm eases back to the first frame</source>
        <translation>两遍之间，机械臂会平缓地回到第一帧</translation>
    </message>
    <message>
        <source>Switch torque off at the end</source>
        <translation>结束时关闭扭矩</translation>
    </message>
    <message>
        <source>Otherwise the arm holds the last frame</source>
        <translation>否则机械臂保持最后一帧的姿态</translation>
    </message>
    <message>
        <source>&amp;Play</source>
        <translation>播放(&amp;P)</translation>
    </message>
    <message>
        <source>Torque on where the arm stands, a gentle move to the first frame, then the frames at their recorded times</source>
        <translation>在机械臂当前位置开启扭矩，平缓移动到第一帧，然后按记录的时间播放各帧</translation>
    </message>
    <message>
        <source>S&amp;top</source>
        <translation>停止(&amp;T)</translation>
    </message>
    <message>
        <source>Stop recording, or stop the replay with the arm held where it stands</source>
        <translation>停止记录，或停止回放并使机械臂保持在当前位置</translation>
    </message>
    <message>
        <source>Speed:</source>
        <translation>速度：</translation>
    </message>
    <message>
        <source>Loops:</source>
        <translation>遍数：</translation>
    </message>
    <message>
        <source>Nothing was recorded: not every joint answered.</source>
        <translation>未记录任何内容：并非所有关节都有应答。</translation>
    </message>
    <message numerus="yes">
        <source>Recorded %n frame(s) over %1 s.</source>
        <translation>
            <numerusform>已在 %1 秒内记录 %n 帧。</numerusform>
        </translation>
    </message>
    <message>
        <source>Stop &amp;recording</source>
        <translation>停止记录(&amp;R)</translation>
    </message>
    <message numerus="yes">
        <source>Recording: %n frame(s), %1 s</source>
        <translation>
            <numerusform>正在记录：%n 帧，%1 秒</numerusform>
        </translation>
    </message>
    <message>
        <source>Replaying: the arm eases to the first frame first.</source>
        <translation>正在回放：机械臂先平缓移动到第一帧。</translation>
    </message>
    <message>
        <source>Stopping: the arm is held where it stands…</source>
        <translation>正在停止：机械臂保持在当前位置…</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <source>%1 s of %2 s, frame %3 of %4 — %5</source>
        <translation>%1 秒 / %2 秒，第 %3/%4 帧 — %5</translation>
    </message>
    <message>
        <source>Open recording</source>
        <translation>打开记录</translation>
    </message>
    <message>
        <source>Motion recordings (*.csv)</source>
        <translation>动作记录 (*.csv)</translation>
    </message>
    <message>
        <source>Save recording</source>
        <translation>保存记录</translation>
    </message>
    <message numerus="yes">
        <source>Opened %1: %n frame(s) over %2 s.</source>
        <translation>
            <numerusform>已打开 %1：%2 秒内共 %n 帧。</numerusform>
        </translation>
    </message>
    <message>
        <source>Saved to %1.</source>
        <translation>已保存到 %1。</translation>
    </message>
    <message>
        <source>The servos whose positions are recorded; Record switches their torque off so that they can be moved by hand</source>
        <translation>要记录位置的舵机；“录制”会关闭它们的扭矩，以便用手移动</translation>
    </message>
    <message>
        <source>Torque off and &amp;record</source>
        <translation>关闭扭矩并录制(&amp;R)</translation>
    </message>
    <message>
        <source>Support the arm: torque goes off on the joints to record, so that you can move them by hand</source>
        <translation>请扶住机械臂：要录制的关节将关闭扭矩，以便您用手移动它们</translation>
    </message>
    <message>
        <source>%1 · %2 · %3 bps</source>
        <translation>%1 · %2 · %3 bps</translation>
    </message>
    <message numerus="yes">
        <source>Switching torque off on %n joint(s)…</source>
        <translation>
            <numerusform>正在关闭 %n 个关节的扭矩…</numerusform>
        </translation>
    </message>
    <message>
        <source>Recording: torque is off, move the joints by hand, then Stop.</source>
        <translation>正在录制：扭矩已关闭，请用手移动关节，然后点击停止。</translation>
    </message>
    <message>
        <source>Torque could not be switched off on %1: %2 Nothing is recorded.</source>
        <translation>无法关闭 %1 的扭矩：%2 未录制任何内容。</translation>
    </message>
    <message>
        <source>its model has no torque enable.</source>
        <translation>其型号没有扭矩开关。</translation>
    </message>
</context>
<context>
    <name>RegisterTable</name>
    <message>
        <source>not valid JSON at offset %1: %2</source>
        <translation>偏移量 %1 处不是有效的 JSON：%2</translation>
    </message>
    <message>
        <source>the document is not a JSON object</source>
        <translation>文档不是 JSON 对象</translation>
    </message>
    <message>
        <source>unsupported &quot;format&quot; (expected 1)</source>
        <translation>不支持的 &quot;format&quot;（应为 1）</translation>
    </message>
    <message>
        <source>register &quot;%1&quot; (address %2)</source>
        <translation>寄存器 &quot;%1&quot;（地址 %2）</translation>
    </message>
    <message>
        <source>unknown field &quot;%1&quot;</source>
        <translation>未知字段 &quot;%1&quot;</translation>
    </message>
    <message>
        <source>the key must be snake_case</source>
        <translation>键名必须为 snake_case 格式</translation>
    </message>
    <message>
        <source>the address must be a whole number from 0 to 255</source>
        <translation>地址必须是 0 到 255 之间的整数</translation>
    </message>
    <message>
        <source>the size must be 1 or 2 bytes</source>
        <translation>大小必须为 1 或 2 字节</translation>
    </message>
    <message>
        <source>the register runs past address 255</source>
        <translation>寄存器超出了地址 255</translation>
    </message>
    <message>
        <source>the label is missing</source>
        <translation>缺少标签</translation>
    </message>
    <message>
        <source>storage must be &quot;eeprom&quot; or &quot;ram&quot;</source>
        <translation>storage 必须为 &quot;eeprom&quot; 或 &quot;ram&quot;</translation>
    </message>
    <message>
        <source>access must be &quot;ro&quot; or &quot;rw&quot;</source>
        <translation>access 必须为 &quot;ro&quot; 或 &quot;rw&quot;</translation>
    </message>
    <message>
        <source>the unit must be a string</source>
        <translation>单位必须是字符串</translation>
    </message>
    <message>
        <source>the scale must be a positive number</source>
        <translation>比例必须是正数</translation>
    </message>
    <message>
        <source>the sign bit must lie inside the register</source>
        <translation>符号位必须位于寄存器之内</translation>
    </message>
    <message>
        <source>min and max must be whole numbers</source>
        <translation>min 和 max 必须是整数</translation>
    </message>
    <message>
        <source>min is greater than max</source>
        <translation>min 大于 max</translation>
    </message>
    <message>
        <source>the range %1..%2 does not fit a %3-byte register</source>
        <translation>范围 %1..%2 超出了 %3 字节寄存器的容量</translation>
    </message>
    <message>
        <source>the default does not fit the register</source>
        <translation>默认值超出了寄存器的容量</translation>
    </message>
    <message>
        <source>a choice needs a value that fits the register and a label</source>
        <translation>选项需要一个寄存器能容纳的值和一个标签</translation>
    </message>
    <message>
        <source>a bit needs an index inside the register and a label</source>
        <translation>位需要一个位于寄存器之内的序号和一个标签</translation>
    </message>
    <message>
        <source>unknown family &quot;%1&quot;</source>
        <translation>未知系列 &quot;%1&quot;</translation>
    </message>
    <message>
        <source>byte_order must be &quot;little&quot; or &quot;big&quot;</source>
        <translation>byte_order 必须为 &quot;little&quot; 或 &quot;big&quot;</translation>
    </message>
    <message>
        <source>there are no registers</source>
        <translation>没有寄存器</translation>
    </message>
    <message>
        <source>every register must be a JSON object</source>
        <translation>每个寄存器都必须是 JSON 对象</translation>
    </message>
    <message>
        <source>the key &quot;%1&quot; is used twice</source>
        <translation>键名 &quot;%1&quot; 被使用了两次</translation>
    </message>
    <message>
        <source>registers &quot;%1&quot; and &quot;%2&quot; overlap at address %3</source>
        <translation>寄存器 &quot;%1&quot; 与 &quot;%2&quot; 在地址 %3 处重叠</translation>
    </message>
    <message>
        <source>families_by_major: &quot;%1&quot; is not a major number with a family</source>
        <translation>families_by_major：&quot;%1&quot; 不是带系列的主编号</translation>
    </message>
    <message>
        <source>model &quot;%1&quot;: needs a name and major and minor numbers 0-255</source>
        <translation>型号 &quot;%1&quot;：需要名称以及 0-255 的主编号和次编号</translation>
    </message>
    <message>
        <source>model &quot;%1&quot;: unknown family</source>
        <translation>型号 &quot;%1&quot;：未知系列</translation>
    </message>
    <message>
        <source>model %1/%2 is listed twice</source>
        <translation>型号 %1/%2 被列出了两次</translation>
    </message>
    <message>
        <source>%1 (model %2/%3)</source>
        <translation>%1（型号 %2/%3）</translation>
    </message>
    <message>
        <source>Unknown model %1/%2</source>
        <translation>未知型号 %1/%2</translation>
    </message>
    <message>
        <source>Raw bytes (unknown model)</source>
        <translation>原始字节（未知型号）</translation>
    </message>
    <message>
        <source>Byte %1</source>
        <translation>字节 %1</translation>
    </message>
    <message>
        <source>%1 Mbps</source>
        <translation>%1 Mbps</translation>
    </message>
    <message>
        <source>%L1 bps</source>
        <translation>%L1 bps</translation>
    </message>
    <message>
        <source>torque_enable_values: the table has no torque_enable</source>
        <translation>torque_enable_values：寄存器表中没有 torque_enable</translation>
    </message>
    <message>
        <source>torque_enable_values must be an object</source>
        <translation>torque_enable_values 必须是对象</translation>
    </message>
    <message>
        <source>torque_enable_values: unknown mode &quot;%1&quot;</source>
        <translation>torque_enable_values：未知模式 &quot;%1&quot;</translation>
    </message>
    <message>
        <source>torque_enable_values: &quot;%1&quot; is not one of torque_enable&apos;s choices</source>
        <translation>torque_enable_values：&quot;%1&quot; 不是 torque_enable 的选项之一</translation>
    </message>
    <message>
        <source>torque_enable_values: &quot;%1&quot; is missing</source>
        <translation>torque_enable_values：缺少 &quot;%1&quot;</translation>
    </message>
    <message>
        <source>feedback_block must give the address of present_position and a size that ends at the end of a register</source>
        <translation>feedback_block 必须给出 present_position 的地址，以及一个恰好在某寄存器末尾结束的大小</translation>
    </message>
    <message>
        <source>baud_rates: every rate must be a positive number, listed once</source>
        <translation>baud_rates：每个波特率都必须是正数，且只能列出一次</translation>
    </message>
    <message>
        <source>baud_rates must list the rates of codes 0 to 7</source>
        <translation>baud_rates 必须列出代码 0 到 7 的波特率</translation>
    </message>
</context>
<context>
    <name>RegisterTableModel</name>
    <message>
        <source>%1 to %2</source>
        <translation>%1 到 %2</translation>
    </message>
    <message>
        <source>On the servo: %1</source>
        <translation>舵机上：%1</translation>
    </message>
    <message>
        <source>EEPROM</source>
        <translation>EEPROM</translation>
    </message>
    <message>
        <source>RAM</source>
        <translation>RAM</translation>
    </message>
    <message>
        <source>RW</source>
        <translation>读写</translation>
    </message>
    <message>
        <source>RO</source>
        <translation>只读</translation>
    </message>
    <message>
        <source>—</source>
        <translation>—</translation>
    </message>
    <message>
        <source>Addr</source>
        <translation>地址</translation>
    </message>
    <message>
        <source>Key</source>
        <translation>键名</translation>
    </message>
    <message>
        <source>Register</source>
        <translation>寄存器</translation>
    </message>
    <message>
        <source>Size</source>
        <translation>大小</translation>
    </message>
    <message>
        <source>Area</source>
        <translation>区域</translation>
    </message>
    <message>
        <source>Access</source>
        <translation>权限</translation>
    </message>
    <message>
        <source>Raw</source>
        <translation>原始值</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>值</translation>
    </message>
    <message>
        <source>State</source>
        <translation>状态</translation>
    </message>
    <message>
        <source>, in steps of %1</source>
        <translation>，步长 %1</translation>
    </message>
    <message>
        <source>%1, snapped</source>
        <comment>state of a register whose typed value was put on a step</comment>
        <translation>%1，已按步长取整</translation>
    </message>
</context>
<context>
    <name>ReplaceMotorWizard</name>
    <message>
        <source>Replace a motor</source>
        <translation>更换舵机</translation>
    </message>
    <message>
        <source>The Feetech port is closed: open it again to go on.</source>
        <translation>Feetech 端口已关闭：请重新打开以继续。</translation>
    </message>
    <message>
        <source>A new servo takes the place of one joint of an arm set up and calibrated before. ServoBench sets it up as that joint (its ID, the robot&apos;s baud rate and the joint&apos;s settings, each read back), then calibrates that joint alone and updates the arm&apos;s LeRobot calibration file with it: the file&apos;s other joints stay as they are.</source>
        <translation>新舵机将替换一条此前已设置并校准过的机械臂上的某个关节。ServoBench 会将其设置为该关节（其 ID、机器人的波特率和该关节的设置，每项都会回读），然后只校准该关节，并用结果更新机械臂的 LeRobot 校准文件：文件中的其他关节保持不变。</translation>
    </message>
    <message>
        <source>Robot:</source>
        <translation>机器人：</translation>
    </message>
    <message>
        <source>Joint replaced:</source>
        <translation>更换的关节：</translation>
    </message>
    <message>
        <source>The arm&apos;s LeRobot calibration file</source>
        <translation>机械臂的 LeRobot 校准文件</translation>
    </message>
    <message>
        <source>&amp;Browse…</source>
        <translation>浏览(&amp;B)…</translation>
    </message>
    <message>
        <source>Choose the arm&apos;s LeRobot calibration file</source>
        <translation>选择机械臂的 LeRobot 校准文件</translation>
    </message>
    <message>
        <source>Calibration file:</source>
        <translation>校准文件：</translation>
    </message>
    <message>
        <source>&amp;Next</source>
        <translation>下一步(&amp;N)</translation>
    </message>
    <message>
        <source>Check that the file has the joint, then set up the new servo</source>
        <translation>检查文件中是否有该关节，然后设置新舵机</translation>
    </message>
    <message>
        <source>&amp;Back</source>
        <translation>上一步(&amp;B)</translation>
    </message>
    <message>
        <source>Choose another joint or file</source>
        <translation>选择其他关节或文件</translation>
    </message>
    <message>
        <source>&amp;Find</source>
        <translation>查找(&amp;F)</translation>
    </message>
    <message>
        <source>Look for the one servo on the bus, at every ID and baud rate; nothing is written</source>
        <translation>在所有 ID 和波特率下查找总线上唯一的舵机；不写入任何内容</translation>
    </message>
    <message>
        <source>&amp;Set up</source>
        <translation>设置(&amp;S)</translation>
    </message>
    <message>
        <source>Give the servo found the joint&apos;s ID, the robot&apos;s baud rate and the joint&apos;s settings, each read back</source>
        <translation>为找到的舵机设置该关节的 ID、机器人的波特率和该关节的设置，每项都会回读</translation>
    </message>
    <message>
        <source>S&amp;can the arm</source>
        <translation>扫描机械臂(&amp;C)</translation>
    </message>
    <message>
        <source>Look for the arm&apos;s servos at the robot&apos;s baud rate; nothing is written</source>
        <translation>以机器人的波特率查找机械臂的舵机；不写入任何内容</translation>
    </message>
    <message>
        <source>&amp;Calibrate the joint…</source>
        <translation>校准关节(&amp;C)…</translation>
    </message>
    <message>
        <source>Record the new servo&apos;s range by hand and update the calibration file</source>
        <translation>手动记录新舵机的范围，并更新校准文件</translation>
    </message>
    <message>
        <source>%1 (ID %2)</source>
        <translation>%1 (ID %2)</translation>
    </message>
    <message>
        <source>The arm&apos;s LeRobot calibration</source>
        <translation>机械臂的 LeRobot 校准文件</translation>
    </message>
    <message>
        <source>LeRobot calibration (*.json)</source>
        <translation>LeRobot 校准文件 (*.json)</translation>
    </message>
    <message>
        <source>Open the Feetech port the new servo is connected to first.</source>
        <translation>请先打开连接新舵机的 Feetech 端口。</translation>
    </message>
    <message>
        <source>Choose the robot and the joint whose motor is replaced.</source>
        <translation>请选择机器人以及要更换舵机的关节。</translation>
    </message>
    <message>
        <source>Choose the arm&apos;s LeRobot calibration file: the new joint&apos;s calibration goes into it.</source>
        <translation>请选择机械臂的 LeRobot 校准文件：新关节的校准将写入其中。</translation>
    </message>
    <message>
        <source>%1 has no joint with ID %2: choose the file of the arm whose %3 motor is replaced.</source>
        <translation>%1 中没有 ID 为 %2 的关节：请选择更换了 %3 舵机的那条机械臂的文件。</translation>
    </message>
    <message>
        <source>&lt;b&gt;Unplug every servo of the arm from the bus&lt;/b&gt; and connect only the new servo for &lt;b&gt;%1&lt;/b&gt;, then press &lt;i&gt;Find&lt;/i&gt;.&lt;br&gt;&lt;small&gt;Keep the power on. A new servo answers at ID 1 and 1 Mbps; ServoBench finds it at any ID and rate and gives it ID %2 and %3.&lt;/small&gt;</source>
        <translation>&lt;b&gt;从总线上拔下机械臂的所有舵机&lt;/b&gt;，只连接 &lt;b&gt;%1&lt;/b&gt; 的新舵机，然后点击&lt;i&gt;查找&lt;/i&gt;。&lt;br&gt;&lt;small&gt;请保持通电。新舵机在 ID 1、1 Mbps 下应答；ServoBench 能在任意 ID 和波特率下找到它，并将其设为 ID %2 和 %3。&lt;/small&gt;</translation>
    </message>
    <message>
        <source>Looking for the servo at every baud rate…</source>
        <translation>正在所有波特率下查找舵机…</translation>
    </message>
    <message>
        <source>Setting up the servo…</source>
        <translation>正在设置舵机…</translation>
    </message>
    <message>
        <source>Step %1 of %2: %3</source>
        <translation>第 %1 步，共 %2 步：%3</translation>
    </message>
    <message>
        <source>Nothing was written to any servo.</source>
        <translation>未向任何舵机写入内容。</translation>
    </message>
    <message>
        <source>Done before that:</source>
        <translation>此前已完成：</translation>
    </message>
    <message>
        <source>&lt;b&gt;Found one servo:&lt;/b&gt; servo %1 at %2, model %3. Press &lt;i&gt;Set up&lt;/i&gt; to make it the %4 joint.</source>
        <translation>&lt;b&gt;找到一个舵机：&lt;/b&gt;舵机 %1，位于 %2，型号 %3。点击&lt;i&gt;设置&lt;/i&gt;将其设为 %4 关节。</translation>
    </message>
    <message>
        <source>&lt;b&gt;Put the arm back together:&lt;/b&gt; connect every servo in its chain as before, keep the power on, and press &lt;i&gt;Scan the arm&lt;/i&gt;. The %1 joint is then calibrated alone into %2.</source>
        <translation>&lt;b&gt;重新组装机械臂：&lt;/b&gt;像之前一样将所有舵机串联，保持通电，然后点击&lt;i&gt;扫描机械臂&lt;/i&gt;。随后只校准 %1 关节，并将结果写入 %2。</translation>
    </message>
    <message>
        <source>&amp;Calibrate %1…</source>
        <translation>校准 %1(&amp;C)…</translation>
    </message>
    <message>
        <source>Looking for the arm&apos;s servos at %1…</source>
        <translation>正在以 %1 查找机械臂的舵机…</translation>
    </message>
    <message>
        <source>The new %1 servo does not answer at ID %2 and %3: check its cable and the power, then scan again.</source>
        <translation>新的 %1 舵机在 ID %2、%3 下无应答：请检查其电缆和电源，然后重新扫描。</translation>
    </message>
    <message numerus="yes">
        <source>%n servo(s) answer, the new one among them.</source>
        <translation>
            <numerusform>%n 个舵机有应答，其中包括新舵机。</numerusform>
        </translation>
    </message>
    <message>
        <source>The scan did not list servo %1: scan the arm again.</source>
        <translation>扫描结果中没有舵机 %1：请重新扫描机械臂。</translation>
    </message>
    <message>
        <source>Stopping after this step…</source>
        <translation>将在此步骤后停止…</translation>
    </message>
</context>
<context>
    <name>RequestEngine</name>
    <message>
        <source>stray input discarded before a request</source>
        <translation>请求前丢弃的杂散输入</translation>
    </message>
    <message>
        <source>received while no request was waiting</source>
        <translation>在没有等待中的请求时收到</translation>
    </message>
    <message>
        <source>came sooner than any answer to this request could: a late answer to an earlier one, discarded</source>
        <translation>到达时间早于本请求任何可能的应答：是对先前请求的迟到应答，已丢弃</translation>
    </message>
    <message>
        <source>unexpected frame, ignored</source>
        <translation>意外的帧，已忽略</translation>
    </message>
    <message>
        <source>garbled: answers at once</source>
        <translation>乱码：多个舵机同时应答</translation>
    </message>
    <message>
        <source>bad checksum</source>
        <translation>校验和错误</translation>
    </message>
    <message>
        <source>bytes that form no frame</source>
        <translation>无法构成帧的字节</translation>
    </message>
    <message numerus="yes">
        <source>%n answer(s) in time; the others are missing</source>
        <translation>
            <numerusform>%n 个应答按时到达；其余丢失</numerusform>
        </translation>
    </message>
    <message>
        <source>no reply (attempt %1 of %2)</source>
        <translation>无应答（第 %1 次尝试，共 %2 次）</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <comment>frame summary (note)</comment>
        <translation>%1（%2）</translation>
    </message>
    <message>
        <source>late answer, %1 ms after its request</source>
        <translation>迟到应答，在请求后 %1 ms 到达</translation>
    </message>
    <message>
        <source>late</source>
        <translation>迟到</translation>
    </message>
    <message>
        <source>late answer, discarded</source>
        <translation>迟到应答，已丢弃</translation>
    </message>
    <message>
        <source>heard while several may answer</source>
        <translation>在多个舵机可能同时应答时收到</translation>
    </message>
    <message>
        <source>%1: silence was expected, not counted as an error</source>
        <comment>no reply (attempt …)</comment>
        <translation>%1：预期无应答，不计为错误</translation>
    </message>
</context>
<context>
    <name>RobotActions</name>
    <message>
        <source>&amp;Identify the servo</source>
        <translation>识别舵机(&amp;I)</translation>
    </message>
    <message>
        <source>Apply &amp;profile to selected servos…</source>
        <translation>将配置文件应用到所选舵机(&amp;P)…</translation>
    </message>
    <message>
        <source>Apply &amp;template settings to selected servos…</source>
        <translation>将模板设置应用到所选舵机(&amp;T)…</translation>
    </message>
    <message>
        <source>&amp;Save as robot template…</source>
        <translation>另存为机器人模板(&amp;S)…</translation>
    </message>
    <message>
        <source>Connect to a Feetech bus first.</source>
        <translation>请先连接到 Feetech 总线。</translation>
    </message>
    <message>
        <source>The scan is still running.</source>
        <translation>扫描仍在进行。</translation>
    </message>
    <message>
        <source>Scan the bus first: no servos are known.</source>
        <translation>请先扫描总线：尚无已知舵机。</translation>
    </message>
    <message>
        <source>&amp;Identify servo ID %1</source>
        <translation>识别舵机 ID %1(&amp;I)</translation>
    </message>
    <message>
        <source>Move the servo a little each way, slowly and with little torque, then put it back as it was: you see which servo of the arm it is</source>
        <translation>缓慢地以小扭矩将舵机向两侧各转动一点，然后恢复原状：这样就能看出它是机械臂上的哪个舵机</translation>
    </message>
    <message>
        <source>Servos are being programmed.</source>
        <translation>正在编程舵机。</translation>
    </message>
    <message>
        <source>Another operation is still running.</source>
        <translation>另一项操作仍在进行。</translation>
    </message>
    <message>
        <source>Select servos in the tree first (Ctrl+click or Shift+click for several).</source>
        <translation>请先在树中选择舵机（按住 Ctrl 或 Shift 单击可选择多个）。</translation>
    </message>
    <message>
        <source>Write, verify and report each selected servo in turn</source>
        <translation>依次写入、验证并报告每个所选舵机</translation>
    </message>
    <message>
        <source>Describe this arm as a template the set-up wizards offer</source>
        <translation>将此机械臂描述为一个模板，供设置向导使用</translation>
    </message>
    <message>
        <source>Identifying servo ID %1: watch which horn moves…</source>
        <translation>正在识别舵机 ID %1：请观察哪个舵盘在动…</translation>
    </message>
    <message>
        <source>Programming servos</source>
        <translation>正在编程舵机</translation>
    </message>
    <message>
        <source>Starting…</source>
        <translation>正在开始…</translation>
    </message>
    <message>
        <source>Programming %1: some servos failed; see the result table.</source>
        <translation>编程 %1：部分舵机失败；请查看结果表。</translation>
    </message>
    <message>
        <source>Programming %1: done.</source>
        <translation>编程 %1：完成。</translation>
    </message>
    <message>
        <source>Apply template settings</source>
        <translation>应用模板设置</translation>
    </message>
    <message>
        <source>Each selected servo gets the settings of the template&apos;s joint with its ID:</source>
        <translation>每个所选舵机将获得模板中与其 ID 相同的关节的设置：</translation>
    </message>
    <message>
        <source>Robot template saved to %1</source>
        <translation>机器人模板已保存到 %1</translation>
    </message>
    <message>
        <source>servo ID %1</source>
        <translation>舵机 ID %1</translation>
    </message>
</context>
<context>
    <name>RobotTemplate</name>
    <message>
        <source>&quot;%1&quot; must be an object of register values</source>
        <translation>&quot;%1&quot; 必须是由寄存器值组成的对象</translation>
    </message>
    <message>
        <source>settings: &quot;%1&quot; is no writable register of %2 servos</source>
        <translation>settings：&quot;%1&quot; 不是 %2 舵机的可写寄存器</translation>
    </message>
    <message>
        <source>settings: &quot;%1&quot; is set by its own flow, not by a template</source>
        <translation>settings：&quot;%1&quot; 由其专门的流程设置，不能通过模板设置</translation>
    </message>
    <message>
        <source>settings: &quot;%1&quot; must be a whole number</source>
        <translation>settings：&quot;%1&quot; 必须是整数</translation>
    </message>
    <message>
        <source>settings: &quot;%1&quot; = %2 is out of range (%3 to %4)</source>
        <translation>settings：&quot;%1&quot; = %2 超出范围（%3 到 %4）</translation>
    </message>
    <message>
        <source>every joint must be a JSON object</source>
        <translation>每个关节都必须是 JSON 对象</translation>
    </message>
    <message>
        <source>unknown entry &quot;%1&quot;</source>
        <translation>未知条目 &quot;%1&quot;</translation>
    </message>
    <message>
        <source>&quot;%1&quot; must be a name of letters, digits and _ that starts with a letter</source>
        <translation>&quot;%1&quot; 必须是由字母、数字和 _ 组成且以字母开头的名称</translation>
    </message>
    <message>
        <source>&quot;%1&quot; must be a servo ID from 0 to %2</source>
        <translation>&quot;%1&quot; 必须是 0 到 %2 之间的舵机 ID</translation>
    </message>
    <message>
        <source>&quot;%1&quot;: &quot;%2&quot; is no model with a known register table</source>
        <translation>&quot;%1&quot;：&quot;%2&quot; 不是具有已知寄存器表的型号</translation>
    </message>
    <message>
        <source>&quot;%1&quot; must be true or false</source>
        <translation>&quot;%1&quot; 必须为 true 或 false</translation>
    </message>
    <message>
        <source>&quot;%1&quot; must be a name for the robot</source>
        <translation>&quot;%1&quot; 必须是机器人的名称</translation>
    </message>
    <message>
        <source>&quot;%1&quot; must be a Feetech baud rate in bps</source>
        <translation>&quot;%1&quot; 必须是以 bps 为单位的 Feetech 波特率</translation>
    </message>
    <message>
        <source>&quot;%1&quot; must list the robot&apos;s joints</source>
        <translation>&quot;%1&quot; 必须列出机器人的关节</translation>
    </message>
    <message>
        <source>joint %1</source>
        <translation>关节 %1</translation>
    </message>
    <message>
        <source>joint %1: the name &quot;%2&quot; is used twice</source>
        <translation>关节 %1：名称 &quot;%2&quot; 被使用了两次</translation>
    </message>
    <message>
        <source>joint %1 (%2): ID %3 is already %4&apos;s</source>
        <translation>关节 %1（%2）：ID %3 已被 %4 使用</translation>
    </message>
    <message>
        <source>the file is too large for a robot template</source>
        <translation>文件太大，不可能是机器人模板</translation>
    </message>
    <message>
        <source>SO-100 follower arm</source>
        <translation>SO-100 从臂</translation>
    </message>
    <message>
        <source>SO-100 leader arm</source>
        <translation>SO-100 主臂</translation>
    </message>
    <message>
        <source>SO-101 follower arm</source>
        <translation>SO-101 从臂</translation>
    </message>
    <message>
        <source>SO-101 leader arm</source>
        <translation>SO-101 主臂</translation>
    </message>
    <message>
        <source>not a ServoBench robot template (the document is not a JSON object)</source>
        <translation>不是 ServoBench 机器人模板（文档不是 JSON 对象）</translation>
    </message>
    <message>
        <source>not a ServoBench robot template (&quot;%1&quot; is not &quot;%2&quot;)</source>
        <translation>不是 ServoBench 机器人模板（&quot;%1&quot; 不是 &quot;%2&quot;）</translation>
    </message>
    <message>
        <source>the template has format version %1 and was written by a newer ServoBench; this version reads format version %2 and older</source>
        <translation>该模板的格式版本为 %1，由较新版本的 ServoBench 写入；本版本只能读取格式版本 %2 及更早版本</translation>
    </message>
    <message>
        <source>&quot;%1&quot; must be an object of bit numbers by register</source>
        <translation>&quot;%1&quot; 必须是以寄存器为键、以位编号为值的对象</translation>
    </message>
    <message>
        <source>%1: &quot;%2&quot; is no writable register of %3 servos</source>
        <translation>%1：&quot;%2&quot; 不是 %3 舵机的可写寄存器</translation>
    </message>
    <message>
        <source>%1: &quot;%2&quot; is set by its own flow, not by a template</source>
        <translation>%1：&quot;%2&quot; 由其专门的流程设置，不能通过模板设置</translation>
    </message>
    <message>
        <source>%1: &quot;%2&quot; must be a list of bit numbers</source>
        <translation>%1：&quot;%2&quot; 必须是位编号列表</translation>
    </message>
    <message>
        <source>%1: &quot;%2&quot; has bits 0 to %3</source>
        <translation>%1：&quot;%2&quot; 的位为 0 到 %3</translation>
    </message>
</context>
<context>
    <name>RobotTemplateDialog</name>
    <message>
        <source>Replace the template?</source>
        <translation>替换模板？</translation>
    </message>
    <message>
        <source>%1 exists already. Replace it?</source>
        <translation>%1 已存在。是否替换？</translation>
    </message>
    <message>
        <source>Save as robot template</source>
        <translation>另存为机器人模板</translation>
    </message>
    <message>
        <source>Template: %1</source>
        <translation>模板：%1</translation>
    </message>
    <message numerus="yes">
        <source>The %n servo(s) the scan found</source>
        <translation>
            <numerusform>扫描找到的 %n 个舵机</numerusform>
        </translation>
    </message>
    <message>
        <source>Joint name</source>
        <translation>关节名称</translation>
    </message>
    <message>
        <source>ID</source>
        <translation>ID</translation>
    </message>
    <message>
        <source>Model</source>
        <translation>型号</translation>
    </message>
    <message>
        <source>Full turn</source>
        <translation>整圈</translation>
    </message>
    <message>
        <source>Settings (register units)</source>
        <translation>设置（寄存器单位）</translation>
    </message>
    <message>
        <source>Registers set-up writes to this joint: key=value, separated by commas</source>
        <translation>设置时写入此关节的寄存器：key=value，以逗号分隔</translation>
    </message>
    <message>
        <source>Turns without end stops (a wrist roll): calibrated over 0-4095</source>
        <translation>无限位、可整圈旋转（如腕部旋转）：在 0-4095 范围内校准</translation>
    </message>
    <message>
        <source>Add joint</source>
        <translation>添加关节</translation>
    </message>
    <message>
        <source>Remove joint</source>
        <translation>移除关节</translation>
    </message>
    <message>
        <source>ID %1 (%2)</source>
        <translation>ID %1（%2）</translation>
    </message>
    <message>
        <source>Take settings from servo</source>
        <translation>从舵机获取设置</translation>
    </message>
    <message>
        <source>The selected joint&apos;s settings get the chosen servo&apos;s present values of the same registers</source>
        <translation>所选关节的设置将取为所选舵机上相同寄存器的当前值</translation>
    </message>
    <message>
        <source>Start from:</source>
        <translation>起始于：</translation>
    </message>
    <message>
        <source>Name:</source>
        <translation>名称：</translation>
    </message>
    <message>
        <source>Baud rate after set-up:</source>
        <translation>设置后的波特率：</translation>
    </message>
    <message>
        <source>Not offered (unreadable): %1</source>
        <translation>未提供（无法读取）：%1</translation>
    </message>
    <message>
        <source>My %1</source>
        <translation>我的 %1</translation>
    </message>
    <message>
        <source>My arm</source>
        <translation>我的机械臂</translation>
    </message>
    <message>
        <source>joint %1: the ID &quot;%2&quot; is not a number</source>
        <translation>关节 %1：ID &quot;%2&quot; 不是数字</translation>
    </message>
    <message>
        <source>joint %1: &quot;%2&quot; is not key=value (a register and a whole number)</source>
        <translation>关节 %1：&quot;%2&quot; 不是 key=value 格式（一个寄存器和一个整数）</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is the name of a built-in template: choose another, so the wizards can tell them apart</source>
        <translation>&quot;%1&quot; 是内置模板的名称：请另选一个，以便向导区分它们</translation>
    </message>
    <message>
        <source>Will be saved to %1, where the set-up wizards find it.</source>
        <translation>将保存到 %1，设置向导会在那里找到它。</translation>
    </message>
    <message>
        <source>The folder %1 cannot be created.</source>
        <translation>无法创建文件夹 %1。</translation>
    </message>
    <message>
        <source>Select a joint and a servo first.</source>
        <translation>请先选择一个关节和一个舵机。</translation>
    </message>
    <message>
        <source>The bus is busy: try again in a moment.</source>
        <translation>总线忙：请稍后再试。</translation>
    </message>
    <message>
        <source>Reading servo ID %1…</source>
        <translation>正在读取舵机 ID %1…</translation>
    </message>
    <message>
        <source>Fix the template first: %1</source>
        <translation>请先修正模板：%1</translation>
    </message>
    <message>
        <source>Joint %1 sets no registers yet: type their keys (key=value), then take their values from a servo.</source>
        <translation>关节 %1 尚未设置任何寄存器：请先输入寄存器键名（key=value），再从舵机获取其值。</translation>
    </message>
    <message>
        <source>The servo has no value for %1: kept as they were.</source>
        <translation>舵机没有 %1 的值：保持原样。</translation>
    </message>
</context>
<context>
    <name>ScanDialog</name>
    <message>
        <source>Scan the bus</source>
        <translation>扫描总线</translation>
    </message>
    <message>
        <source>Servo IDs</source>
        <translation>舵机 ID</translation>
    </message>
    <message>
        <source>From</source>
        <translation>从</translation>
    </message>
    <message>
        <source>to</source>
        <translation>到</translation>
    </message>
    <message>
        <source>Baud rates</source>
        <translation>波特率</translation>
    </message>
    <message>
        <source>%L1 bps</source>
        <translation>%L1 bps</translation>
    </message>
    <message>
        <source>All</source>
        <translation>全部</translation>
    </message>
    <message>
        <source>None</source>
        <translation>无</translation>
    </message>
    <message>
        <source>Skip baud rates where nothing answers a broadcast PING</source>
        <translation>跳过广播 PING 无人应答的波特率</translation>
    </message>
    <message>
        <source>Every servo answers a broadcast PING. When no byte at all comes back at a rate, no servo listens there and its IDs need not be asked one by one. Turn off to ask every ID regardless.</source>
        <translation>每个舵机都会应答广播 PING。如果在某个波特率下完全没有字节返回，说明没有舵机在该波特率下监听，无需逐个询问其 ID。关闭此项则无论如何都逐个询问每个 ID。</translation>
    </message>
    <message>
        <source>Scan</source>
        <translation>扫描</translation>
    </message>
    <message>
        <source>Choose at least one baud rate.</source>
        <translation>请至少选择一个波特率。</translation>
    </message>
    <message numerus="yes">
        <source>%n ID(s) at %1 baud rate(s). Missing IDs cost a few milliseconds each: the wait adapts to how fast the servos answer.</source>
        <translation>
            <numerusform>在 %1 个波特率下扫描 %n 个 ID。每个缺失的 ID 会耗费几毫秒：等待时间会根据舵机的应答速度自动调整。</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>SerialLink</name>
    <message>
        <source>%1 does not exist. Is the adapter plugged in?</source>
        <translation>%1 不存在。适配器是否已插入？</translation>
    </message>
    <message>
        <source>Permission denied on %1. Either another program has it open, or you are not in the group that may use serial ports: run &quot;sudo usermod -aG dialout $USER&quot;, then log out and back in.</source>
        <translation>%1 权限被拒绝。可能是其他程序正在使用它，或者您不在允许使用串口的用户组中：请运行 &quot;sudo usermod -aG dialout $USER&quot;，然后注销并重新登录。</translation>
    </message>
    <message>
        <source>Permission denied on %1: another program may have it open.</source>
        <translation>%1 权限被拒绝：可能有其他程序正在使用它。</translation>
    </message>
    <message>
        <source>%1 is already open.</source>
        <translation>%1 已经打开。</translation>
    </message>
    <message>
        <source>%1 is not open.</source>
        <translation>%1 未打开。</translation>
    </message>
    <message>
        <source>Could not write to %1 (%2).</source>
        <translation>无法写入 %1（%2）。</translation>
    </message>
    <message>
        <source>Could not read from %1 (%2).</source>
        <translation>无法从 %1 读取（%2）。</translation>
    </message>
    <message>
        <source>%1 went away: the adapter was unplugged or the device closed.</source>
        <translation>%1 已消失：适配器被拔出或设备已关闭。</translation>
    </message>
    <message>
        <source>%1 does not support this setting (%2).</source>
        <translation>%1 不支持此设置（%2）。</translation>
    </message>
    <message>
        <source>%1 timed out.</source>
        <translation>%1 超时。</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
</context>
<context>
    <name>ServoControlGroups</name>
    <message>
        <source>Torque</source>
        <translation>扭矩</translation>
    </message>
    <message>
        <source>Off</source>
        <translation>关</translation>
    </message>
    <message>
        <source>Torque off: the horn turns freely (torque enable 0).</source>
        <translation>扭矩关闭：舵盘可自由转动（扭矩开关 0）。</translation>
    </message>
    <message>
        <source>On</source>
        <translation>开</translation>
    </message>
    <message>
        <source>Torque on: the servo holds its goal position (torque enable 1).</source>
        <translation>扭矩开启：舵机保持其目标位置（扭矩开关 1）。</translation>
    </message>
    <message>
        <source>Damping</source>
        <translation>阻尼</translation>
    </message>
    <message>
        <source>Damping: the horn can be turned by hand against a resistance (torque enable 2).</source>
        <translation>阻尼：可以用手转动舵盘，但会感到阻力（扭矩开关 2）。</translation>
    </message>
    <message>
        <source>Operating mode</source>
        <translation>运行模式</translation>
    </message>
    <message>
        <source>How the servo uses its goal registers. Stored in EEPROM.</source>
        <translation>舵机如何使用其目标寄存器。保存在 EEPROM 中。</translation>
    </message>
    <message>
        <source>Set mode…</source>
        <translation>设置模式…</translation>
    </message>
    <message>
        <source>Write the chosen operating mode to the servo&apos;s EEPROM.</source>
        <translation>将所选的运行模式写入舵机的 EEPROM。</translation>
    </message>
    <message>
        <source>Goal position</source>
        <translation>目标位置</translation>
    </message>
    <message>
        <source>Drag to move the servo: goals are sent as fast as the servo confirms them, always the newest one.</source>
        <translation>拖动以移动舵机：目标会以舵机确认的最快速度发送，且总是发送最新的目标。</translation>
    </message>
    <message>
        <source>Move</source>
        <translation>移动</translation>
    </message>
    <message>
        <source>Send this goal position with the speed and acceleration below.</source>
        <translation>以下方的速度和加速度发送此目标位置。</translation>
    </message>
    <message>
        <source>Where the horn is: the monitor&apos;s newest sample, or the last read of the present position.</source>
        <translation>舵盘所在位置：监视的最新采样，或最后一次读取的当前位置。</translation>
    </message>
    <message>
        <source>Goal</source>
        <translation>目标</translation>
    </message>
    <message>
        <source>Present</source>
        <translation>当前</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>速度</translation>
    </message>
    <message>
        <source>Acceleration</source>
        <translation>加速度</translation>
    </message>
    <message>
        <source>Goal speed (0: the servo&apos;s maximum). The arrows move by one step of the register.</source>
        <translation>目标速度（0：舵机的最大值）。箭头每次按寄存器的一个步长调整。</translation>
    </message>
    <message>
        <source>Acceleration (0: the servo&apos;s maximum). The arrows move by one step of the register.</source>
        <translation>加速度（0：舵机的最大值）。箭头每次按寄存器的一个步长调整。</translation>
    </message>
</context>
<context>
    <name>ServoHealth</name>
    <message>
        <source>bit %1</source>
        <translation>位 %1</translation>
    </message>
    <message>
        <source>The servo reports a %1 error (status bit %2): its protection tripped.</source>
        <translation>舵机报告 %1 错误（状态位 %2）：其保护已触发。</translation>
    </message>
    <message>
        <source>The supply reads %1 V, above the servo&apos;s maximum of %2 V: use a supply the servo is made for.</source>
        <translation>电源电压为 %1 V，高于舵机的最大值 %2 V：请使用适合该舵机的电源。</translation>
    </message>
    <message>
        <source>The supply reads %1 V, below the servo&apos;s minimum of %2 V: charge the battery or check the supply and its wires.</source>
        <translation>电源电压为 %1 V，低于舵机的最小值 %2 V：请给电池充电，或检查电源及其接线。</translation>
    </message>
    <message>
        <source>The supply reads %1 V, close to the servo&apos;s maximum of %2 V.</source>
        <translation>电源电压为 %1 V，接近舵机的最大值 %2 V。</translation>
    </message>
    <message>
        <source>The supply reads %1 V, close to the servo&apos;s minimum of %2 V.</source>
        <translation>电源电压为 %1 V，接近舵机的最小值 %2 V。</translation>
    </message>
    <message>
        <source>The servo is at %1 °C, at or over its maximum of %2 °C: let it cool and look for what makes it work so hard.</source>
        <translation>舵机温度为 %1 °C，达到或超过其最高温度 %2 °C：请让它冷却，并查明是什么让它负荷如此之大。</translation>
    </message>
    <message>
        <source>The servo is at %1 °C, within %2 °C of its maximum of %3 °C.</source>
        <translation>舵机温度为 %1 °C，距其最高温度 %3 °C 不到 %2 °C。</translation>
    </message>
    <message numerus="yes">
        <source>None of %n feedback read(s) was answered: check the servo&apos;s cable and power.</source>
        <translation>
            <numerusform>%n 次反馈读取均无应答：请检查舵机的线缆和电源。</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%1 of %n feedback read(s) went unanswered even after retries (%2): check the cable, its connectors and the bus&apos;s length.</source>
        <translation>
            <numerusform>%n 次反馈读取中有 %1 次重试后仍无应答（%2）：请检查线缆、接头以及总线长度。</numerusform>
        </translation>
    </message>
    <message>
        <source>Every read was answered, but not at the first try (%1): the line is noisy or marginal.</source>
        <translation>每次读取都有应答，但并非都在第一次尝试时（%1）：线路有噪声或处于临界状态。</translation>
    </message>
    <message>
        <source>OK</source>
        <translation>正常</translation>
    </message>
    <message>
        <source>Warning</source>
        <translation>警告</translation>
    </message>
    <message>
        <source>Fault</source>
        <translation>故障</translation>
    </message>
    <message>
        <source>Its settings could not be read: %1</source>
        <translation>无法读取其设置：%1</translation>
    </message>
    <message>
        <source>ServoBench has no register table for model %1: only its answers are checked.</source>
        <translation>ServoBench 没有型号 %1 的寄存器表：只检查其应答。</translation>
    </message>
    <message>
        <source>The servo works at %1 % load while the check reads it, at or over its overload level of %2 %: something pushes against the horn.</source>
        <translation>检查读取时舵机负载为 %1 %，达到或超过其过载水平 %2 %：有东西在顶住舵盘。</translation>
    </message>
    <message>
        <source>The horn stands at %1, outside its angle limits %2 to %3: it cannot be sent back there, and the limits may be wrong.</source>
        <translation>舵盘位于 %1，超出其角度限制 %2 到 %3：无法将其送回该位置，且角度限制可能有误。</translation>
    </message>
    <message>
        <source>The move test did not complete: %1</source>
        <translation>运动测试未完成：%1</translation>
    </message>
    <message>
        <source>The horn did not follow a move of %1 steps from %2 to %3: it may be blocked, or its torque is limited.</source>
        <translation>舵盘未跟随从 %2 到 %3 的 %1 步运动：可能被卡住，或其扭矩受到限制。</translation>
    </message>
    <message>
        <source>The move overshot by %1 %: its gains may be too high.</source>
        <translation>运动超调 %1 %：其增益可能过高。</translation>
    </message>
    <message>
        <source>The horn stopped %1 steps from its goal: a load holds it off, or its dead zone is wide.</source>
        <translation>舵盘停在距目标 %1 步处：有负载阻挡了它，或其不灵敏区过宽。</translation>
    </message>
    <message>
        <source>servo %1 has %2</source>
        <translation>舵机 %1 为 %2</translation>
    </message>
    <message>
        <source>Its firmware %1 differs from other %2 servos on the bus (%3): they may behave differently with the same settings.</source>
        <translation>其固件 %1 与总线上其他 %2 舵机不同（%3）：相同设置下它们的表现可能不同。</translation>
    </message>
    <message>
        <source>%1/%2 answered, %3 retries, %4 timeouts, %5 checksum errors</source>
        <translation>%1/%2 次应答，%3 次重试，%4 次超时，%5 次校验和错误</translation>
    </message>
    <message>
        <source>not measured</source>
        <translation>未测量</translation>
    </message>
    <message>
        <source>none</source>
        <translation>无</translation>
    </message>
    <message>
        <source>%1 → %2: rise %3, overshoot %4, steady-state error %5</source>
        <translation>%1 → %2：上升时间 %3，超调 %4，稳态误差 %5</translation>
    </message>
    <message>
        <source>%1 s</source>
        <translation>%1 秒</translation>
    </message>
    <message>
        <source>%1 %</source>
        <translation>%1 %</translation>
    </message>
    <message>
        <source>%1 steps</source>
        <translation>%1 步</translation>
    </message>
</context>
<context>
    <name>ServoTree</name>
    <message>
        <source>Servo</source>
        <translation>舵机</translation>
    </message>
    <message>
        <source>Model</source>
        <translation>型号</translation>
    </message>
    <message>
        <source>Family</source>
        <translation>系列</translation>
    </message>
    <message>
        <source>Firmware</source>
        <translation>固件</translation>
    </message>
    <message>
        <source>Bus</source>
        <translation>总线</translation>
    </message>
    <message>
        <source>unknown</source>
        <translation>未知</translation>
    </message>
    <message>
        <source>ID %1 (shared!)</source>
        <translation>ID %1（共用！）</translation>
    </message>
    <message>
        <source>Two or more servos answer at ID %1: their replies come back garbled. Nothing is written to this ID while it is shared; connect them one at a time and give each its own ID.</source>
        <translation>有两个或更多舵机在 ID %1 应答：它们的应答是乱码。该 ID 被共用期间不会向其写入任何内容；请逐个连接，并为每个舵机分配各自的 ID。</translation>
    </message>
    <message>
        <source>It answers with error bits: %1 (the Doctor says why).</source>
        <translation>它的应答带有错误位：%1（诊断会说明原因）。</translation>
    </message>
    <message>
        <source>Model number %1 (major %2, minor %3)</source>
        <translation>型号编号 %1（主 %2，次 %3）</translation>
    </message>
    <message>
        <source>No register table is known for this model: its memory is shown as raw bytes, read-only.</source>
        <translation>此型号没有已知的寄存器表：其内存以原始字节只读显示。</translation>
    </message>
    <message>
        <source>The servos are the joints of the %1</source>
        <translation>这些舵机是 %1 的关节</translation>
    </message>
</context>
<context>
    <name>SettingsCheck</name>
    <message>
        <source>not written: torque is on, and writing %1 could move the horn; switch the torque off first</source>
        <translation>未写入：扭矩已开启，写入 %1 可能使舵盘移动；请先关闭扭矩</translation>
    </message>
    <message>
        <source>written, but it reads back %1, not %2</source>
        <translation>已写入，但回读为 %1，而不是 %2</translation>
    </message>
    <message>
        <source>not verified: %1</source>
        <translation>未验证：%1</translation>
    </message>
    <message>
        <source>ServoBench has no register table for model %1.</source>
        <translation>ServoBench 没有型号 %1 的寄存器表。</translation>
    </message>
    <message>
        <source>nothing to write fixes this</source>
        <translation>无法通过写入修复</translation>
    </message>
    <message>
        <source>not written: servo %1 does not answer (%2); check its cable and power</source>
        <translation>未写入：舵机 %1 无应答（%2）；请检查其线缆和电源</translation>
    </message>
    <message>
        <source>%1 is %2; %3 sets %4 (a RAM register: it is lost at power-off and set again at every connect).</source>
        <translation>%1 为 %2；%3 将其设为 %4（RAM 寄存器：断电后丢失，每次连接时重新设置）。</translation>
    </message>
    <message>
        <source>%1 is %2; %3 sets %4.</source>
        <translation>%1 为 %2；%3 将其设为 %4。</translation>
    </message>
    <message>
        <source>%1 is %2 with bits 0x%3 set; %4 clears them.</source>
        <translation>%1 为 %2，位 0x%3 已置位；%4 会将其清除。</translation>
    </message>
    <message>
        <source>Phase bit 4 is set: the servo counts whole turns, so its position leaves 0-4095 and goals and calibration no longer match it.</source>
        <translation>相位第 4 位已置位：舵机会累计整圈数，因此其位置会超出 0-4095，目标和校准都不再与之相符。</translation>
    </message>
    <message>
        <source>The torque limit is 0: the servo has no force to move with.</source>
        <translation>扭矩限制为 0：舵机没有可用于运动的力量。</translation>
    </message>
    <message>
        <source>The maximum torque is 0: at every power-on the torque limit starts at 0, and the servo does not move.</source>
        <translation>最大扭矩为 0：每次上电时扭矩限制都从 0 开始，舵机不会运动。</translation>
    </message>
    <message>
        <source>The operating mode is %1, not position (0): a joint does not follow its goal position.</source>
        <translation>运行模式为 %1，而不是位置模式（0）：关节不会跟随其目标位置。</translation>
    </message>
    <message>
        <source>Both angle limits are 0: the servo turns without end (multi-turn or wheel), not as a joint.</source>
        <translation>两个角度限制均为 0：舵机会无限转动（多圈或轮式），而不是作为关节工作。</translation>
    </message>
    <message>
        <source>The minimum angle limit %1 is not below the maximum %2: the servo refuses every goal.</source>
        <translation>最小角度限制 %1 不小于最大角度限制 %2：舵机会拒绝所有目标。</translation>
    </message>
    <message>
        <source>The servo waits %1 µs before each answer: every read of the bus is that much slower.</source>
        <translation>舵机每次应答前会等待 %1 µs：总线上的每次读取都会因此变慢。</translation>
    </message>
    <message>
        <source>The EEPROM is unlocked: a stray write would change settings for good.</source>
        <translation>EEPROM 未上锁：一次误写就会永久更改设置。</translation>
    </message>
    <message>
        <source>The supply reads %1 V, above the maximum voltage setting of %2 V: the servo reports a voltage error and may not move. Use a supply it is made for, or raise the limit if it is a higher-voltage model.</source>
        <translation>电源电压为 %1 V，高于最高电压设置 %2 V：舵机会报告电压错误，可能无法运动。请使用适合它的电源；如果它是更高电压的型号，则提高该限制。</translation>
    </message>
    <message>
        <source>The supply reads %1 V, below the minimum voltage setting of %2 V: the servo reports a voltage error and may not move. Charge the battery or check the supply.</source>
        <translation>电源电压为 %1 V，低于最低电压设置 %2 V：舵机会报告电压错误，可能无法运动。请给电池充电或检查电源。</translation>
    </message>
    <message>
        <source>Its settings could not be read: %1</source>
        <translation>无法读取其设置：%1</translation>
    </message>
    <message>
        <source>fixed, verified</source>
        <translation>已修复，已验证</translation>
    </message>
</context>
<context>
    <name>SettingsCheckPanel</name>
    <message>
        <source>Finds the settings that stop a servo moving or make it misbehave: multi-turn phase bit, torque limits at 0, a mode other than position, angle limits, a slow return delay, an unlocked EEPROM, mixed firmware, voltage limits the supply breaks, and what differs from the robot template. It only reads; Fix writes the expected value and reads it back (limits, offset, mode, torque limit and phase only with torque off).</source>
        <translation>查找会让舵机无法运动或行为异常的设置：多圈相位位、为 0 的扭矩限制、位置模式以外的运行模式、角度限制、过慢的返回延时、未上锁的 EEPROM、不一致的固件、电源不满足的电压限制，以及与机器人模板不同之处。该检查只读取；“修复”会写入预期值并回读（限制、偏移、模式、扭矩限制和相位仅在扭矩关闭时写入）。</translation>
    </message>
    <message>
        <source>Also compare the servos with this robot template&apos;s settings</source>
        <translation>同时将舵机与此机器人模板的设置进行比较</translation>
    </message>
    <message>
        <source>No robot template</source>
        <translation>无机器人模板</translation>
    </message>
    <message>
        <source>Check settings</source>
        <translation>检查设置</translation>
    </message>
    <message>
        <source>Read the settings of every servo found</source>
        <translation>读取找到的每个舵机的设置</translation>
    </message>
    <message>
        <source>Fix all</source>
        <translation>全部修复</translation>
    </message>
    <message>
        <source>Write the expected value of every finding that a write fixes, each read back</source>
        <translation>为每个可通过写入修复的问题写入预期值，并逐一回读</translation>
    </message>
    <message>
        <source>Robot:</source>
        <translation>机器人：</translation>
    </message>
    <message>
        <source>ID</source>
        <translation>ID</translation>
    </message>
    <message>
        <source>Setting</source>
        <translation>设置项</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>值</translation>
    </message>
    <message>
        <source>Expected</source>
        <translation>预期值</translation>
    </message>
    <message>
        <source>Why</source>
        <translation>原因</translation>
    </message>
    <message>
        <source>Fix</source>
        <translation>修复</translation>
    </message>
    <message>
        <source>Result</source>
        <translation>结果</translation>
    </message>
    <message>
        <source>No problem found in the settings.</source>
        <translation>设置中未发现问题。</translation>
    </message>
    <message numerus="yes">
        <source>%n finding(s).</source>
        <translation>
            <numerusform>发现 %n 个问题。</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Reading the settings of %n servo(s)…</source>
        <translation>
            <numerusform>正在读取 %n 个舵机的设置…</numerusform>
        </translation>
    </message>
    <message>
        <source>There is no finding in row %1.</source>
        <translation>第 %1 行没有问题。</translation>
    </message>
    <message>
        <source>Writing and reading back…</source>
        <translation>正在写入并回读…</translation>
    </message>
    <message>
        <source>Nothing to write fixes this</source>
        <translation>无法通过写入修复</translation>
    </message>
    <message>
        <source>Write %1 = %2 to servo %3 and read it back</source>
        <translation>将 %1 = %2 写入舵机 %3 并回读</translation>
    </message>
    <message>
        <source>Fixed, verified</source>
        <translation>已修复，已验证</translation>
    </message>
    <message>
        <source>%1 Check again to see the servos as they are now.</source>
        <translation>%1 请重新检查，以查看舵机的当前状态。</translation>
    </message>
</context>
<context>
    <name>SettingsFile</name>
    <message>
        <source>the file is too large for a profile or a robot template</source>
        <translation>文件太大，不可能是配置文件或机器人模板</translation>
    </message>
    <message>
        <source>servo %1 is of an unknown model (%2); nothing is written to it</source>
        <translation>舵机 %1 为未知型号（%2）；不向其写入任何内容</translation>
    </message>
    <message>
        <source>%1 has no joint with ID %2</source>
        <translation>%1 中没有 ID 为 %2 的关节</translation>
    </message>
    <message>
        <source>joint %1 of %2 is a %3, but servo %4 is a %5</source>
        <translation>%2 的关节 %1 是 %3，但舵机 %4 是 %5</translation>
    </message>
    <message>
        <source>%1 does not fit servo %2: %3</source>
        <translation>%1 不适用于舵机 %2：%3</translation>
    </message>
    <message>
        <source>Not copied from the profile: %1 (each servo&apos;s own calibration, not a setting to copy; use a robot template or Load calibration for it).</source>
        <translation>未从配置文件复制：%1（这是每个舵机各自的校准，不是可复制的设置；请使用机器人模板或“加载校准”）。</translation>
    </message>
    <message>
        <source>written and verified</source>
        <translation>已写入并验证</translation>
    </message>
    <message>
        <source>unchanged</source>
        <translation>未更改</translation>
    </message>
    <message>
        <source>failed</source>
        <translation>失败</translation>
    </message>
    <message>
        <source>torque is on: switch it off before changing the position offset, limits or phase</source>
        <translation>扭矩已开启：更改位置偏移、角度限制或相位前请先关闭扭矩</translation>
    </message>
</context>
<context>
    <name>SetupWizard</name>
    <message>
        <source>Set up motors</source>
        <translation>设置舵机</translation>
    </message>
    <message>
        <source>Robot:</source>
        <translation>机器人：</translation>
    </message>
    <message>
        <source>Check the bus</source>
        <translation>检查总线</translation>
    </message>
    <message>
        <source>Ask every joint&apos;s ID at the robot&apos;s rate: joints whose servo already answers there, as its model and with its settings, are done</source>
        <translation>以机器人的波特率询问每个关节的 ID：舵机已在该处应答、型号正确且设置一致的关节即视为完成</translation>
    </message>
    <message>
        <source>Joint</source>
        <translation>关节</translation>
    </message>
    <message>
        <source>ID</source>
        <translation>ID</translation>
    </message>
    <message>
        <source>Model</source>
        <translation>型号</translation>
    </message>
    <message>
        <source>Status</source>
        <translation>状态</translation>
    </message>
    <message>
        <source>&amp;Find</source>
        <translation>查找(&amp;F)</translation>
    </message>
    <message>
        <source>Look for the one servo on the bus, at every ID and baud rate; nothing is written</source>
        <translation>在所有 ID 和波特率下查找总线上唯一的舵机；不写入任何内容</translation>
    </message>
    <message>
        <source>&amp;Set up</source>
        <translation>设置(&amp;S)</translation>
    </message>
    <message>
        <source>Give the servo found the joint&apos;s ID, the robot&apos;s baud rate and the joint&apos;s settings, each read back</source>
        <translation>为找到的舵机设置该关节的 ID、机器人的波特率和该关节的设置，每项都会回读</translation>
    </message>
    <message>
        <source>S&amp;top</source>
        <translation>停止(&amp;T)</translation>
    </message>
    <message>
        <source>Stop before the next step; a step under way ends first, so the servo&apos;s EEPROM is always locked again</source>
        <translation>在下一步之前停止；正在进行的步骤会先完成，因此舵机的 EEPROM 总会重新上锁</translation>
    </message>
    <message>
        <source>Done</source>
        <translation>完成</translation>
    </message>
    <message>
        <source>Failed: %1</source>
        <translation>失败：%1</translation>
    </message>
    <message>
        <source>Current</source>
        <translation>当前</translation>
    </message>
    <message>
        <source>To do</source>
        <translation>待完成</translation>
    </message>
    <message>
        <source>Current, %1</source>
        <translation>当前，%1</translation>
    </message>
    <message>
        <source>Not connected</source>
        <translation>未连接</translation>
    </message>
    <message>
        <source>Open the Feetech port the servos are connected to first.</source>
        <translation>请先打开连接舵机的 Feetech 端口。</translation>
    </message>
    <message>
        <source>All done</source>
        <translation>全部完成</translation>
    </message>
    <message>
        <source>Every joint of the %1 is set up. Connect the servos in a chain and press &lt;i&gt;Check the bus&lt;/i&gt; to confirm them together.</source>
        <translation>%1 的所有关节均已设置。将舵机串联起来，然后点击&lt;i&gt;检查总线&lt;/i&gt;以一并确认。</translation>
    </message>
    <message>
        <source>Joint %1 of %2: %3</source>
        <translation>关节 %1/%2：%3</translation>
    </message>
    <message>
        <source>Connect only the &lt;b&gt;%1&lt;/b&gt; servo (ID will be %2) and press &lt;i&gt;Find&lt;/i&gt;.&lt;br&gt;&lt;small&gt;Unplug every other servo from the bus first and keep the power on. A new servo answers at ID 1 and 1 Mbps; ServoBench finds it at any ID and rate.&lt;/small&gt;</source>
        <translation>只连接 &lt;b&gt;%1&lt;/b&gt; 舵机（ID 将设为 %2），然后点击&lt;i&gt;查找&lt;/i&gt;。&lt;br&gt;&lt;small&gt;请先从总线上拔下其他所有舵机，并保持通电。新舵机在 ID 1、1 Mbps 下应答；ServoBench 能在任意 ID 和波特率下找到它。&lt;/small&gt;</translation>
    </message>
    <message>
        <source>servo %1 at %2, model %3, firmware %4</source>
        <translation>舵机 %1，位于 %2，型号 %3，固件 %4</translation>
    </message>
    <message>
        <source>Asking every joint&apos;s ID at %1…</source>
        <translation>正在以 %1 询问每个关节的 ID…</translation>
    </message>
    <message>
        <source>Looking for the servo at every baud rate…</source>
        <translation>正在所有波特率下查找舵机…</translation>
    </message>
    <message>
        <source>Stopping after this step…</source>
        <translation>将在此步骤后停止…</translation>
    </message>
    <message>
        <source>Step %1 of %2: %3</source>
        <translation>第 %1 步，共 %2 步：%3</translation>
    </message>
    <message>
        <source>Nothing was written to any servo.</source>
        <translation>未向任何舵机写入内容。</translation>
    </message>
    <message>
        <source>&lt;b&gt;Found one servo:&lt;/b&gt; %1.</source>
        <translation>&lt;b&gt;找到一个舵机：&lt;/b&gt;%1。</translation>
    </message>
    <message>
        <source>It answers where %1 should: it may be the %1 servo, already set up. Set it up as %2 only if it is the %2 servo.</source>
        <translation>它在 %1 应在的位置应答：它可能是已设置好的 %1 舵机。只有当它确实是 %2 舵机时，才将其设置为 %2。</translation>
    </message>
    <message numerus="yes">
        <source>Press &lt;i&gt;Set up&lt;/i&gt; to give it ID %2, %3 and the %1 settings (%n value(s), each read back).</source>
        <translation>
            <numerusform>点击&lt;i&gt;设置&lt;/i&gt;，为其设置 ID %2、%3 以及 %1 的设置（%n 个值，每个都会回读）。</numerusform>
        </translation>
    </message>
    <message>
        <source>Done before that:</source>
        <translation>此前已完成：</translation>
    </message>
    <message>
        <source>Unplug it and connect the next servo: &lt;b&gt;%1&lt;/b&gt;.</source>
        <translation>拔下它并连接下一个舵机：&lt;b&gt;%1&lt;/b&gt;。</translation>
    </message>
    <message>
        <source>Every joint is set up.</source>
        <translation>所有关节均已设置。</translation>
    </message>
    <message numerus="yes">
        <source>Checked the bus at %1: %2 of %n joint(s) set up.</source>
        <translation>
            <numerusform>已在 %1 下检查总线：%n 个关节中有 %2 个已设置。</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>ShareAlerts</name>
    <message>
        <source>Servo %1 reports overload: it stopped holding (torque off) until it is switched on again. Look for a blocked joint or a load too heavy for it.</source>
        <translation>舵机 %1 报告过载：在重新开启扭矩之前它已停止保持（扭矩关闭）。请检查关节是否被卡住，或负载是否过重。</translation>
    </message>
    <message>
        <source>Servo %1 answers with error bits set: %2.</source>
        <translation>舵机 %1 的应答带有错误位：%2。</translation>
    </message>
    <message>
        <source>Answers at ID %1 come garbled again and again: two servos may share this ID. Connect them one at a time and give each its own ID.</source>
        <translation>ID %1 的应答屡次出现乱码：可能有两个舵机共用此 ID。请逐个连接它们，并为每个舵机设置各自的 ID。</translation>
    </message>
    <message>
        <source>Servo %1 is at %2 °C, within %3 °C of its maximum (%4 °C): it will soon cut its torque. Let it cool, or lighten its load.</source>
        <translation>舵机 %1 温度为 %2 °C，距其最高温度（%4 °C）不到 %3 °C：它很快会切断扭矩。请让它冷却，或减轻负载。</translation>
    </message>
    <message>
        <source>Servo %1 measures %2 V, outside its limits %3-%4 V: check the supply.</source>
        <translation>舵机 %1 测得 %2 V，超出其限制 %3-%4 V：请检查电源。</translation>
    </message>
    <message>
        <source>The program set phase bit 4 of servo %1 (multi-turn): its positions will leave 0-4095 and a calibration made without it no longer fits.</source>
        <translation>该程序设置了舵机 %1 的相位第 4 位（多圈）：其位置将超出 0-4095，不含此设置的校准将不再适用。</translation>
    </message>
    <message>
        <source>The program switched torque on at servo %1 with its goal %2 steps from where it stands (%3 → %4): the horn jumps.</source>
        <translation>该程序在舵机 %1 的目标距当前位置 %2 步时开启了扭矩（%3 → %4）：舵盘会跳动。</translation>
    </message>
    <message>
        <source>The program unlocked the EEPROM of servo %1 and has not locked it again: a stray write now changes its settings for good.</source>
        <translation>该程序解锁了舵机 %1 的 EEPROM 且未重新锁定：此时一次误写就会永久改变其设置。</translation>
    </message>
</context>
<context>
    <name>ShareCommand</name>
    <message>
        <source>share takes no --%1</source>
        <translation>share 不接受 --%1</translation>
    </message>
    <message>
        <source>share takes no arguments besides its options</source>
        <translation>share 除选项外不接受参数</translation>
    </message>
    <message>
        <source>share needs --port: the adapter the servos are on</source>
        <translation>share 需要 --port：舵机所在的适配器</translation>
    </message>
    <message>
        <source>share needs --link PATH: the path the other program opens</source>
        <translation>share 需要 --link PATH：另一个程序要打开的路径</translation>
    </message>
    <message>
        <source>Sharing %1 at %2 baud: give the other program %3 (%4). Ctrl-C ends.</source>
        <translation>正在以 %2 波特率共享 %1：请把 %3（%4）交给另一个程序。按 Ctrl-C 结束。</translation>
    </message>
    <message>
        <source>alert %1 at ID %2: %3</source>
        <translation>警报 %1，ID %2：%3</translation>
    </message>
    <message>
        <source>Output: %1.</source>
        <translation>输出：%1。</translation>
    </message>
</context>
<context>
    <name>ShareDialog</name>
    <message>
        <source>Share this bus</source>
        <translation>共享此总线</translation>
    </message>
    <message>
        <source>ServoBench keeps the port and gives another program (LeRobot, a script) a port of its own: open the path below in it. Every byte passes both ways unchanged. Its traffic shows in the packet log, its servos in the servo tree, its reads of position, load, voltage and temperature in the Monitor, without a read of ServoBench&apos;s own. ServoBench&apos;s operations wait for the gaps between its transactions; a scan or a new baud rate waits until sharing stops; All torque off always goes.</source>
        <translation>ServoBench 保留该端口，并为另一个程序（LeRobot、脚本）提供专用端口：在该程序中打开下方的路径。每个字节都原样双向传递。其通信显示在数据包日志中，其舵机显示在舵机树中，其对位置、负载、电压和温度的读取显示在“监视”中，ServoBench 自身无需读取。ServoBench 的操作会等待该程序各事务之间的间隙；扫描或更改波特率须等到共享停止；“全部关闭扭矩”始终有效。</translation>
    </message>
    <message>
        <source>The path the other program opens as its serial port</source>
        <translation>另一个程序作为串口打开的路径</translation>
    </message>
    <message>
        <source>&amp;Copy path</source>
        <translation>复制路径(&amp;C)</translation>
    </message>
    <message>
        <source>No recording</source>
        <translation>不记录</translation>
    </message>
    <message>
        <source>Every frame with its time and direction; the packet log&apos;s Open recording… shows it</source>
        <translation>记录每一帧及其时间和方向；可用数据包日志中的“打开记录…”查看</translation>
    </message>
    <message>
        <source>C&amp;hoose…</source>
        <translation>选择(&amp;H)…</translation>
    </message>
    <message>
        <source>&amp;Watch: read the program&apos;s servos in its idle gaps</source>
        <translation>监视(&amp;W)：在该程序的空闲间隙读取其舵机</translation>
    </message>
    <message>
        <source>One READ at a time, only while the program leaves the bus quiet, so alerts also cover what the program does not read itself</source>
        <translation>每次一条 READ，仅在该程序让总线空闲时进行，使警报也能覆盖该程序自身未读取的内容</translation>
    </message>
    <message>
        <source>Path for the other program:</source>
        <translation>给另一个程序的路径：</translation>
    </message>
    <message>
        <source>Recording file:</source>
        <translation>记录文件：</translation>
    </message>
    <message>
        <source>Alerts:</source>
        <translation>警报：</translation>
    </message>
    <message>
        <source>Copied %1: paste it as the other program&apos;s port.</source>
        <translation>已复制 %1：请将其粘贴为另一个程序的端口。</translation>
    </message>
    <message>
        <source>Record the shared bus to</source>
        <translation>将共享总线记录到</translation>
    </message>
    <message>
        <source>Share recordings (*.txt);;All files (*)</source>
        <translation>共享记录 (*.txt);;所有文件 (*)</translation>
    </message>
    <message>
        <source>&amp;Start sharing</source>
        <translation>开始共享(&amp;S)</translation>
    </message>
    <message>
        <source>Not sharing.</source>
        <translation>未在共享。</translation>
    </message>
    <message>
        <source>Connect to a Feetech bus first.</source>
        <translation>请先连接到 Feetech 总线。</translation>
    </message>
    <message>
        <source>&amp;Stop sharing</source>
        <translation>停止共享(&amp;S)</translation>
    </message>
    <message>
        <source>Starting…</source>
        <translation>正在启动…</translation>
    </message>
    <message>
        <source>Sharing at %1 baud: give the other program %2 (the pseudo-terminal %3).</source>
        <translation>正在以 %1 波特率共享：请把 %2（伪终端 %3）交给另一个程序。</translation>
    </message>
    <message>
        <source>From the program: %1 frame(s). Back to it: %2 frame(s). Unanswered: %3. Garbled bytes: %4. Alerts: %5. Watch reads: %6.</source>
        <translation>来自该程序：%1 帧。返回给它：%2 帧。无应答：%3。乱码字节：%4。警报：%5。监视读取：%6。</translation>
    </message>
    <message>
        <source>%1  ID %2: %3</source>
        <translation>%1  ID %2：%3</translation>
    </message>
</context>
<context>
    <name>ShareLogEntries</name>
    <message>
        <source>Shared bus: %1</source>
        <translation>共享总线：%1</translation>
    </message>
    <message>
        <source>Not a whole frame (passed on to the other program)</source>
        <translation>不是完整的帧（已转交给另一个程序）</translation>
    </message>
    <message>
        <source>Not a whole frame</source>
        <translation>不是完整的帧</translation>
    </message>
    <message>
        <source>Other program: %1</source>
        <translation>另一个程序：%1</translation>
    </message>
    <message>
        <source>ServoBench (shared bus): %1</source>
        <translation>ServoBench（共享总线）：%1</translation>
    </message>
</context>
<context>
    <name>ShareRecording</name>
    <message>
        <source>it is larger than any recording (1 GiB)</source>
        <translation>它比任何记录都大（1 GiB）</translation>
    </message>
    <message>
        <source>line %1 is not &quot;&lt;seconds&gt; &lt;direction&gt; &lt;hex&gt;&quot;</source>
        <translation>第 %1 行不是 &quot;&lt;seconds&gt; &lt;direction&gt; &lt;hex&gt;&quot;</translation>
    </message>
    <message>
        <source>this is no ServoBench share recording</source>
        <translation>这不是 ServoBench 共享记录</translation>
    </message>
</context>
<context>
    <name>ShareRecordingWindow</name>
    <message>
        <source>Recording %1</source>
        <translation>记录 %1</translation>
    </message>
    <message numerus="yes">
        <source>%n frame(s) and note(s) from %1, in the order they passed; the time is seconds since sharing began.</source>
        <translation>
            <numerusform>来自 %1 的 %n 条帧和备注，按经过的顺序排列；时间为自共享开始以来的秒数。</numerusform>
        </translation>
    </message>
    <message>
        <source>Time (s)</source>
        <translation>时间（秒）</translation>
    </message>
    <message>
        <source>From</source>
        <translation>来源</translation>
    </message>
    <message>
        <source>Bytes</source>
        <translation>字节</translation>
    </message>
    <message>
        <source>Meaning</source>
        <translation>含义</translation>
    </message>
    <message>
        <source>Error</source>
        <translation>错误</translation>
    </message>
    <message>
        <source>program → bus</source>
        <translation>程序 → 总线</translation>
    </message>
    <message>
        <source>bus → program</source>
        <translation>总线 → 程序</translation>
    </message>
    <message>
        <source>ServoBench → bus</source>
        <translation>ServoBench → 总线</translation>
    </message>
    <message>
        <source>bus → ServoBench</source>
        <translation>总线 → ServoBench</translation>
    </message>
    <message>
        <source>note</source>
        <translation>备注</translation>
    </message>
</context>
<context>
    <name>SharedIdCheck</name>
    <message>
        <source>Two or more servos answer at ID %1 (their replies come back garbled): nothing is written to it while it is shared. Connect them one at a time and give each its own ID.</source>
        <translation>有两个或更多舵机在 ID %1 应答（它们的应答是乱码）：该 ID 被共用期间不会向其写入任何内容。请逐个连接，并为每个舵机分配各自的 ID。</translation>
    </message>
</context>
<context>
    <name>ShortcutsDialog</name>
    <message>
        <source>Keyboard shortcuts</source>
        <translation>键盘快捷键</translation>
    </message>
    <message>
        <source>Keys</source>
        <translation>按键</translation>
    </message>
    <message>
        <source>Command</source>
        <translation>命令</translation>
    </message>
</context>
<context>
    <name>SimLog</name>
    <message>
        <source>cannot write the log %1: %2</source>
        <translation>无法写入日志 %1：%2</translation>
    </message>
</context>
<context>
    <name>SimulatorData</name>
    <message>
        <source>must be an object</source>
        <translation>必须是对象</translation>
    </message>
    <message>
        <source>must be a whole number from %1 to %2</source>
        <translation>必须是 %1 到 %2 之间的整数</translation>
    </message>
    <message>
        <source>the document is not a JSON object</source>
        <translation>文档不是 JSON 对象</translation>
    </message>
    <message>
        <source>is not a field of this file</source>
        <translation>不是此文件的字段</translation>
    </message>
    <message>
        <source>must be %1</source>
        <translation>必须为 %1</translation>
    </message>
    <message>
        <source>is not a Feetech family (scs, sts, sms, hls)</source>
        <translation>不是 Feetech 系列（scs、sts、sms、hls）</translation>
    </message>
    <message>
        <source>is not a field of a family</source>
        <translation>不是系列的字段</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <source>%1: %2 %3</source>
        <translation>%1：%2 %3</translation>
    </message>
</context>
<context>
    <name>SimulatorDock</name>
    <message>
        <source>Simulator</source>
        <translation>模拟器</translation>
    </message>
    <message>
        <source>#</source>
        <translation>#</translation>
    </message>
    <message>
        <source>ID</source>
        <translation>ID</translation>
    </message>
    <message>
        <source>Rate</source>
        <translation>波特率</translation>
    </message>
    <message>
        <source>Model</source>
        <translation>型号</translation>
    </message>
    <message>
        <source>Position</source>
        <translation>位置</translation>
    </message>
    <message>
        <source>Torque</source>
        <translation>扭矩</translation>
    </message>
    <message>
        <source>Bench</source>
        <translation>台架</translation>
    </message>
    <message>
        <source>The servos on the simulated bus, as they are now</source>
        <translation>模拟总线上的舵机及其当前状态</translation>
    </message>
    <message>
        <source>Horn</source>
        <translation>舵盘</translation>
    </message>
    <message>
        <source>Sweep</source>
        <translation>扫动</translation>
    </message>
    <message>
        <source>Where the hand starts, and comes back to</source>
        <translation>手的起始位置，也是返回的位置</translation>
    </message>
    <message>
        <source>Where the hand turns back</source>
        <translation>手折返的位置</translation>
    </message>
    <message>
        <source> s</source>
        <translation> 秒</translation>
    </message>
    <message>
        <source>How long one sweep there and back takes</source>
        <translation>一次来回扫动所需的时间</translation>
    </message>
    <message>
        <source>until let go</source>
        <translation>直到松手</translation>
    </message>
    <message>
        <source>×</source>
        <translation>次</translation>
    </message>
    <message>
        <source>How many times; 0 sweeps until Let go</source>
        <translation>次数；0 表示一直扫动直到“松手”</translation>
    </message>
    <message>
        <source>to</source>
        <translation>到</translation>
    </message>
    <message>
        <source>The hand sweeps the selected joint from the first position to the second and back</source>
        <translation>手将所选关节从第一个位置扫动到第二个位置再返回</translation>
    </message>
    <message>
        <source>Let go</source>
        <translation>松手</translation>
    </message>
    <message>
        <source>The hand stops every sweep</source>
        <translation>手停止所有扫动</translation>
    </message>
    <message>
        <source>Plug in a factory-new servo…</source>
        <translation>插入全新出厂舵机…</translation>
    </message>
    <message>
        <source>Adds a servo as it comes from the factory: ID 1, its family&apos;s default rate</source>
        <translation>添加一个出厂状态的舵机：ID 1，其系列的默认波特率</translation>
    </message>
    <message>
        <source>Unplug</source>
        <translation>拔出</translation>
    </message>
    <message>
        <source>Takes the selected servo off the bus</source>
        <translation>将所选舵机从总线上移除</translation>
    </message>
    <message>
        <source>Put at ID…</source>
        <translation>设为 ID…</translation>
    </message>
    <message>
        <source>Changes the selected servo&apos;s ID in its EEPROM, as a set-up would; two servos may then share one</source>
        <translation>像设置流程那样更改所选舵机 EEPROM 中的 ID；之后两个舵机可能共用一个 ID</translation>
    </message>
    <message>
        <source>Power-cycle</source>
        <translation>断电重启</translation>
    </message>
    <message>
        <source>Switches the bus off and on: torque off, RAM back to its power-on values</source>
        <translation>将总线断电后重新上电：扭矩关闭，RAM 恢复为上电值</translation>
    </message>
    <message>
        <source>No simulated Feetech bus is running.</source>
        <translation>没有正在运行的模拟 Feetech 总线。</translation>
    </message>
    <message>
        <source>The simulator refused.</source>
        <translation>模拟器拒绝了操作。</translation>
    </message>
    <message>
        <source>Select a servo in the list first.</source>
        <translation>请先在列表中选择一个舵机。</translation>
    </message>
    <message>
        <source>on</source>
        <translation>开启</translation>
    </message>
    <message>
        <source>off, hand sweeping</source>
        <translation>关闭，手正在扫动</translation>
    </message>
    <message>
        <source>off</source>
        <translation>关闭</translation>
    </message>
    <message>
        <source>%1 V, %2 °C</source>
        <translation>%1 V，%2 °C</translation>
    </message>
    <message>
        <source>Select a servo to turn its horn by hand</source>
        <translation>选择一个舵机，用手转动其舵盘</translation>
    </message>
    <message>
        <source>Servo #%1 has its torque on: it holds its position against the hand. Switch its torque off to turn it.</source>
        <translation>舵机 #%1 的扭矩已开启：它会抵抗手的转动保持位置。请关闭其扭矩后再转动。</translation>
    </message>
    <message>
        <source>Turns servo #%1&apos;s horn by hand, as during a calibration</source>
        <translation>像校准时那样用手转动舵机 #%1 的舵盘</translation>
    </message>
    <message>
        <source>Turned servo #%1 to %2.</source>
        <translation>已将舵机 #%1 转到 %2。</translation>
    </message>
    <message>
        <source>The hand sweeps servo #%1 from %2 to %3 and back every %4 s.</source>
        <translation>手每 %4 秒将舵机 #%1 从 %2 扫动到 %3 再返回。</translation>
    </message>
    <message>
        <source>The hand let go.</source>
        <translation>手已松开。</translation>
    </message>
    <message>
        <source>Plugged in a factory-new %1 at ID 1.</source>
        <translation>已在 ID 1 插入一个全新出厂的 %1。</translation>
    </message>
    <message>
        <source>Unplugged servo #%1.</source>
        <translation>已拔出舵机 #%1。</translation>
    </message>
    <message>
        <source>Servo #%1 is now at ID %2.</source>
        <translation>舵机 #%1 现在的 ID 为 %2。</translation>
    </message>
    <message>
        <source>Power-cycled the simulated bus.</source>
        <translation>已将模拟总线断电重启。</translation>
    </message>
    <message>
        <source>Plug in a factory-new servo</source>
        <translation>插入全新出厂舵机</translation>
    </message>
    <message>
        <source>Model (it comes at ID 1, at its family&apos;s default rate):</source>
        <translation>型号（出厂 ID 为 1，使用其系列的默认波特率）：</translation>
    </message>
    <message>
        <source>Put at ID</source>
        <translation>设为 ID</translation>
    </message>
    <message>
        <source>New ID for servo #%1 (another servo may have it too):</source>
        <translation>舵机 #%1 的新 ID（其他舵机可能也使用该 ID）：</translation>
    </message>
    <message>
        <source>Bench case</source>
        <translation>台架情形</translation>
    </message>
    <message>
        <source>What goes wrong on a real bench, played on the selected servo or on the whole bus</source>
        <translation>真实台架上会出现的问题，在所选舵机或整条总线上重现</translation>
    </message>
    <message>
        <source>Play</source>
        <translation>执行</translation>
    </message>
    <message>
        <source>Plays the chosen bench case now</source>
        <translation>立即执行所选的台架情形</translation>
    </message>
    <message>
        <source>Plug back in</source>
        <translation>重新接回</translation>
    </message>
    <message>
        <source>Puts the servo unplugged last back on the bus, as it was</source>
        <translation>将最后拔下的舵机按原样接回总线</translation>
    </message>
    <message>
        <source>ID %1 (%2)</source>
        <translation>ID %1（%2）</translation>
    </message>
    <message>
        <source>Nothing was unplugged</source>
        <translation>没有拔下任何舵机</translation>
    </message>
    <message>
        <source>Puts %1, unplugged last, back on the bus as it was</source>
        <translation>将最后拔下的 %1 按原样接回总线</translation>
    </message>
    <message>
        <source>Plugged %1 back in.</source>
        <translation>已将 %1 接回。</translation>
    </message>
</context>
<context>
    <name>SkippableQuestion</name>
    <message>
        <source>Don&apos;t ask again</source>
        <translation>不再询问</translation>
    </message>
    <message>
        <source>View &gt; Ask skipped questions again brings it back</source>
        <translation>可通过“视图 &gt; 重新询问已跳过的问题”恢复</translation>
    </message>
</context>
<context>
    <name>TelemetryPlot</name>
    <message>
        <source>Drag across a time span to zoom in, right-click to zoom out, or turn the wheel; Reset zoom goes back to live data</source>
        <translation>在时间段上拖动以放大，右键单击以缩小，或滚动滚轮；“重置缩放”可返回实时数据</translation>
    </message>
    <message>
        <source>There is nothing to export: choose at least one quantity to plot.</source>
        <translation>没有可导出的内容：请至少选择一个要绘制的量。</translation>
    </message>
    <message>
        <source>No file name was given for the image.</source>
        <translation>未指定图像文件名。</translation>
    </message>
    <message>
        <source>The plot could not be drawn into an image (it has no size).</source>
        <translation>无法将曲线绘制为图像（尺寸为零）。</translation>
    </message>
    <message>
        <source>Could not save the plot to %1: %2.</source>
        <translation>无法将曲线保存到 %1：%2。</translation>
    </message>
</context>
<context>
    <name>TelemetryPlotPainter</name>
    <message>
        <source>ID %1</source>
        <translation>ID %1</translation>
    </message>
    <message>
        <source>ID %1 · %2</source>
        <translation>ID %1 · %2</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>Time (s)</source>
        <translation>时间（秒）</translation>
    </message>
</context>
<context>
    <name>TeleopDialog</name>
    <message>
        <source>Teleoperate</source>
        <translation>遥操作</translation>
    </message>
    <message>
        <source>Arms</source>
        <translation>机械臂</translation>
    </message>
    <message>
        <source>The leader arm&apos;s adapter: a second port, not the one the window has open</source>
        <translation>主臂的适配器：第二个端口，而不是本窗口已打开的端口</translation>
    </message>
    <message>
        <source>Re&amp;fresh</source>
        <translation>刷新(&amp;F)</translation>
    </message>
    <message>
        <source>List the serial ports again</source>
        <translation>重新列出串口</translation>
    </message>
    <message>
        <source>The arm on %1 (the window&apos;s bus)</source>
        <translation>%1 上的机械臂（本窗口的总线）</translation>
    </message>
    <message>
        <source>None: connect to the follower arm&apos;s bus first</source>
        <translation>无：请先连接到从臂的总线</translation>
    </message>
    <message>
        <source>A LeRobot calibration file (.json)</source>
        <translation>LeRobot 校准文件 (.json)</translation>
    </message>
    <message>
        <source>Browse…</source>
        <translation>浏览…</translation>
    </message>
    <message>
        <source>The follower&apos;s calibration file</source>
        <translation>从臂的校准文件</translation>
    </message>
    <message>
        <source>The leader&apos;s calibration file</source>
        <translation>主臂的校准文件</translation>
    </message>
    <message>
        <source> °/s</source>
        <translation> °/s</translation>
    </message>
    <message>
        <source>No joint of the follower moves faster, so it eases to the leader&apos;s pose at the start</source>
        <translation>从臂的任何关节都不会超过此速度，因此开始时它会平缓地移动到主臂的姿态</translation>
    </message>
    <message>
        <source> Hz</source>
        <translation> Hz</translation>
    </message>
    <message>
        <source>How often the leader is read; each reading is one write to the follower, as fast as the follower&apos;s bus takes them</source>
        <translation>读取主臂的频率；每次读取对应一次向从臂的写入，速度以从臂总线能承受的为限</translation>
    </message>
    <message>
        <source>Follower:</source>
        <translation>从臂：</translation>
    </message>
    <message>
        <source>Follower&apos;s calibration:</source>
        <translation>从臂校准：</translation>
    </message>
    <message>
        <source>Leader port:</source>
        <translation>主臂端口：</translation>
    </message>
    <message>
        <source>Leader&apos;s calibration:</source>
        <translation>主臂校准：</translation>
    </message>
    <message>
        <source>Maximum speed:</source>
        <translation>最大速度：</translation>
    </message>
    <message>
        <source>Rate:</source>
        <translation>频率：</translation>
    </message>
    <message>
        <source>&amp;Start</source>
        <translation>开始(&amp;S)</translation>
    </message>
    <message>
        <source>Check both arms against their files, hold the follower where it stands, then follow the leader</source>
        <translation>将两条机械臂与各自的文件核对，使从臂保持在当前位置，然后跟随主臂</translation>
    </message>
    <message>
        <source>S&amp;top</source>
        <translation>停止(&amp;T)</translation>
    </message>
    <message>
        <source>Stop following: the follower holds where it is</source>
        <translation>停止跟随：从臂保持在当前位置</translation>
    </message>
    <message>
        <source>Joints (LeRobot&apos;s units: −100…100, the gripper 0…100)</source>
        <translation>关节（LeRobot 单位：−100…100，夹爪 0…100）</translation>
    </message>
    <message>
        <source>Joint</source>
        <translation>关节</translation>
    </message>
    <message>
        <source>Leader</source>
        <translation>主臂</translation>
    </message>
    <message>
        <source>Follower&apos;s goal</source>
        <translation>从臂目标</translation>
    </message>
    <message>
        <source>The joints both files name show here once started.</source>
        <translation>启动后，这里会显示两个文件中都有的关节。</translation>
    </message>
    <message>
        <source>Loop: not running.</source>
        <translation>循环：未运行。</translation>
    </message>
    <message>
        <source>Simulated SO-101 leader arm</source>
        <translation>模拟 SO-101 主臂</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>LeRobot calibration files (*.json);;All files (*)</source>
        <translation>LeRobot 校准文件 (*.json);;所有文件 (*)</translation>
    </message>
    <message>
        <source>The simulated leader arm could not start: %1</source>
        <translation>模拟主臂无法启动：%1</translation>
    </message>
    <message>
        <source>—</source>
        <translation>—</translation>
    </message>
    <message>
        <source>Where the leader&apos;s %1 is</source>
        <translation>主臂 %1 的位置</translation>
    </message>
    <message>
        <source>The goal last sent to the follower&apos;s %1, within its speed limit</source>
        <translation>最后发送给从臂 %1 的目标，受其速度限制约束</translation>
    </message>
    <message>
        <source>Loop: waiting for the leader&apos;s first reading.</source>
        <translation>循环：正在等待主臂的首次读数。</translation>
    </message>
    <message numerus="yes">
        <source>Loop: %1 cycles a second; leader to follower %2 ms (median %3 ms); %n cycle(s) so far</source>
        <translation>
            <numerusform>循环：每秒 %1 个周期；主臂到从臂 %2 ms（中位数 %3 ms）；至今共 %n 个周期</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Loop: stopped after %n cycle(s); leader to follower %1 ms (median)</source>
        <translation>
            <numerusform>循环：%n 个周期后已停止；主臂到从臂 %1 ms（中位数）</numerusform>
        </translation>
    </message>
    <message>
        <source>Degrees from the middle (LeRobot&apos;s use_degrees, its default)</source>
        <translation>距中点的角度（LeRobot 的 use_degrees，其默认）</translation>
    </message>
    <message>
        <source>Range onto range, −100 to 100 (LeRobot&apos;s range_m100_100)</source>
        <translation>范围对范围，−100 到 100（LeRobot 的 range_m100_100）</translation>
    </message>
    <message>
        <source>How a leader&apos;s joint position becomes the follower&apos;s goal, as LeRobot&apos;s teleoperation does it: the same angle from the middle of each arm&apos;s range, or the same share of each range. The gripper is always share of range.</source>
        <translation>主臂的关节位置如何变成从臂的目标，与 LeRobot 的遥操作相同：距各臂范围中点的相同角度，或各范围中的相同比例。夹爪始终按范围比例。</translation>
    </message>
    <message>
        <source>Joints map:</source>
        <translation>关节映射：</translation>
    </message>
    <message>
        <source>The simulated leader&apos;s calibration file could not be made: %1</source>
        <translation>无法生成模拟主臂的校准文件：%1</translation>
    </message>
</context>
<context>
    <name>TeleopMapping</name>
    <message>
        <source>%1 (not in the leader&apos;s file)</source>
        <translation>%1（不在主臂的文件中）</translation>
    </message>
    <message>
        <source>%1 (not in the follower&apos;s file)</source>
        <translation>%1（不在从臂的文件中）</translation>
    </message>
</context>
<context>
    <name>UnlockedNotice</name>
    <message>
        <source>Lock EEPROM</source>
        <translation>锁定 EEPROM</translation>
    </message>
    <message>
        <source>Writes the lock register (1) and reads it back. Nothing else changes.</source>
        <translation>写入锁标志寄存器（1）并回读。不会更改其他任何内容。</translation>
    </message>
    <message>
        <source>Dismiss</source>
        <translation>忽略</translation>
    </message>
    <message>
        <source>Hides this note for this servo until the next connection; the lock stays open.</source>
        <translation>在下次连接之前不再为此舵机显示本提示；锁仍保持打开。</translation>
    </message>
    <message>
        <source>Note: servo %1&apos;s EEPROM is unlocked (lock = 0), as some programs (LeRobot among them) leave it: anything written to its settings now stays after a power cut. ServoBench locks it after each of its own writes; Lock EEPROM locks it now.</source>
        <translation>提示：舵机 %1 的 EEPROM 未上锁（lock = 0），一些程序（包括 LeRobot）会这样留下它：现在写入其设置的任何内容在断电后都会保留。ServoBench 在自己的每次写入后都会将其上锁；“锁定 EEPROM”可立即上锁。</translation>
    </message>
</context>
<context>
    <name>VirtualFeetechBus</name>
    <message>
        <source>a Feetech bus needs at least one servo</source>
        <translation>Feetech 总线至少需要一个舵机</translation>
    </message>
    <message>
        <source>servo %1: model %2 has no register table to simulate</source>
        <translation>舵机 %1：型号 %2 没有可供模拟的寄存器表</translation>
    </message>
    <message>
        <source>servo %1: unknown model &quot;%2&quot;</source>
        <translation>舵机 %1：未知型号 &quot;%2&quot;</translation>
    </message>
    <message>
        <source>servo ID %1 is out of range: IDs are 0 to %2</source>
        <translation>舵机 ID %1 超出范围：ID 为 0 到 %2</translation>
    </message>
    <message>
        <source>servo %1: %2 bps is not a Feetech baud rate (%3)</source>
        <translation>舵机 %1：%2 bps 不是 Feetech 波特率（%3）</translation>
    </message>
    <message>
        <source>two servos have ID %1 at %2 bps</source>
        <translation>有两个舵机在 %2 bps 下使用 ID %1</translation>
    </message>
    <message>
        <source>there is no servo #%1 on the bus (it has %2)</source>
        <translation>总线上没有舵机 #%1（总线上共有 %2 个）</translation>
    </message>
    <message>
        <source>no servo has ID %1</source>
        <translation>没有舵机使用 ID %1</translation>
    </message>
    <message>
        <source>servos %1 share ID %2: name one by its place, as #N</source>
        <translation>舵机 %1 共用 ID %2：请按位置指定其中一个，如 #N</translation>
    </message>
    <message>
        <source>cannot write the state file %1: %2</source>
        <translation>无法写入状态文件 %1：%2</translation>
    </message>
    <message>
        <source>larger than any state file (over 16 MB)</source>
        <translation>比任何状态文件都大（超过 16 MB）</translation>
    </message>
    <message>
        <source>state file %1: %2</source>
        <translation>状态文件 %1：%2</translation>
    </message>
    <message>
        <source>not valid JSON (%1)</source>
        <translation>不是有效的 JSON（%1）</translation>
    </message>
    <message>
        <source>not a format %1 simulator state</source>
        <translation>不是格式 %1 的模拟器状态</translation>
    </message>
    <message>
        <source>it holds %1 servos, the bus has %2</source>
        <translation>文件包含 %1 个舵机，而总线上有 %2 个</translation>
    </message>
    <message>
        <source>servo %1 is a %2 in the file but a %3 on the bus</source>
        <translation>舵机 %1 在文件中是 %2，而在总线上是 %3</translation>
    </message>
    <message>
        <source>servo %1: the EEPROM image is not %2 hex bytes</source>
        <translation>舵机 %1：EEPROM 映像不是 %2 个十六进制字节</translation>
    </message>
    <message>
        <source>servo %1: the EEPROM image is of model %2/%3, not %4</source>
        <translation>舵机 %1：EEPROM 映像属于型号 %2/%3，而不是 %4</translation>
    </message>
    <message>
        <source>servo %1: the EEPROM image holds an invalid ID or baud code</source>
        <translation>舵机 %1：EEPROM 映像包含无效的 ID 或波特率代码</translation>
    </message>
</context>
<context>
    <name>WelcomePanel</name>
    <message>
        <source>&lt;h2&gt;Connect your servos&lt;/h2&gt;</source>
        <translation>&lt;h2&gt;连接舵机&lt;/h2&gt;</translation>
    </message>
    <message>
        <source>Choose the serial port of your USB adapter and press &lt;b&gt;Connect&lt;/b&gt; (or double-click it), or try ServoBench on simulated servos. Nothing is sent to a servo until you connect.</source>
        <translation>选择 USB 适配器的串口并按&lt;b&gt;连接&lt;/b&gt;（或双击该串口），也可以先用模拟舵机试用 ServoBench。连接之前不会向任何舵机发送数据。</translation>
    </message>
    <message>
        <source>Serial ports</source>
        <translation>串口</translation>
    </message>
    <message>
        <source>Port</source>
        <translation>端口</translation>
    </message>
    <message>
        <source>Description</source>
        <translation>描述</translation>
    </message>
    <message>
        <source>Manufacturer</source>
        <translation>制造商</translation>
    </message>
    <message>
        <source>Serial number</source>
        <translation>序列号</translation>
    </message>
    <message>
        <source>USB ID</source>
        <translation>USB ID</translation>
    </message>
    <message>
        <source>Connect</source>
        <translation>连接</translation>
    </message>
    <message>
        <source>Simulated servos</source>
        <translation>模拟舵机</translation>
    </message>
    <message>
        <source>PTK servo</source>
        <translation>PTK 舵机</translation>
    </message>
    <message>
        <source>Feetech bus (five servos)</source>
        <translation>Feetech 总线（五个舵机）</translation>
    </message>
    <message>
        <source>SO-101 arm (six STS3215)</source>
        <translation>SO-101 机械臂（六个 STS3215）</translation>
    </message>
    <message>
        <source>Wiring</source>
        <translation>接线</translation>
    </message>
    <message>
        <source>&lt;b&gt;PTK RC servos&lt;/b&gt; (one signal wire, 115200 baud): a 3.3 V or 5 V USB-serial adapter with a 470 Ω resistor from TX to RX. The servo&apos;s signal wire goes to RX, its ground to the adapter&apos;s ground; power the servo from its own supply. The adapter hears its own bytes, and ServoBench expects that.</source>
        <translation>&lt;b&gt;PTK 模型舵机&lt;/b&gt;（单信号线，115200 波特率）：使用 3.3 V 或 5 V 的 USB 转串口适配器，并在 TX 与 RX 之间接一个 470 Ω 电阻。舵机的信号线接 RX，地线接适配器的地；舵机由独立电源供电。适配器会收到自己发出的字节（回显），ServoBench 会按此处理。</translation>
    </message>
    <message>
        <source>&lt;b&gt;Feetech serial-bus servos&lt;/b&gt;: Feetech&apos;s URT-1 / FE-URT board, or any half-duplex TTL adapter (SCS, STS, HLS) or RS485 adapter (SMS). Chain the servos with their 3-wire cables; power them from the board&apos;s supply (7.4 V or 12 V as the servos ask), never from USB. New servos all answer at ID 1 and 1 Mbps: set them up one at a time (Robot &gt; Set up motors).</source>
        <translation>&lt;b&gt;飞特串行总线舵机&lt;/b&gt;：使用飞特的 URT-1 / FE-URT 板，或任意半双工 TTL 适配器（SCS、STS、HLS）或 RS485 适配器（SMS）。用舵机的三线电缆将舵机串联；由板上的电源供电（按舵机要求 7.4 V 或 12 V），切勿用 USB 供电。新舵机的 ID 都是 1、波特率都是 1 Mbps：请逐个设置（机器人 &gt; 设置舵机）。</translation>
    </message>
    <message>
        <source>Nothing answers? Leave Protocol on &lt;b&gt;Auto&lt;/b&gt; and connect: ServoBench finds the family and rate, and the Doctor says what is wrong.</source>
        <translation>没有应答？将协议保持为&lt;b&gt;自动&lt;/b&gt;并连接：ServoBench 会找出舵机系列和波特率，诊断会指出问题所在。</translation>
    </message>
    <message>
        <source>No serial port found. Plug in the USB adapter: it shows up here by itself.</source>
        <translation>未找到串口。请插入 USB 适配器：它会自动出现在这里。</translation>
    </message>
    <message>
        <source>Choose a serial port first</source>
        <translation>请先选择串口</translation>
    </message>
</context>
<context>
    <name>feetech</name>
    <message>
        <source>voltage</source>
        <translation>电压</translation>
    </message>
    <message>
        <source>encoder</source>
        <translation>编码器</translation>
    </message>
    <message>
        <source>temperature</source>
        <translation>温度</translation>
    </message>
    <message>
        <source>current</source>
        <translation>电流</translation>
    </message>
    <message>
        <source>angle</source>
        <translation>角度</translation>
    </message>
    <message>
        <source>overload</source>
        <translation>过载</translation>
    </message>
    <message>
        <source>bit 6</source>
        <translation>位 6</translation>
    </message>
    <message>
        <source>bit 7</source>
        <translation>位 7</translation>
    </message>
</context>
<context>
    <name>feetech::BatchProgram</name>
    <message>
        <source>Servos are being programmed already.</source>
        <translation>舵机已在编程中。</translation>
    </message>
    <message>
        <source>The bus is not connected.</source>
        <translation>总线未连接。</translation>
    </message>
    <message>
        <source>Another operation is still running.</source>
        <translation>另一项操作仍在进行。</translation>
    </message>
    <message>
        <source>Select the servos to program first.</source>
        <translation>请先选择要编程的舵机。</translation>
    </message>
    <message>
        <source>Programming servo ID %1 (%2 of %3)…</source>
        <translation>正在编程舵机 ID %1（第 %2 个，共 %3 个）…</translation>
    </message>
    <message>
        <source>Servo ID %1 is no longer on the bus.</source>
        <translation>舵机 ID %1 已不在总线上。</translation>
    </message>
    <message>
        <source>Servo ID %1 has edits that are not applied: apply or revert them first.</source>
        <translation>舵机 ID %1 有尚未应用的修改：请先应用或撤销。</translation>
    </message>
    <message>
        <source>%1 is %2</source>
        <translation>%1 为 %2</translation>
    </message>
    <message>
        <source>not verified: %1</source>
        <translation>未验证：%1</translation>
    </message>
    <message>
        <source>The bus was disconnected.</source>
        <translation>总线已断开。</translation>
    </message>
</context>
<context>
    <name>feetech::MotionTest</name>
    <message>
        <source>All torque off: the test was stopped.</source>
        <translation>已关闭全部扭矩：测试已停止。</translation>
    </message>
    <message>
        <source>The test was stopped: %1</source>
        <translation>测试已停止：%1</translation>
    </message>
    <message>
        <source>%1 is no longer on the bus: the test was stopped.</source>
        <translation>%1 已不在总线上：测试已停止。</translation>
    </message>
    <message>
        <source>A motion test is running on servo ID %1.</source>
        <translation>舵机 ID %1 正在进行运动测试。</translation>
    </message>
    <message>
        <source>The test was stopped.</source>
        <translation>测试已停止。</translation>
    </message>
    <message>
        <source>Servo ID %1</source>
        <translation>舵机 ID %1</translation>
    </message>
    <message>
        <source>Moving to the start position %1…</source>
        <translation>正在移动到起始位置 %1…</translation>
    </message>
    <message>
        <source>Step to %1: recording for %2 s…</source>
        <translation>阶跃到 %1：记录 %2 秒…</translation>
    </message>
    <message>
        <source>Too few position samples arrived during the recording (%1): does %2 answer?</source>
        <translation>记录期间收到的位置采样太少（%1）：%2 是否在应答？</translation>
    </message>
    <message>
        <source>Step test done.</source>
        <translation>阶跃测试完成。</translation>
    </message>
    <message>
        <source>Sweep leg %1 of %2: moving to %3…</source>
        <translation>扫动第 %1 段，共 %2 段：正在移动到 %3…</translation>
    </message>
    <message>
        <source>Sweep done: %1 of %2 legs reached their goal.</source>
        <translation>扫动完成：%2 段中有 %1 段到达目标。</translation>
    </message>
    <message>
        <source>No position samples arrived from %1: is it answering?</source>
        <translation>没有收到来自 %1 的位置采样：它是否在应答？</translation>
    </message>
    <message>
        <source>%1 did not settle at %2 within %3 s; going on from %4.</source>
        <translation>%1 未能在 %3 秒内稳定在 %2；从 %4 继续。</translation>
    </message>
    <message>
        <source>Writing to %1 failed: %2</source>
        <translation>写入 %1 失败：%2</translation>
    </message>
    <message>
        <source>The bus was disconnected: the test was stopped.</source>
        <translation>总线已断开：测试已停止。</translation>
    </message>
</context>
<context>
    <name>feetech::TelemetryRecorder</name>
    <message>
        <source>No file name was given for the recording.</source>
        <translation>未指定记录文件名。</translation>
    </message>
    <message>
        <source>The telemetry output is not open for writing.</source>
        <translation>遥测输出未打开，无法写入。</translation>
    </message>
    <message>
        <source>The telemetry output cannot be written.</source>
        <translation>无法写入遥测输出。</translation>
    </message>
    <message numerus="yes">
        <source>%1; the %n row(s) written before it are kept whole in %2.</source>
        <translation>
            <numerusform>%1；此前写入的 %n 行已完整保存在 %2 中。</numerusform>
        </translation>
    </message>
    <message>
        <source>%1; the incomplete file %2 was removed.</source>
        <translation>%1；不完整的文件 %2 已删除。</translation>
    </message>
</context>
<context>
    <name>feetech::TeleopBus</name>
    <message>
        <source>The follower&apos;s bus is not open.</source>
        <translation>从臂的总线未打开。</translation>
    </message>
</context>
<context>
    <name>feetech::Teleoperation</name>
    <message>
        <source>Connect to the follower arm&apos;s bus first: it is the bus the window has open.</source>
        <translation>请先连接到从臂的总线：即本窗口打开的总线。</translation>
    </message>
    <message>
        <source>Choose the leader arm&apos;s port.</source>
        <translation>请选择主臂的端口。</translation>
    </message>
    <message>
        <source>The leader&apos;s port is the follower&apos;s: the leader and the follower are two arms on two adapters.</source>
        <translation>主臂的端口与从臂相同：主臂和从臂是接在两个适配器上的两条机械臂。</translation>
    </message>
    <message>
        <source>The two files name different joints: %1.</source>
        <translation>两个文件中的关节不一致：%1。</translation>
    </message>
    <message>
        <source>The follower&apos;s joint %1 (servo %2) is not on the bus the window has open: scan it, or choose the follower&apos;s file.</source>
        <translation>从臂的关节 %1（舵机 %2）不在本窗口打开的总线上：请扫描该总线，或选择从臂的文件。</translation>
    </message>
    <message>
        <source>Opening the leader&apos;s port…</source>
        <translation>正在打开主臂的端口…</translation>
    </message>
    <message>
        <source>Stopped before the follower moved.</source>
        <translation>已在从臂移动之前停止。</translation>
    </message>
    <message>
        <source>Checking the leader&apos;s joints…</source>
        <translation>正在检查主臂的关节…</translation>
    </message>
    <message>
        <source>The leader was lost: %1</source>
        <translation>主臂已失去连接：%1</translation>
    </message>
    <message>
        <source>The leader&apos;s port could not be opened: %1</source>
        <translation>无法打开主臂的端口：%1</translation>
    </message>
    <message>
        <source>The follower was lost: %1. It could not be told to hold.</source>
        <translation>从臂已失去连接：%1。无法令其保持位置。</translation>
    </message>
    <message>
        <source>Checking the follower&apos;s joints…</source>
        <translation>正在检查从臂的关节…</translation>
    </message>
    <message>
        <source>The leader&apos;s joint %1 (servo %2) does not answer: %3</source>
        <translation>主臂的关节 %1（舵机 %2）无应答：%3</translation>
    </message>
    <message>
        <source>its model is unknown</source>
        <translation>其型号未知</translation>
    </message>
    <message>
        <source>The follower holds where it stands…</source>
        <translation>从臂正保持在当前位置…</translation>
    </message>
    <message>
        <source>The follower&apos;s torque could not be switched on.</source>
        <translation>无法开启从臂的扭矩。</translation>
    </message>
    <message>
        <source>Servo %1 reports no position.</source>
        <translation>舵机 %1 未报告位置。</translation>
    </message>
    <message>
        <source>Following the leader.</source>
        <translation>正在跟随主臂。</translation>
    </message>
    <message>
        <source>The follower could not be told to hold.</source>
        <translation>无法令从臂保持位置。</translation>
    </message>
    <message>
        <source>Stopped: the follower holds where it is.</source>
        <translation>已停止：从臂保持在当前位置。</translation>
    </message>
    <message>
        <source>%1 The follower holds where it is.</source>
        <translation>%1 从臂保持在当前位置。</translation>
    </message>
    <message>
        <source>Choose the follower&apos;s LeRobot calibration file: the one saved when the follower arm was calibrated (Robot › Calibrate arm…).</source>
        <translation>请选择从臂的 LeRobot 校准文件：即校准从臂时保存的文件（机器人 › 校准机械臂…）。</translation>
    </message>
    <message>
        <source>Choose the leader&apos;s LeRobot calibration file: the one saved when the leader arm was calibrated.</source>
        <translation>请选择主臂的 LeRobot 校准文件：即校准主臂时保存的文件。</translation>
    </message>
    <message>
        <source>The leader&apos;s %1 (servo %2) does not hold what %3 says (%4). Nothing was written. Connect to the leader arm and write the file to it (Robot › Load calibration…), or choose the leader&apos;s own file.</source>
        <translation>主臂的 %1（舵机 %2）与 %3 中的值不符（%4）。未写入任何内容。请连接主臂并将该文件写入（机器人 › 加载校准…），或选择主臂自己的文件。</translation>
    </message>
    <message>
        <source>The follower&apos;s %1 (servo %2) does not hold what %3 says (%4). Nothing was written. Write the file to the follower (Robot › Load calibration…), or choose the follower&apos;s own file.</source>
        <translation>从臂的 %1（舵机 %2）与 %3 中的值不符（%4）。未写入任何内容。请将该文件写入从臂（机器人 › 加载校准…），或选择从臂自己的文件。</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <source>Programmer and live monitor for PTK and Feetech servos</source>
        <translation>PTK 和 Feetech 舵机的编程与实时监视工具</translation>
    </message>
    <message>
        <source>Start the simulated servos and connect to the PTK servo (the Feetech bus is in the port list).</source>
        <translation>启动模拟舵机并连接到 PTK 舵机（Feetech 总线在端口列表中）。</translation>
    </message>
    <message>
        <source>Start the simulated servos, connect to the Feetech bus and scan it.</source>
        <translation>启动模拟舵机，连接到 Feetech 总线并扫描。</translation>
    </message>
    <message>
        <source>Start a simulated SO-101 arm (six STS3215 at IDs 1-6, set up), connect to it and scan it; the Simulator dock turns its joints by hand.</source>
        <translation>启动一个模拟的 SO-101 机械臂（六个 STS3215，ID 1-6，已设置好），连接并扫描；“模拟器”面板可以用手转动其关节。</translation>
    </message>
    <message>
        <source>Connect to PORT at start.</source>
        <translation>启动时连接到 PORT。</translation>
    </message>
</context>
<context>
    <name>model::ParameterModel</name>
    <message>
        <source>unknown parameter &quot;%1&quot;</source>
        <translation>未知参数 &quot;%1&quot;</translation>
    </message>
    <message>
        <source>%1 is read-only</source>
        <translation>%1 为只读</translation>
    </message>
    <message>
        <source>%1 must be between %2 and %3</source>
        <translation>%1 必须介于 %2 和 %3 之间</translation>
    </message>
    <message>
        <source>Edited</source>
        <translation>已修改</translation>
    </message>
    <message>
        <source>Writing</source>
        <translation>正在写入</translation>
    </message>
    <message>
        <source>Verified</source>
        <translation>已验证</translation>
    </message>
    <message>
        <source>Mismatch</source>
        <translation>不一致</translation>
    </message>
    <message>
        <source>Failed</source>
        <translation>失败</translation>
    </message>
    <message>
        <source>Unknown</source>
        <translation>未知</translation>
    </message>
    <message>
        <source>%1: %2 to %3</source>
        <translation>%1：%2 到 %3</translation>
    </message>
    <message>
        <source>Key</source>
        <translation>键名</translation>
    </message>
    <message>
        <source>Parameter</source>
        <translation>参数</translation>
    </message>
    <message>
        <source>Device</source>
        <translation>设备</translation>
    </message>
    <message>
        <source>Edit</source>
        <translation>编辑</translation>
    </message>
    <message>
        <source>Unit</source>
        <translation>单位</translation>
    </message>
    <message>
        <source>State</source>
        <translation>状态</translation>
    </message>
</context>
<context>
    <name>ptk</name>
    <message>
        <source>Gain</source>
        <translation>增益</translation>
    </message>
    <message>
        <source>Damping</source>
        <translation>阻尼</translation>
    </message>
    <message>
        <source>Deadband</source>
        <translation>死区</translation>
    </message>
    <message>
        <source>Neutral</source>
        <translation>中位</translation>
    </message>
    <message>
        <source>Minimum angle</source>
        <translation>最小角度</translation>
    </message>
    <message>
        <source>Maximum angle</source>
        <translation>最大角度</translation>
    </message>
    <message>
        <source>Minimum pulse width</source>
        <translation>最小脉宽</translation>
    </message>
    <message>
        <source>Maximum pulse width</source>
        <translation>最大脉宽</translation>
    </message>
    <message>
        <source>Inversion</source>
        <translation>反向</translation>
    </message>
    <message>
        <source>Maximum power</source>
        <translation>最大功率</translation>
    </message>
    <message>
        <source>Overload protection power</source>
        <translation>过载保护功率</translation>
    </message>
    <message>
        <source>Overload protection time</source>
        <translation>过载保护时间</translation>
    </message>
    <message>
        <source>Soft start</source>
        <translation>软启动</translation>
    </message>
    <message>
        <source>Off</source>
        <translation>关闭</translation>
    </message>
    <message>
        <source>On</source>
        <translation>开启</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not NAME=VALUE</source>
        <translation>&quot;%1&quot; 不是 NAME=VALUE 格式</translation>
    </message>
    <message>
        <source>unknown parameter &quot;%1&quot; (known: %2)</source>
        <translation>未知参数 &quot;%1&quot;（已知参数：%2）</translation>
    </message>
    <message>
        <source>%1: &quot;%2&quot; is not a number</source>
        <translation>%1：&quot;%2&quot; 不是数字</translation>
    </message>
    <message>
        <source>Response</source>
        <translation>响应</translation>
    </message>
    <message>
        <source>Travel</source>
        <translation>行程</translation>
    </message>
    <message>
        <source>Power</source>
        <translation>功率</translation>
    </message>
    <message>
        <source>%1 must be between %2 and %3%4</source>
        <translation>%1 必须介于 %2 和 %3%4 之间</translation>
    </message>
</context>
<context>
    <name>seriallink::PacketLogModel</name>
    <message>
        <source>The log could not be written.</source>
        <translation>无法写入日志。</translation>
    </message>
    <message>
        <source>Cannot write %1: %2</source>
        <translation>无法写入 %1：%2</translation>
    </message>
    <message>
        <source>→ out</source>
        <translation>→ 发出</translation>
    </message>
    <message>
        <source>← in</source>
        <translation>← 收到</translation>
    </message>
    <message>
        <source>echo</source>
        <translation>回显</translation>
    </message>
    <message>
        <source>stray</source>
        <translation>杂散</translation>
    </message>
    <message numerus="yes">
        <source>%n byte(s)</source>
        <translation>
            <numerusform>%n 字节</numerusform>
        </translation>
    </message>
    <message>
        <source>Time</source>
        <translation>时间</translation>
    </message>
    <message>
        <source>Direction</source>
        <translation>方向</translation>
    </message>
    <message>
        <source>Bytes</source>
        <translation>字节</translation>
    </message>
    <message>
        <source>Meaning</source>
        <translation>含义</translation>
    </message>
    <message>
        <source>Error</source>
        <translation>错误</translation>
    </message>
</context>
<context>
    <name>servoctl</name>
    <message>
        <source>--%1 takes no value</source>
        <translation>--%1 不接受值</translation>
    </message>
    <message>
        <source>--%1 needs a value</source>
        <translation>--%1 需要一个值</translation>
    </message>
    <message>
        <source>--%1 is given twice</source>
        <translation>--%1 被指定了两次</translation>
    </message>
    <message>
        <source>unknown option --%1</source>
        <translation>未知选项 --%1</translation>
    </message>
    <message>
        <source>--%1: &quot;%2&quot; is not a number</source>
        <translation>--%1：&quot;%2&quot; 不是数字</translation>
    </message>
    <message>
        <source>--%1: %2 is out of range (%3 to %4)</source>
        <translation>--%1：%2 超出范围（%3 到 %4）</translation>
    </message>
    <message>
        <source>--duration must be a number of seconds above 0</source>
        <translation>--duration 必须是大于 0 的秒数</translation>
    </message>
    <message>
        <source>--ids: &quot;%1&quot; is not an ID</source>
        <translation>--ids：&quot;%1&quot; 不是 ID</translation>
    </message>
    <message>
        <source>--ids: ID %1 is over %2</source>
        <translation>--ids：ID %1 大于 %2</translation>
    </message>
    <message>
        <source>--ids: &quot;%1&quot; has an empty place between commas</source>
        <translation>--ids：&quot;%1&quot; 中逗号之间有空项</translation>
    </message>
    <message>
        <source>--ids: the range %1 runs backwards</source>
        <translation>--ids：范围 %1 是倒序的</translation>
    </message>
    <message>
        <source>--ids needs at least one ID</source>
        <translation>--ids 至少需要一个 ID</translation>
    </message>
    <message>
        <source>%1 takes no --%2</source>
        <translation>%1 不接受 --%2</translation>
    </message>
    <message>
        <source>%1 needs --port PATH (see servoctl ports)</source>
        <translation>%1 需要 --port PATH（参见 servoctl ports）</translation>
    </message>
    <message>
        <source>detect takes no arguments</source>
        <translation>detect 不接受参数</translation>
    </message>
    <message>
        <source>PTK servo at 115200 bps%1</source>
        <translation>PTK 舵机，115200 bps%1</translation>
    </message>
    <message>
        <source>, adapter echo</source>
        <translation>，适配器回显</translation>
    </message>
    <message numerus="yes">
        <source>Feetech bus%1: %n servo(s)</source>
        <translation>
            <numerusform>Feetech 总线%1：%n 个舵机</numerusform>
        </translation>
    </message>
    <message>
        <source>interrupted before the probe ended</source>
        <translation>探测结束前被中断</translation>
    </message>
    <message>
        <source>nothing answers on %1</source>
        <translation>%1 上没有任何应答</translation>
    </message>
    <message>
        <source>doctor takes no arguments (the expected IDs go in --expect)</source>
        <translation>doctor 不接受参数（预期的 ID 请用 --expect 给出）</translation>
    </message>
    <message>
        <source>doctor --baud names the rate of the --expect servos</source>
        <translation>doctor 的 --baud 用于指定 --expect 所列舵机的波特率</translation>
    </message>
    <message>
        <source>--baud %1 is not a Feetech rate (%2)</source>
        <translation>--baud %1 不是 Feetech 波特率（%2）</translation>
    </message>
    <message>
        <source>A PTK servo answers on %1.</source>
        <translation>%1 上有 PTK 舵机应答。</translation>
    </message>
    <message numerus="yes">
        <source>The bus holds what was expected: %n servo(s).</source>
        <translation>
            <numerusform>总线与预期一致：%n 个舵机。</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 needs --ids LIST (such as 1-6)</source>
        <translation>%1 需要 --ids LIST（如 1-6）</translation>
    </message>
    <message>
        <source>--ids names no servo</source>
        <translation>--ids 未指定任何舵机</translation>
    </message>
    <message>
        <source>--ids names servo %1 twice</source>
        <translation>--ids 两次指定了舵机 %1</translation>
    </message>
    <message>
        <source>--names gives %1 name(s) for %2 servo(s) in --ids</source>
        <translation>--names 给出了 %1 个名称，而 --ids 中有 %2 个舵机</translation>
    </message>
    <message>
        <source>--names: &quot;%1&quot; is not a joint name (letters, digits and _, a letter first)</source>
        <translation>--names：&quot;%1&quot; 不是关节名称（由字母、数字和 _ 组成，以字母开头）</translation>
    </message>
    <message>
        <source>--names: &quot;%1&quot; is given twice</source>
        <translation>--names：&quot;%1&quot; 被指定了两次</translation>
    </message>
    <message>
        <source>servo %1 (%2) has no position offset on a 4096-step encoder: it cannot be calibrated; nothing was written</source>
        <translation>舵机 %1（%2）没有适用于 4096 步编码器的位置偏移：无法校准；未写入任何内容</translation>
    </message>
    <message>
        <source>--full-turn: servo %1 is not in --ids</source>
        <translation>--full-turn：舵机 %1 不在 --ids 中</translation>
    </message>
    <message>
        <source>%1 needs --out FILE: the LeRobot calibration file to save</source>
        <translation>%1 需要 --out FILE：要保存的 LeRobot 校准文件</translation>
    </message>
    <message>
        <source>%1 needs --duration S when standard input is not a terminal (Enter on a terminal ends the recording otherwise)</source>
        <translation>标准输入不是终端时，%1 需要 --duration S（在终端上则按 Enter 结束记录）</translation>
    </message>
    <message>
        <source>servo %1: torque could not be switched off: %2</source>
        <translation>舵机 %1：无法关闭扭矩：%2</translation>
    </message>
    <message>
        <source>%1 (servo %2): refused, nothing written: %3</source>
        <translation>%1（舵机 %2）：已拒绝，未写入任何内容：%3</translation>
    </message>
    <message>
        <source>%1 (servo %2): offset %3, limits %4 to %5</source>
        <translation>%1（舵机 %2）：偏移 %3，限制 %4 到 %5</translation>
    </message>
    <message>
        <source> (not written: --dry-run)</source>
        <translation> （未写入：--dry-run）</translation>
    </message>
    <message>
        <source>, written and verified</source>
        <translation>，已写入并验证</translation>
    </message>
    <message>
        <source>, NOT verified: %1</source>
        <translation>，未验证：%1</translation>
    </message>
    <message numerus="yes">
        <source>saved %n joint(s) to %1</source>
        <translation>
            <numerusform>已将 %n 个关节保存到 %1</numerusform>
        </translation>
    </message>
    <message>
        <source>no joint could be calibrated; %1 was not written</source>
        <translation>没有任何关节能够校准；未写入 %1</translation>
    </message>
    <message>
        <source>not every joint was calibrated: see the refusals above</source>
        <translation>并非所有关节都已校准：请查看上方的拒绝信息</translation>
    </message>
    <message>
        <source>servoctl: torque is off; move every joint through its whole range for %1 s</source>
        <translation>servoctl：扭矩已关闭；请在 %1 秒内将每个关节转过其整个范围</translation>
    </message>
    <message>
        <source>servoctl: torque is off; move every joint through its whole range, then press Enter</source>
        <translation>servoctl：扭矩已关闭；请将每个关节转过其整个范围，然后按 Enter</translation>
    </message>
    <message>
        <source>interrupted: nothing was written (torque stays off)</source>
        <translation>已中断：未写入任何内容（扭矩保持关闭）</translation>
    </message>
    <message>
        <source>joint</source>
        <translation>关节</translation>
    </message>
    <message>
        <source>id</source>
        <translation>ID</translation>
    </message>
    <message>
        <source>min</source>
        <translation>最小</translation>
    </message>
    <message>
        <source>present</source>
        <translation>当前</translation>
    </message>
    <message>
        <source>max</source>
        <translation>最大</translation>
    </message>
    <message>
        <source>  (stopped answering)</source>
        <translation>  （停止应答）</translation>
    </message>
    <message>
        <source>%1 needs save or load</source>
        <translation>%1 需要 save 或 load</translation>
    </message>
    <message>
        <source>unknown %1 command &quot;%2&quot;: use save or load</source>
        <translation>未知的 %1 命令 &quot;%2&quot;：请使用 save 或 load</translation>
    </message>
    <message>
        <source>one FILE</source>
        <translation>一个 FILE</translation>
    </message>
    <message>
        <source>servo %1 holds the limits %2 to %3, which are no calibrated range (min = max = 0 is multi-turn mode); %4 was not written</source>
        <translation>舵机 %1 的限制为 %2 到 %3，不是已校准的范围（最小 = 最大 = 0 为多圈模式）；未写入 %4</translation>
    </message>
    <message numerus="yes">
        <source>saved the calibration of %n servo(s) to %1</source>
        <translation>
            <numerusform>已将 %n 个舵机的校准保存到 %1</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 (servo %2)</source>
        <translation>%1（舵机 %2）</translation>
    </message>
    <message>
        <source>%1: already holds the file&apos;s values</source>
        <translation>%1：已包含文件中的值</translation>
    </message>
    <message>
        <source>torque is on: the new offset would move the horn; switch torque off (support the arm) and load again</source>
        <translation>扭矩已开启：新的偏移会使舵盘移动；请关闭扭矩（扶住机械臂）后重新加载</translation>
    </message>
    <message>
        <source>%1: %2; refused, nothing written: %3</source>
        <translation>%1：%2；已拒绝，未写入任何内容：%3</translation>
    </message>
    <message>
        <source>%1: %2; written and verified</source>
        <translation>%1：%2；已写入并验证</translation>
    </message>
    <message>
        <source>%1: %2; NOT verified: %3</source>
        <translation>%1：%2；未验证：%3</translation>
    </message>
    <message>
        <source>the calibration of %1 was not loaded whole: see above</source>
        <translation>%1 的校准未完整加载：请见上文</translation>
    </message>
    <message>
        <source>feetech needs a command (try servoctl --help)</source>
        <translation>feetech 需要一个命令（请尝试 servoctl --help）</translation>
    </message>
    <message>
        <source>unknown feetech command &quot;%1&quot;: use %2</source>
        <translation>未知的 feetech 命令 &quot;%1&quot;：请使用 %2</translation>
    </message>
    <message>
        <source>%1 takes no arguments</source>
        <translation>%1 不接受参数</translation>
    </message>
    <message>
        <source>%1 needs %2</source>
        <translation>%1 需要%2</translation>
    </message>
    <message>
        <source>%1: &quot;%2&quot; is not a Feetech baud rate (%3)</source>
        <translation>%1：&quot;%2&quot; 不是 Feetech 波特率（%3）</translation>
    </message>
    <message>
        <source>%1 needs --id N</source>
        <translation>%1 需要 --id N</translation>
    </message>
    <message>
        <source>the folder of %1 does not exist</source>
        <translation>%1 所在的文件夹不存在</translation>
    </message>
    <message>
        <source>servo %1 is of an unknown model (%2); nothing is written to it</source>
        <translation>舵机 %1 为未知型号（%2）；不向其写入任何内容</translation>
    </message>
    <message numerus="yes">
        <source>written to servo %1 and verified: %n register(s)</source>
        <translation>
            <numerusform>已写入舵机 %1 并验证：%n 个寄存器</numerusform>
        </translation>
    </message>
    <message>
        <source>verification failed: %1</source>
        <translation>验证失败：%1</translation>
    </message>
    <message>
        <source>%1: wrote %2, the servo holds %3</source>
        <translation>%1：写入 %2，舵机中为 %3</translation>
    </message>
    <message>
        <source>nothing</source>
        <translation>无</translation>
    </message>
    <message>
        <source>%1 bps</source>
        <translation>%1 bps</translation>
    </message>
    <message>
        <source>unknown model, raw bytes only</source>
        <translation>未知型号，仅显示原始字节</translation>
    </message>
    <message>
        <source>servo %1 at %2: %3 (%4), firmware %5</source>
        <translation>舵机 %1，位于 %2：%3（%4），固件 %5</translation>
    </message>
    <message>
        <source>feetech commands need --port PATH (see servoctl ports)</source>
        <translation>feetech 命令需要 --port PATH（参见 servoctl ports）</translation>
    </message>
    <message>
        <source>%1 could not be opened</source>
        <translation>无法打开 %1</translation>
    </message>
    <message>
        <source>%1 (at %2; servoctl feetech scan --baud all looks at every rate)</source>
        <translation>%1（在 %2 下；servoctl feetech scan --baud all 会检查所有波特率）</translation>
    </message>
    <message>
        <source>servo %1 answers PING but its identity (addresses 0-8) could not be read: %2</source>
        <translation>舵机 %1 应答了 PING，但无法读取其身份信息（地址 0-8）：%2</translation>
    </message>
    <message>
        <source>interrupted: nothing more was sent</source>
        <translation>已中断：不再发送任何内容</translation>
    </message>
    <message>
        <source>interrupted: %1</source>
        <translation>已中断：%1</translation>
    </message>
    <message>
        <source>interrupted again before the operation ended: check the servo&apos;s torque and EEPROM lock</source>
        <translation>操作结束前再次被中断：请检查舵机的扭矩和 EEPROM 锁标志</translation>
    </message>
    <message>
        <source>the servo did not finish in time</source>
        <translation>舵机未能及时完成</translation>
    </message>
    <message>
        <source>the NEW ID</source>
        <translation>新 ID（NEW）</translation>
    </message>
    <message>
        <source>%1: &quot;%2&quot; is not an ID (0 to %3)</source>
        <translation>%1：&quot;%2&quot; 不是 ID（0 到 %3）</translation>
    </message>
    <message>
        <source>servo %1 already has ID %1; nothing written</source>
        <translation>舵机 %1 的 ID 已经是 %1；未写入任何内容</translation>
    </message>
    <message>
        <source>the new BAUD rate in bits per second</source>
        <translation>新的波特率 BAUD（单位为 bps）</translation>
    </message>
    <message>
        <source>servo %1 already runs at %2; nothing written</source>
        <translation>舵机 %1 已在 %2 下运行；未写入任何内容</translation>
    </message>
    <message>
        <source>%1 servos do not support %2</source>
        <translation>%1 舵机不支持 %2</translation>
    </message>
    <message>
        <source>--backup needs a FILE</source>
        <translation>--backup 需要一个 FILE</translation>
    </message>
    <message>
        <source>servo %1 is of an unknown model (%2): no backup can be saved, so it is not reset</source>
        <translation>舵机 %1 为未知型号（%2）：无法保存备份，因此不进行复位</translation>
    </message>
    <message>
        <source>the backup could not be saved, so the servo was not reset: %1</source>
        <translation>无法保存备份，因此舵机未复位：%1</translation>
    </message>
    <message>
        <source>backup of servo %1 saved to %2</source>
        <translation>舵机 %1 的备份已保存到 %2</translation>
    </message>
    <message>
        <source>servo %1 is of an unknown model (%2): its EEPROM lock is not known</source>
        <translation>舵机 %1 为未知型号（%2）：其 EEPROM 锁标志未知</translation>
    </message>
    <message>
        <source>servo %1 is of an unknown model (%2): its status bits are not known</source>
        <translation>舵机 %1 为未知型号（%2）：其状态位未知</translation>
    </message>
    <message>
        <source>after the power cycle: servoctl feetech recover --id %1 --check</source>
        <translation>断电重启后：servoctl feetech recover --id %1 --check</translation>
    </message>
    <message>
        <source>not read</source>
        <translation>未读取</translation>
    </message>
    <message>
        <source>its identity (addresses 0-8) could not be read</source>
        <translation>无法读取其身份信息（地址 0-8）</translation>
    </message>
    <message>
        <source>moving servo %1 by %2 steps from %3 and back…</source>
        <translation>正在将舵机 %1 从 %3 移动 %2 步再返回…</translation>
    </message>
    <message>
        <source>servo %1 (no answer): %2</source>
        <translation>舵机 %1（无应答）：%2</translation>
    </message>
    <message>
        <source>servo %1 (%2, firmware %3): %4</source>
        <translation>舵机 %1（%2，固件 %3）：%4</translation>
    </message>
    <message>
        <source>voltage %1, temperature %2, load %3, position %4, status %5</source>
        <translation>电压 %1，温度 %2，负载 %3，位置 %4，状态 %5</translation>
    </message>
    <message>
        <source>steps</source>
        <translation>步</translation>
    </message>
    <message>
        <source>communication: %1</source>
        <translation>通信：%1</translation>
    </message>
    <message>
        <source>move test: %1</source>
        <translation>运动测试：%1</translation>
    </message>
    <message>
        <source>not run (the servo has a fault)</source>
        <translation>未运行（舵机有故障）</translation>
    </message>
    <message>
        <source>%1 needs --ids LIST (such as 1,2,5-7)</source>
        <translation>%1 需要 --ids LIST（如 1,2,5-7）</translation>
    </message>
    <message>
        <source>choose --csv or --json, not both</source>
        <translation>--csv 和 --json 只能选择其一</translation>
    </message>
    <message>
        <source>servo %1 is of an unknown model (%2): its feedback cannot be decoded</source>
        <translation>舵机 %1 为未知型号（%2）：无法解码其反馈</translation>
    </message>
    <message>
        <source>servoctl: servo %1 stopped answering</source>
        <translation>servoctl：舵机 %1 停止应答</translation>
    </message>
    <message>
        <source>servoctl: servo %1 answers again</source>
        <translation>servoctl：舵机 %1 恢复应答</translation>
    </message>
    <message>
        <source>servoctl: %1 samples in %2 s (%3 per second); %4 missed, %5 late</source>
        <translation>servoctl：%2 秒内 %1 个采样（每秒 %3 个）；丢失 %4 个，迟到 %5 个</translation>
    </message>
    <message>
        <source>no servo answered the telemetry requests</source>
        <translation>没有舵机应答遥测请求</translation>
    </message>
    <message>
        <source>--rate must be a number of samples per second from 1 to 1000, or max</source>
        <translation>--rate 必须是每秒采样数（1 到 1000）或 max</translation>
    </message>
    <message>
        <source>%1 = %2 is outside its range (%3 to %4) and is left out of the profile</source>
        <translation>%1 = %2 超出其范围（%3 到 %4），未写入配置文件</translation>
    </message>
    <message>
        <source>servo %1 is of an unknown model (%2): no profile can be saved</source>
        <translation>舵机 %1 为未知型号（%2）：无法保存配置文件</translation>
    </message>
    <message>
        <source>saved servo %1 (%2) to %3</source>
        <translation>已将舵机 %1（%2）保存到 %3</translation>
    </message>
    <message>
        <source>%1 takes --id N or --ids LIST, not both</source>
        <translation>%1 接受 --id N 或 --ids LIST，但不能同时使用</translation>
    </message>
    <message>
        <source>note: the profile was saved from a %1, this servo is a %2</source>
        <translation>注意：该配置文件保存自 %1，而此舵机是 %2</translation>
    </message>
    <message>
        <source>servo %1: %2</source>
        <translation>舵机 %1：%2</translation>
    </message>
    <message>
        <source>servo %1 already holds every value of %2; nothing written</source>
        <translation>舵机 %1 已包含 %2 的所有值；未写入任何内容</translation>
    </message>
    <message>
        <source>--ids: a scan covers one range of IDs, such as 0-20</source>
        <translation>--ids：一次扫描只覆盖一个 ID 范围，如 0-20</translation>
    </message>
    <message>
        <source>baud</source>
        <translation>波特率</translation>
    </message>
    <message>
        <source>model</source>
        <translation>型号</translation>
    </message>
    <message>
        <source>number</source>
        <translation>编号</translation>
    </message>
    <message>
        <source>family</source>
        <translation>系列</translation>
    </message>
    <message>
        <source>firmware</source>
        <translation>固件</translation>
    </message>
    <message>
        <source>no servo answered (try --baud all, or check power and wiring)</source>
        <translation>没有舵机应答（请尝试 --baud all，或检查电源和接线）</translation>
    </message>
    <message>
        <source>%1; answered in %2 ms</source>
        <translation>%1；%2 ms 内应答</translation>
    </message>
    <message>
        <source>no register table is known for this model: the bytes are shown as they are, and nothing can be written</source>
        <translation>此型号没有已知的寄存器表：按原样显示字节，且无法写入任何内容</translation>
    </message>
    <message>
        <source>addr</source>
        <translation>地址</translation>
    </message>
    <message>
        <source>key</source>
        <translation>键名</translation>
    </message>
    <message>
        <source>value</source>
        <translation>值</translation>
    </message>
    <message>
        <source>meaning</source>
        <translation>含义</translation>
    </message>
    <message>
        <source>%1 needs the register KEYs to read</source>
        <translation>%1 需要要读取的寄存器 KEY</translation>
    </message>
    <message>
        <source>%1: &quot;%2&quot; is not a register key</source>
        <translation>%1：&quot;%2&quot; 不是寄存器键名</translation>
    </message>
    <message>
        <source>%1 servos have no register &quot;%2&quot; (servoctl feetech read lists them)</source>
        <translation>%1 舵机没有寄存器 &quot;%2&quot;（servoctl feetech read 会列出所有寄存器）</translation>
    </message>
    <message>
        <source>%1 needs KEY=VALUE arguments</source>
        <translation>%1 需要 KEY=VALUE 参数</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not KEY=VALUE</source>
        <translation>&quot;%1&quot; 不是 KEY=VALUE 格式</translation>
    </message>
    <message>
        <source>the ID changes how the servo is reached: use servoctl feetech set-id --id N NEW</source>
        <translation>ID 决定了如何访问舵机：请使用 servoctl feetech set-id --id N NEW</translation>
    </message>
    <message>
        <source>the baud rate changes how the servo is reached: use servoctl feetech set-baud --id N BAUD</source>
        <translation>波特率决定了如何访问舵机：请使用 servoctl feetech set-baud --id N BAUD</translation>
    </message>
    <message>
        <source>%1 is given twice</source>
        <translation>%1 被指定了两次</translation>
    </message>
    <message>
        <source>%1 is read-only</source>
        <translation>%1 为只读</translation>
    </message>
    <message>
        <source>moving servo %1 a little each way, slowly…</source>
        <translation>正在缓慢地将舵机 %1 向两侧各移动一点…</translation>
    </message>
    <message numerus="yes">
        <source>%1 to %n servo(s):</source>
        <translation>
            <numerusform>将 %1 应用到 %n 个舵机：</numerusform>
        </translation>
    </message>
    <message>
        <source>ID</source>
        <translation>ID</translation>
    </message>
    <message>
        <source>status</source>
        <translation>状态</translation>
    </message>
    <message>
        <source>changed / error</source>
        <translation>已更改 / 错误</translation>
    </message>
    <message>
        <source>%1: &quot;%2&quot; has no joint with ID %3</source>
        <translation>%1：&quot;%2&quot; 中没有 ID 为 %3 的关节</translation>
    </message>
    <message>
        <source>--model: &quot;%1&quot; is no model with a known register table</source>
        <translation>--model：&quot;%1&quot; 不是具有已知寄存器表的型号</translation>
    </message>
    <message>
        <source>--model %1 does not match the template&apos;s %2 (a %3)</source>
        <translation>--model %1 与模板中的 %2（%3）不符</translation>
    </message>
    <message>
        <source>the set-up ended before it reported; check the port and the cable, then run it again</source>
        <translation>设置在报告结果前就结束了；请检查端口和线缆，然后重新运行</translation>
    </message>
    <message>
        <source>ptk commands need --port PATH (see servoctl ports)</source>
        <translation>ptk 命令需要 --port PATH（参见 servoctl ports）</translation>
    </message>
    <message>
        <source>ptk needs a command: read, write, save, load or monitor</source>
        <translation>ptk 需要一个命令：read、write、save、load 或 monitor</translation>
    </message>
    <message>
        <source>ptk takes no --rate: the servo is polled every 50 ms</source>
        <translation>ptk 不接受 --rate：每 50 ms 轮询一次舵机</translation>
    </message>
    <message>
        <source>ptk takes no --%1</source>
        <translation>ptk 不接受 --%1</translation>
    </message>
    <message>
        <source>only ptk monitor takes --duration</source>
        <translation>只有 ptk monitor 接受 --duration</translation>
    </message>
    <message>
        <source>unknown ptk command &quot;%1&quot;: use read, write, save, load or monitor</source>
        <translation>未知的 ptk 命令 &quot;%1&quot;：请使用 read、write、save、load 或 monitor</translation>
    </message>
    <message>
        <source>ptk read takes no arguments</source>
        <translation>ptk read 不接受参数</translation>
    </message>
    <message>
        <source>written and verified</source>
        <translation>已写入并验证</translation>
    </message>
    <message>
        <source>ptk write needs NAME=VALUE arguments (names: %1)</source>
        <translation>ptk write 需要 NAME=VALUE 参数（名称：%1）</translation>
    </message>
    <message>
        <source>ptk save needs one FILE</source>
        <translation>ptk save 需要一个 FILE</translation>
    </message>
    <message>
        <source>saved %1</source>
        <translation>已保存 %1</translation>
    </message>
    <message>
        <source>ptk load needs one FILE</source>
        <translation>ptk load 需要一个 FILE</translation>
    </message>
    <message>
        <source>ptk monitor takes no arguments</source>
        <translation>ptk monitor 不接受参数</translation>
    </message>
    <message>
        <source>the servo did not answer</source>
        <translation>舵机没有应答</translation>
    </message>
    <message>
        <source>no command given (try servoctl --help)</source>
        <translation>未指定命令（请尝试 servoctl --help）</translation>
    </message>
    <message>
        <source>unknown command &quot;%1&quot; (try servoctl --help)</source>
        <translation>未知命令 &quot;%1&quot;（请尝试 servoctl --help）</translation>
    </message>
    <message>
        <source>ports takes no arguments</source>
        <translation>ports 不接受参数</translation>
    </message>
    <message>
        <source>no serial ports found</source>
        <translation>未找到串口</translation>
    </message>
    <message>
        <source>decode needs the bytes to decode, as hex</source>
        <translation>decode 需要以十六进制给出要解码的字节</translation>
    </message>
    <message>
        <source>--family must be ptk or feetech</source>
        <translation>--family 必须为 ptk 或 feetech</translation>
    </message>
    <message>
        <source>no PTK (AF FA) or Feetech (FF FF) header found; name the protocol with --family</source>
        <translation>未找到 PTK（AF FA）或 Feetech（FF FF）字头；请用 --family 指定协议</translation>
    </message>
    <message>
        <source> [checksum ok]</source>
        <translation> [校验和正确]</translation>
    </message>
    <message>
        <source> [BAD CHECKSUM]</source>
        <translation> [校验和错误]</translation>
    </message>
    <message>
        <source>packet needs a protocol: ptk or feetech</source>
        <translation>packet 需要一个协议：ptk 或 feetech</translation>
    </message>
    <message>
        <source>unknown protocol &quot;%1&quot;: use ptk or feetech</source>
        <translation>未知协议 &quot;%1&quot;：请使用 ptk 或 feetech</translation>
    </message>
    <message>
        <source>packet ptk needs query CMD or write NAME=VALUE...</source>
        <translation>packet ptk 需要 query CMD 或 write NAME=VALUE...</translation>
    </message>
    <message>
        <source>packet ptk query needs exactly one command</source>
        <translation>packet ptk query 只需要一个命令</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a command byte (0-255) or N1..N8</source>
        <translation>&quot;%1&quot; 不是命令字节（0-255）或 N1..N8</translation>
    </message>
    <message>
        <source>unknown PTK packet &quot;%1&quot;: use query or write</source>
        <translation>未知的 PTK 数据包 &quot;%1&quot;：请使用 query 或 write</translation>
    </message>
    <message>
        <source>packet ptk write needs NAME=VALUE arguments</source>
        <translation>packet ptk write 需要 NAME=VALUE 参数</translation>
    </message>
    <message>
        <source>write %1 also carries %2; give it too</source>
        <translation>写入 %1 时也会写入 %2；请一并给出</translation>
    </message>
    <message>
        <source>packet feetech needs one instruction (try servoctl --help)</source>
        <translation>packet feetech 需要一条指令（请尝试 servoctl --help）</translation>
    </message>
    <message>
        <source>%1 needs --id</source>
        <translation>%1 需要 --id</translation>
    </message>
    <message>
        <source>%1 needs a unicast ID (0-253), not %2</source>
        <translation>%1 需要单播 ID（0-253），而不是 %2</translation>
    </message>
    <message>
        <source>%1 needs --addr</source>
        <translation>%1 需要 --addr</translation>
    </message>
    <message>
        <source>%1 needs --data</source>
        <translation>%1 需要 --data</translation>
    </message>
    <message>
        <source>--data is empty</source>
        <translation>--data 为空</translation>
    </message>
    <message>
        <source>%1 needs --len</source>
        <translation>%1 需要 --len</translation>
    </message>
    <message>
        <source>the packet would be %1 bytes; the limit is %2</source>
        <translation>数据包将为 %1 字节；上限为 %2</translation>
    </message>
    <message>
        <source>calibrate --data is a 2-byte position in the family&apos;s byte order</source>
        <translation>calibrate 的 --data 是按该系列字节顺序排列的 2 字节位置</translation>
    </message>
    <message>
        <source>%1 needs --ids</source>
        <translation>%1 需要 --ids</translation>
    </message>
    <message>
        <source>--data must hold %1 or %2 bytes (--len %1 for %3 servos)</source>
        <translation>--data 必须包含 %1 或 %2 字节（%3 个舵机时 --len %1）</translation>
    </message>
    <message>
        <source>the SYNC WRITE would exceed %1 bytes</source>
        <translation>SYNC WRITE 将超过 %1 字节</translation>
    </message>
    <message>
        <source>unknown Feetech instruction &quot;%1&quot; (try servoctl --help)</source>
        <translation>未知的 Feetech 指令 &quot;%1&quot;（请尝试 servoctl --help）</translation>
    </message>
    <message>
        <source>--echo must be auto, on or off</source>
        <translation>--echo 必须为 auto、on 或 off</translation>
    </message>
    <message>
        <source>drive_mode %1 is LeRobot&apos;s software setting (the direction inverted), held by no register: it is kept in the file only</source>
        <translation>drive_mode %1 是 LeRobot 的软件设置（方向反转），没有寄存器保存它：它只保留在文件中</translation>
    </message>
    <message>
        <source>%1: note: %2</source>
        <translation>%1：提示：%2</translation>
    </message>
    <message>
        <source>note: servo %1&apos;s EEPROM is unlocked (lock = 0), as some programs (LeRobot among them) leave it: a setting written to it now survives a power cut. servoctl locks it again after each of its own EEPROM writes; to lock it now: servoctl feetech lock --id %1</source>
        <translation>提示：舵机 %1 的 EEPROM 未上锁（lock = 0），一些程序（包括 LeRobot）会这样留下它：现在写入的设置在断电后仍会保留。servoctl 在自己的每次 EEPROM 写入后都会重新上锁；要立即上锁：servoctl feetech lock --id %1</translation>
    </message>
    <message>
        <source>servo %1 answers with error bits 0x%2 (%3): servoctl doctor says why</source>
        <translation>舵机 %1 的应答带有错误位 0x%2（%3）：servoctl doctor 会说明原因</translation>
    </message>
    <message>
        <source>decode --log takes the recording only, no bytes</source>
        <translation>decode --log 只接受记录文件，不接受字节</translation>
    </message>
    <message>
        <source>share recordings are of Feetech buses: --family feetech</source>
        <translation>共享记录属于飞特总线：--family feetech</translation>
    </message>
    <message>
        <source>%1 --update FILE takes the joints&apos; names from the file and saves to it: no --out or --names</source>
        <translation>%1 --update FILE 从该文件获取关节名称并保存到该文件：不能使用 --out 或 --names</translation>
    </message>
    <message>
        <source>servo %1 is no joint of %2</source>
        <translation>舵机 %1 不是 %2 的关节</translation>
    </message>
    <message>
        <source>%1 --robot: %2</source>
        <translation>%1 --robot：%2</translation>
    </message>
    <message numerus="yes">
        <source>fixing %n setting(s)…</source>
        <translation>
            <numerusform>正在修复 %n 项设置…</numerusform>
        </translation>
    </message>
    <message>
        <source>nothing to write fixes this</source>
        <translation>无法通过写入修复</translation>
    </message>
    <message numerus="yes">
        <source>No problem found in the settings of %n servo(s).</source>
        <translation>
            <numerusform>%n 个舵机的设置中未发现问题。</numerusform>
        </translation>
    </message>
    <message>
        <source>SETTING</source>
        <translation>设置项</translation>
    </message>
    <message>
        <source>VALUE</source>
        <translation>值</translation>
    </message>
    <message>
        <source>EXPECTED</source>
        <translation>预期值</translation>
    </message>
    <message>
        <source>WHY</source>
        <translation>原因</translation>
    </message>
    <message numerus="yes">
        <source>%n finding(s); --fix writes the expected values and reads them back.</source>
        <translation>
            <numerusform>发现 %n 个问题；--fix 会写入预期值并回读。</numerusform>
        </translation>
    </message>
    <message>
        <source>servo %1 %2: %3 → %4: %5</source>
        <translation>舵机 %1 %2：%3 → %4：%5</translation>
    </message>
    <message>
        <source>--%1 must be %2</source>
        <translation>--%1 必须是%2</translation>
    </message>
    <message>
        <source>%1 needs --out FILE: the CSV file to record into</source>
        <translation>%1 需要 --out FILE：用于记录的 CSV 文件</translation>
    </message>
    <message>
        <source>a number of frames per second from 1 to %1</source>
        <translation>每秒帧数，取值 1 到 %1</translation>
    </message>
    <message>
        <source>servo %1 is of an unknown model (%2): its position cannot be read</source>
        <translation>舵机 %1 为未知型号（%2）：无法读取其位置</translation>
    </message>
    <message numerus="yes">
        <source>recording %n joint(s); move them by hand, Ctrl-C ends</source>
        <translation>
            <numerusform>正在记录 %n 个关节；请手动移动它们，按 Ctrl-C 结束</numerusform>
        </translation>
    </message>
    <message>
        <source>no frame was recorded: not every servo answered; nothing was written</source>
        <translation>未记录任何帧：并非所有舵机都有应答；未写入任何内容</translation>
    </message>
    <message numerus="yes">
        <source>recorded %n frame(s) of %1 joint(s) over %2 s into %3</source>
        <translation>
            <numerusform>已将 %1 个关节在 %2 秒内的 %n 帧记录到 %3</numerusform>
        </translation>
    </message>
    <message>
        <source>%1; what was recorded until then is in %2</source>
        <translation>%1；此前记录的内容保存在 %2 中</translation>
    </message>
    <message>
        <source>column %1 matches no servo: %2; nothing was moved</source>
        <translation>列 %1 与任何舵机都不匹配：%2；未移动任何舵机</translation>
    </message>
    <message>
        <source>column %1: servo %2 is of an unknown model (%3); nothing was moved</source>
        <translation>列 %1：舵机 %2 为未知型号（%3）；未移动任何舵机</translation>
    </message>
    <message>
        <source>a number above 0 (2 plays twice as fast)</source>
        <translation>大于 0 的数（2 表示以两倍速度播放）</translation>
    </message>
    <message>
        <source>a number of seconds from 0</source>
        <translation>不小于 0 的秒数</translation>
    </message>
    <message>
        <source>interrupted again before the arm was held: check the servos&apos; torque</source>
        <translation>机械臂保持位置之前再次被中断：请检查舵机的扭矩</translation>
    </message>
    <message>
        <source>joint %1 (servo %2) does not answer: %3</source>
        <translation>关节 %1（舵机 %2）无应答：%3</translation>
    </message>
    <message>
        <source>joint %1 (servo %2) does not hold what %3 says (%4): write the file to the arm first: servoctl --port %5 feetech calibration load %3</source>
        <translation>关节 %1（舵机 %2）中的值与 %3 不符（%4）：请先将该文件写入机械臂：servoctl --port %5 feetech calibration load %3</translation>
    </message>
    <message>
        <source>%1 needs --port FOLLOWER, --leader PORT, --calibration FILE and --leader-calibration FILE</source>
        <translation>%1 需要 --port FOLLOWER、--leader PORT、--calibration FILE 和 --leader-calibration FILE</translation>
    </message>
    <message>
        <source>--leader and --port name the same port: the leader and the follower are two arms on two adapters</source>
        <translation>--leader 和 --port 指定了同一个端口：主臂和从臂是接在两个适配器上的两条机械臂</translation>
    </message>
    <message>
        <source>the two files name different joints: %1</source>
        <translation>两个文件中的关节不一致：%1</translation>
    </message>
    <message>
        <source>the follower&apos;s torque could not be switched on</source>
        <translation>无法开启从臂的扭矩</translation>
    </message>
    <message>
        <source>servoctl: the follower holds; it moves to the leader&apos;s pose at %1°/s at most, then follows. Ctrl-C stops (it holds).</source>
        <translation>servoctl：从臂保持位置；它以最高 %1°/s 的速度移动到主臂的姿态，然后跟随。按 Ctrl-C 停止（从臂保持位置）。</translation>
    </message>
    <message>
        <source>%1 was lost: %2</source>
        <translation>%1已失去连接：%2</translation>
    </message>
    <message>
        <source>the follower</source>
        <translation>从臂</translation>
    </message>
    <message>
        <source>the leader</source>
        <translation>主臂</translation>
    </message>
    <message numerus="yes">
        <source>servoctl: %n frame(s) of the follower&apos;s goals recorded in %1</source>
        <translation>
            <numerusform>servoctl：已将从臂目标的 %n 帧记录到 %1</numerusform>
        </translation>
    </message>
    <message>
        <source>servoctl: %1 cycle(s) in %2 s (%3 per second), leader to follower %4 ms (median)</source>
        <translation>servoctl：%2 秒内 %1 个周期（每秒 %3 个），主臂到从臂的延迟 %4 ms（中位数）</translation>
    </message>
    <message>
        <source>servoctl: the follower&apos;s torque is off</source>
        <translation>servoctl：从臂的扭矩已关闭</translation>
    </message>
    <message>
        <source>servoctl: the follower holds where it is</source>
        <translation>servoctl：从臂保持在当前位置</translation>
    </message>
    <message>
        <source>servoctl: the follower could not be reached to stop it</source>
        <translation>servoctl：无法连接从臂以使其停止</translation>
    </message>
    <message numerus="yes">
        <source>dropped %Ln line(s) nobody read</source>
        <translation>
            <numerusform>丢弃了 %Ln 行无人读取的输出</numerusform>
        </translation>
    </message>
    <message>
        <source>--norm-mode must be degrees (LeRobot&apos;s use_degrees, the default) or range_m100_100</source>
        <translation>--norm-mode 必须是 degrees（LeRobot 的 use_degrees，默认）或 range_m100_100</translation>
    </message>
    <message>
        <source>servoctl: joints map in degrees from the middle of their ranges (LeRobot&apos;s use_degrees, norm mode degrees)</source>
        <translation>servoctl：关节按距其范围中点的角度映射（LeRobot 的 use_degrees，归一化模式 degrees）</translation>
    </message>
    <message>
        <source>servoctl: joints map range onto range (LeRobot&apos;s norm mode range_m100_100)</source>
        <translation>servoctl：关节按范围对范围映射（LeRobot 的归一化模式 range_m100_100）</translation>
    </message>
    <message>
        <source>usage: servoctl [--port PATH] [--baud N] [--json] [--trace] &lt;command&gt; [args]

commands:
  ports                                  list serial ports
  detect                                 find out what answers on the port: a PTK servo
                                         or a Feetech bus (its rates and servos); only
                                         queries, PINGs and READs are sent
  doctor [--expect LIST [--baud N]]      say what is wrong with the bus and what to do;
                                         LIST: the servos expected, in chain order
                                         (1,2,3 or 1-6), at --baud (1000000)
  ptk read                               read the PTK servo&apos;s thirteen parameters
  ptk write NAME=VALUE...                change parameters (full sequence, verified)
  ptk save FILE | ptk load FILE          save the servo to a profile / program one
  ptk monitor [--duration S] [--csv]     poll continuously, one row per full refresh
  feetech scan [--baud N|all] [--ids A-B] [--thorough]
                                         find the servos on the bus (IDs 0-253)
  feetech ping --id N                    check that a servo answers; its model
  feetech read --id N                    read every register of a servo
  feetech get --id N KEY...              read some registers
  feetech set --id N KEY=VALUE...        write registers (register units), verified
  feetech save --id N FILE               save the servo&apos;s EEPROM settings to a profile
  feetech load --id N FILE               write the values of a profile that differ
  feetech load --ids LIST FILE           the same for several servos (1,2,3 or 1-6);
                                         FILE may be a robot template: each servo gets
                                         its joint&apos;s settings by ID; a profile&apos;s
                                         position_offset is not copied; a servo with
                                         torque on is refused offset/limit changes
  feetech set-id --id N NEW              give the servo a new ID (refused if taken)
  feetech set-baud --id N BAUD           move the servo to another baud rate (bps)
  feetech calibrate-middle --id N        make the present position the middle
  feetech factory-reset --id N [--backup FILE]
                                         save a backup profile, then restore factory values
  feetech reboot --id N                  restart the servo and wait for it
  feetech lock --id N                    close an EEPROM lock left open, read it back
  feetech recover --id N [--check]       after an overload trip: torque off and on, goal
                                         at the present position, the overload bit read;
                                         still set: the power-cycle steps (exit 1); after
                                         the power cycle --check only reads the bit
  feetech setup-motor --id N [--baud BPS] [--model MODEL] [--settings ROBOT]
                                         the one servo on the bus (any ID, any rate) gets
                                         ID N and rate BPS (default 1000000, or the
                                         robot&apos;s), verified; ROBOT: a robot template file,
                                         whose joint with ID N gives the model to expect
                                         and the settings to write and verify
  feetech identify --id N                wiggle the servo slowly so you see which it is
  feetech health --ids LIST [--move-test]
                                         check each servo: model and firmware, voltage and
                                         temperature against its limits, status bits, load,
                                         20 reads&apos; retries and errors, position against its
                                         limits; --move-test also moves each servo without
                                         a fault 100 steps and back (rise time, overshoot,
                                         steady-state error); exit 1 when a servo has a fault
  feetech check --ids LIST [--robot ROBOT] [--fix]
                                         find settings that stop a servo moving or make it
                                         misbehave: phase bit 4 (multi-turn), torque limit
                                         or maximum torque 0, a mode other than position,
                                         angle limits, return delay, an open EEPROM, mixed
                                         firmware, voltage limits the supply breaks; ROBOT
                                         (so101-follower, ... or a template file) adds its
                                         settings; --fix writes the expected values, read
                                         back (limits, offset, mode, torque limit and phase
                                         only with torque off); exit 1 when something is left
  feetech monitor --ids LIST [--rate HZ|max] [--duration S] [--csv]
                                         stream position, speed, load, voltage,
                                         temperature and current (SYNC READ)
  feetech calibrate --ids LIST [--names LIST] [--full-turn LIST] [--duration S]
                    [--dry-run] --out FILE | --update FILE
                                         torque off, record each joint&apos;s range by hand
                                         (Enter ends), centre it on the encoder: offset
                                         and limits written, LeRobot calibration saved
                                         (--update: into FILE, its other joints kept)
  feetech calibration save --ids LIST [--names LIST] FILE
                                         the servos&apos; offsets and limits to a LeRobot file
  feetech calibration load FILE          write a LeRobot calibration file, verified
  feetech record --ids LIST --out FILE [--names LIST] [--rate HZ] [--duration S]
                                         record the positions moved by hand (torque left
                                         as it is) until --duration or Ctrl-C: CSV with
                                         time_s and a column per joint (id_N or NAME@N),
                                         in steps; --rate frames per second (default 50)
  feetech replay FILE [--speed X] [--ease S] [--loop N] [--release]
                                         play a recording: refused when a frame is beyond
                                         a servo&apos;s angle limits; torque on where the arm
                                         stands, a gentle move to the first frame (over S
                                         seconds; default from the distance), the frames
                                         at their times (--speed 2: twice as fast), N
                                         times, then hold (--release: torque off). Ctrl-C
                                         holds the arm where it is
  feetech teleop --leader PORT --calibration FILE --leader-calibration FILE
                 [--rate HZ] [--duration S] [--max-speed DEG_PER_S] [--record FILE]
                 [--release] [--norm-mode degrees|range_m100_100]
                                         the leader arm on PORT drives this follower,
                                         joints matched by name; Ctrl-C holds;
                                         --record: the follower&apos;s goals, for replay;
                                         --norm-mode: as LeRobot maps joints (degrees,
                                         its use_degrees: the default)
  share --link PATH [--record FILE] [--watch] [--duration S]
                                         stand between another program and the servos:
                                         it opens PATH, every byte is forwarded; --json
                                         prints each transaction, --watch reads the
                                         servos in its idle gaps; alerts on stderr
  decode [--family ptk|feetech] HEX...   split bytes into frames and explain each
  decode --family feetech --log FILE     explain a recording of share, frame by frame
  packet ptk query CMD                   print a PTK query frame (CMD: 0x38, 56 or N1..N8)
  packet ptk write NAME=VALUE...         print the PTK write frames carrying these values
  packet feetech INSTRUCTION [--id N] [--addr A] [--data HEX] [--len N] [--ids LIST]
      INSTRUCTION: ping read write reg-write action sync-write sync-read
                   recovery reboot reset calibrate

options: --port PATH (device commands), --baud N (PTK: 115200; Feetech: the servo&apos;s
         rate, 1000000),
         --echo auto|on|off (single-wire adapter echo; default auto)

The overload and thermal guard watches every servo a command drives (identify, and set
while it runs); its warnings and actions are printed on stderr.

exit status: 0 done, 1 device or link failure, 2 usage error (nothing sent)
</source>
        <translation>用法：servoctl [--port PATH] [--baud N] [--json] [--trace] &lt;command&gt; [args]

命令：
  ports                                  列出串口
  detect                                 查明端口上是什么在应答：PTK 舵机
                                         还是 Feetech 总线（及其波特率和舵机）；只发送
                                         查询、PING 和 READ
  doctor [--expect LIST [--baud N]]      指出总线有什么问题以及该怎么做；
                                         LIST：预期的舵机，按串联顺序排列
                                         （1,2,3 或 1-6），波特率为 --baud（1000000）
  ptk read                               读取 PTK 舵机的十三个参数
  ptk write NAME=VALUE...                修改参数（完整流程，写后验证）
  ptk save FILE | ptk load FILE          将舵机保存为配置文件 / 用配置文件编程舵机
  ptk monitor [--duration S] [--csv]     持续轮询，每次完整刷新输出一行
  feetech scan [--baud N|all] [--ids A-B] [--thorough]
                                         查找总线上的舵机（ID 0-253）
  feetech ping --id N                    检查舵机是否应答；显示其型号
  feetech read --id N                    读取舵机的所有寄存器
  feetech get --id N KEY...              读取部分寄存器
  feetech set --id N KEY=VALUE...        写入寄存器（寄存器单位），写后验证
  feetech save --id N FILE               将舵机的 EEPROM 设置保存为配置文件
  feetech load --id N FILE               写入配置文件中与舵机不同的值
  feetech load --ids LIST FILE           对多个舵机执行相同操作（1,2,3 或 1-6）；
                                         FILE 可以是机器人模板：每个舵机按 ID 获得
                                         对应关节的设置；配置文件中的
                                         position_offset 不会被复制；扭矩开启的舵机
                                         将拒绝偏移/限制的更改
  feetech set-id --id N NEW              为舵机设置新 ID（若已被占用则拒绝）
  feetech set-baud --id N BAUD           将舵机改为另一个波特率（bps）
  feetech calibrate-middle --id N        将当前位置设为中位
  feetech factory-reset --id N [--backup FILE]
                                         保存备份配置文件，然后恢复出厂值
  feetech reboot --id N                  重启舵机并等待其恢复
  feetech lock --id N                    关闭未上锁的 EEPROM 锁标志并回读
  feetech recover --id N [--check]       过载保护触发后：关闭再开启扭矩，将目标
                                         设为当前位置，读取过载位；
                                         若仍置位：给出断电重启步骤（退出码 1）；断电
                                         重启后，--check 只读取该位
  feetech setup-motor --id N [--baud BPS] [--model MODEL] [--settings ROBOT]
                                         为总线上唯一的舵机（任意 ID、任意波特率）设置
                                         ID N 和波特率 BPS（默认 1000000，或机器人的
                                         波特率），写后验证；ROBOT：机器人模板文件，
                                         其中 ID 为 N 的关节给出预期的型号
                                         以及要写入并验证的设置
  feetech identify --id N                缓慢摆动舵机，让你看出是哪一个
  feetech health --ids LIST [--move-test]
                                         检查每个舵机：型号和固件，电压和温度是否
                                         在限制之内，状态位，负载，
                                         20 次读取的重试和错误，位置是否在其
                                         限制之内；--move-test 还会让每个无故障的舵机
                                         移动 100 步再返回（上升时间、超调、
                                         稳态误差）；有舵机存在故障时退出码为 1
  feetech check --ids LIST [--robot ROBOT] [--fix]
                                         查找会让舵机无法运动或行为异常的设置：
                                         相位第 4 位（多圈），扭矩限制
                                         或最大扭矩为 0，位置模式以外的运行模式，
                                         角度限制，返回延时，未上锁的 EEPROM，不一致的
                                         固件，电源不满足的电压限制；ROBOT
                                         （so101-follower、... 或模板文件）会加入其
                                         设置；--fix 写入预期值并回读
                                         （限制、偏移、模式、扭矩限制和相位
                                         仅在扭矩关闭时写入）；仍有问题时退出码为 1
  feetech monitor --ids LIST [--rate HZ|max] [--duration S] [--csv]
                                         连续输出位置、速度、负载、电压、
                                         温度和电流（SYNC READ）
  feetech calibrate --ids LIST [--names LIST] [--full-turn LIST] [--duration S]
                    [--dry-run] --out FILE | --update FILE
                                         关闭扭矩，用手记录每个关节的范围
                                         （按 Enter 结束），使其在编码器上居中：写入偏移
                                         和限制，保存 LeRobot 校准文件
                                         （--update：保存到 FILE，保留其中的其他关节）
  feetech calibration save --ids LIST [--names LIST] FILE
                                         将舵机的偏移和限制保存到 LeRobot 文件
  feetech calibration load FILE          写入 LeRobot 校准文件，写后验证
  feetech record --ids LIST --out FILE [--names LIST] [--rate HZ] [--duration S]
                                         记录手动移动的位置（扭矩保持
                                         原样），直到 --duration 结束或按 Ctrl-C：CSV 包含
                                         time_s 及每个关节一列（id_N 或 NAME@N），
                                         单位为步；--rate 为每秒帧数（默认 50）
  feetech replay FILE [--speed X] [--ease S] [--loop N] [--release]
                                         播放记录：若有帧超出舵机的角度限制
                                         则拒绝；在机械臂当前位置开启扭矩，
                                         平缓移动到第一帧（用时 S
                                         秒；默认根据距离确定），再按各帧的
                                         时间播放（--speed 2：两倍速），共 N
                                         遍，之后保持（--release：关闭扭矩）。Ctrl-C
                                         使机械臂保持在当前位置
  feetech teleop --leader PORT --calibration FILE --leader-calibration FILE
                 [--rate HZ] [--duration S] [--max-speed DEG_PER_S] [--record FILE]
                 [--release] [--norm-mode degrees|range_m100_100]
                                         PORT 上的主臂驱动此从臂，
                                         关节按名称对应；Ctrl-C 使其保持；
                                         --record：记录从臂的目标，供回放使用；
                                         --norm-mode：与 LeRobot 相同的关节映射
                                         （degrees，即其 use_degrees：默认）
  share --link PATH [--record FILE] [--watch] [--duration S]
                                         介于另一个程序和舵机之间：该程序打开 PATH，
                                         每个字节都被转发；--json 打印每个事务，
                                         --watch 在其空闲间隙读取舵机；
                                         警报输出到 stderr
  decode [--family ptk|feetech] HEX...   将字节拆分为帧并逐一解释
  decode --family feetech --log FILE     逐帧解释 share 的记录
  packet ptk query CMD                   打印 PTK 查询帧（CMD：0x38、56 或 N1..N8）
  packet ptk write NAME=VALUE...         打印携带这些值的 PTK 写入帧
  packet feetech INSTRUCTION [--id N] [--addr A] [--data HEX] [--len N] [--ids LIST]
      INSTRUCTION: ping read write reg-write action sync-write sync-read
                   recovery reboot reset calibrate

选项：   --port PATH（设备命令），--baud N（PTK：115200；Feetech：舵机的
         波特率，1000000），
         --echo auto|on|off（单线适配器回显；默认 auto）

过载和过热保护会监视命令驱动的每个舵机（identify，以及 set
运行期间）；其警告和动作输出到 stderr。

退出状态：0 完成，1 设备或链路故障，2 用法错误（未发送任何内容）
</translation>
    </message>
    <message>
        <source>ID %1: %2</source>
        <translation>ID %1：%2</translation>
    </message>
</context>
<context>
    <name>servosim</name>
    <message>
        <source>#%1 (ID %2)</source>
        <translation>#%1（ID %2）</translation>
    </message>
    <message>
        <source>no servos</source>
        <translation>没有舵机</translation>
    </message>
    <message>
        <source>%1 takes: %2</source>
        <translation>%1 的用法：%2</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a supply from 0 to 30 V</source>
        <translation>&quot;%1&quot; 不是 0 到 30 V 之间的电源电压</translation>
    </message>
    <message>
        <source>the supply is %1 V</source>
        <translation>电源电压为 %1 V</translation>
    </message>
    <message>
        <source>the daisy chain is whole</source>
        <translation>菊花链完整</translation>
    </message>
    <message>
        <source>%1 has power</source>
        <translation>%1 已通电</translation>
    </message>
    <message>
        <source>%1 has no power</source>
        <translation>%1 已断电</translation>
    </message>
    <message>
        <source>%1 loses power once its EEPROM lock is opened</source>
        <translation>%1 在其 EEPROM 锁打开后即断电</translation>
    </message>
    <message>
        <source>%1 loses power after its next EEPROM write</source>
        <translation>%1 在下一次 EEPROM 写入后断电</translation>
    </message>
    <message>
        <source>the daisy chain is broken after %1</source>
        <translation>菊花链在 %1 之后断开</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a rate from -10 to 10 °C/s</source>
        <translation>&quot;%1&quot; 不是 -10 到 10 °C/s 之间的速率</translation>
    </message>
    <message>
        <source>%1 warms by %2 °C/s</source>
        <translation>%1 以 %2 °C/s 升温</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a temperature from -20 to 120 °C</source>
        <translation>&quot;%1&quot; 不是 -20 到 120 °C 之间的温度</translation>
    </message>
    <message>
        <source>%1 is at %2 °C</source>
        <translation>%1 的温度为 %2 °C</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a load from -1000 to 1000 ‰</source>
        <translation>&quot;%1&quot; 不是 -1000 到 1000 ‰ 之间的负载</translation>
    </message>
    <message>
        <source>%1&apos;s horn is held with a load of %2 ‰</source>
        <translation>%1 的舵盘被 %2 ‰ 的负载顶住</translation>
    </message>
    <message>
        <source>%1&apos;s horn is free</source>
        <translation>%1 的舵盘已释放</translation>
    </message>
    <message>
        <source>%1&apos;s overload is latched until a power cycle</source>
        <translation>%1 的过载已锁存，直到断电重启</translation>
    </message>
    <message>
        <source>no power</source>
        <translation>无电源</translation>
    </message>
    <message>
        <source>horn blocked</source>
        <translation>舵盘卡住</translation>
    </message>
    <message>
        <source>overload latched</source>
        <translation>过载已锁存</translation>
    </message>
    <message>
        <source>heating %1 °C/s</source>
        <translation>加热中 %1 °C/s</translation>
    </message>
    <message>
        <source>cooling %1 °C/s</source>
        <translation>冷却中 %1 °C/s</translation>
    </message>
    <message>
        <source>there is no servo %1: the bus has #1 to #%2</source>
        <translation>没有舵机 %1：总线上为 #1 到 #%2</translation>
    </message>
    <message>
        <source>&quot;%1&quot; names no servo: give an ID (0 to %2) or a place as #N</source>
        <translation>&quot;%1&quot; 未指定任何舵机：请给出 ID（0 到 %2）或位置 #N</translation>
    </message>
    <message>
        <source>commands: turn SERVO POS | sweep SERVO FROM TO SECONDS [CYCLES] [up|down] | release | plug ID:MODEL[@BAUD] | unplug SERVO | set-id SERVO ID | list | power-cycle | power SERVO on|off | break-chain SERVO|none | supply VOLTS | heat SERVO C_PER_S | temperature SERVO C | block SERVO [PERMILLE] | unblock SERVO | latch SERVO | power-cut SERVO after-unlock|after-write | help; SERVO is an ID or a place #N from list</source>
        <translation>命令：turn SERVO POS | sweep SERVO FROM TO SECONDS [CYCLES] [up|down] | release | plug ID:MODEL[@BAUD] | unplug SERVO | set-id SERVO ID | list | power-cycle | power SERVO on|off | break-chain SERVO|none | supply VOLTS | heat SERVO C_PER_S | temperature SERVO C | block SERVO [PERMILLE] | unblock SERVO | latch SERVO | power-cut SERVO after-unlock|after-write | help；SERVO 为 ID 或 list 中的位置 #N</translation>
    </message>
    <message>
        <source>unknown command &quot;%1&quot;: try help</source>
        <translation>未知命令 &quot;%1&quot;：请尝试 help</translation>
    </message>
    <message>
        <source>power-cycled</source>
        <translation>已断电重启</translation>
    </message>
    <message>
        <source>%1 is for a Feetech bus; this is a PTK servo</source>
        <translation>%1 仅适用于 Feetech 总线；这是 PTK 舵机</translation>
    </message>
    <message numerus="yes">
        <source>the hand let go of %n sweep(s)</source>
        <translation>
            <numerusform>手已松开，停止了 %n 个扫动</numerusform>
        </translation>
    </message>
    <message>
        <source>plugged %1: %2 at %3 bps</source>
        <translation>已插入 %1：%2，%3 bps</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a position from 0 to 4095</source>
        <translation>&quot;%1&quot; 不是 0 到 4095 之间的位置</translation>
    </message>
    <message>
        <source>turned %1 to %2</source>
        <translation>已将 %1 转到 %2</translation>
    </message>
    <message>
        <source>until released</source>
        <translation>直到松开</translation>
    </message>
    <message numerus="yes">
        <source>%n time(s)</source>
        <translation>
            <numerusform>%n 次</numerusform>
        </translation>
    </message>
    <message>
        <source>sweeping %1 from %2 to %3 and back every %4 s, %5</source>
        <translation>正在每 %4 秒将 %1 从 %2 扫动到 %3 再返回，%5</translation>
    </message>
    <message>
        <source>unplugged %1</source>
        <translation>已拔出 %1</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not an ID from 0 to %2</source>
        <translation>&quot;%1&quot; 不是 0 到 %2 之间的 ID</translation>
    </message>
    <message>
        <source>servo #%1 is now at ID %2</source>
        <translation>舵机 #%1 现在的 ID 为 %2</translation>
    </message>
    <message>
        <source>name a protocol: ptk or feetech</source>
        <translation>请指定协议：ptk 或 feetech</translation>
    </message>
    <message>
        <source>unknown protocol &quot;%1&quot;: use ptk or feetech</source>
        <translation>未知协议 &quot;%1&quot;：请使用 ptk 或 feetech</translation>
    </message>
    <message>
        <source>--allow-shared-ids is for a Feetech bus</source>
        <translation>--allow-shared-ids 仅适用于 Feetech 总线</translation>
    </message>
    <message>
        <source>unknown option &quot;%1&quot;</source>
        <translation>未知选项 &quot;%1&quot;</translation>
    </message>
    <message>
        <source>%1 needs a value</source>
        <translation>%1 需要一个值</translation>
    </message>
    <message>
        <source>--seed must be a whole number from 0 to 4294967295</source>
        <translation>--seed 必须是 0 到 4294967295 之间的整数</translation>
    </message>
    <message>
        <source>--reply-delay-us must be 0 to 10000000</source>
        <translation>--reply-delay-us 必须为 0 到 10000000</translation>
    </message>
    <message>
        <source>unknown adapter &quot;%1&quot;: use %2</source>
        <translation>未知适配器 &quot;%1&quot;：请使用 %2</translation>
    </message>
    <message>
        <source>--values is for the PTK servo</source>
        <translation>--values 仅适用于 PTK 舵机</translation>
    </message>
    <message>
        <source>--state is for a Feetech bus</source>
        <translation>--state 仅适用于 Feetech 总线</translation>
    </message>
    <message>
        <source>--robot is for a Feetech bus</source>
        <translation>--robot 仅适用于 Feetech 总线</translation>
    </message>
    <message>
        <source>--robot may be given once</source>
        <translation>--robot 只能指定一次</translation>
    </message>
    <message>
        <source>--hand is for a Feetech bus</source>
        <translation>--hand 仅适用于 Feetech 总线</translation>
    </message>
    <message>
        <source>--servo is for a Feetech bus</source>
        <translation>--servo 仅适用于 Feetech 总线</translation>
    </message>
    <message>
        <source>--link PATH is required</source>
        <translation>必须指定 --link PATH</translation>
    </message>
    <message>
        <source>a Feetech bus needs at least one --servo ID:MODEL[@BAUD] or a --robot</source>
        <translation>Feetech 总线至少需要一个 --servo ID:MODEL[@BAUD] 或一个 --robot</translation>
    </message>
    <message>
        <source>%1 &quot;%2&quot; is not ID:MODEL[@BAUD]</source>
        <translation>%1 &quot;%2&quot; 不是 ID:MODEL[@BAUD] 格式</translation>
    </message>
    <message>
        <source>%1 &quot;%2&quot;: ID %3 is over %4</source>
        <translation>%1 &quot;%2&quot;：ID %3 大于 %4</translation>
    </message>
    <message>
        <source>%1 &quot;%2&quot; names no model</source>
        <translation>%1 &quot;%2&quot; 未指定型号</translation>
    </message>
    <message>
        <source>%1 &quot;%2&quot;: bad baud rate</source>
        <translation>%1 &quot;%2&quot;：波特率无效</translation>
    </message>
    <message>
        <source>expected ID FROM TO SECONDS [CYCLES] [up|down]</source>
        <translation>应为 ID FROM TO SECONDS [CYCLES] [up|down]</translation>
    </message>
    <message>
        <source>the ID must be 0 to %1, not &quot;%2&quot;</source>
        <translation>ID 必须为 0 到 %1，而不是 &quot;%2&quot;</translation>
    </message>
    <message>
        <source>FROM and TO must be positions from 0 to 4095</source>
        <translation>FROM 和 TO 必须是 0 到 4095 之间的位置</translation>
    </message>
    <message>
        <source>SECONDS must be a number above 0 and at most %1, not &quot;%2&quot;</source>
        <translation>SECONDS 必须是大于 0 且不超过 %1 的数，而不是 &quot;%2&quot;</translation>
    </message>
    <message>
        <source>CYCLES must be a whole number from 0 (until released) to %1, not &quot;%2&quot;</source>
        <translation>CYCLES 必须是 0（直到松开）到 %1 之间的整数，而不是 &quot;%2&quot;</translation>
    </message>
    <message>
        <source>unknown robot &quot;%1&quot;: use %2</source>
        <translation>未知机器人 &quot;%1&quot;：请使用 %2</translation>
    </message>
    <message>
        <source> (--allow-shared-ids lets them share it, their replies colliding)</source>
        <translation> （--allow-shared-ids 允许它们共用，但它们的应答会冲突）</translation>
    </message>
    <message>
        <source>--hand for ID %1: %2</source>
        <translation>ID %1 的 --hand：%2</translation>
    </message>
    <message>
        <source>usage: servosim ptk --link PATH [--values KEY=V,...] [options]
       servosim feetech --link PATH --servo ID:MODEL[@BAUD] [--servo ...] [--state FILE] [options]
       servosim feetech --link PATH --robot so101 [--servo ...] [options]

Feetech options:
  --servo ID:MODEL[@BAUD]  a servo on the bus (BAUD: the family&apos;s default rate)
  --allow-shared-ids       let two --servo share an ID at one rate (replies collide)
  --robot NAME             a set-up arm from a built-in template, horns at rest:
                           so101, so100 (follower arms), so101-leader, so100-leader
  --hand ID:FROM:TO:SECONDS[:CYCLES][:up|down]
                           the hand sweeps a joint whose torque is off from FROM to
                           TO and back in SECONDS, CYCLES times (0 or none: until
                           released); up or down crosses the 4095/0 seam if needed
  --state FILE             keep the servos&apos; EEPROM in FILE across runs
  --command LINE           a standard-input command run before &quot;ready&quot;, e.g.
                           &quot;break-chain 2&quot;, &quot;supply 12.6&quot;, &quot;block 3&quot; (repeatable)

options:
  --echo                 send every host byte back first (single-wire adapter)
  --faults SPEC          drop=P,corrupt=P,truncate=P,noise=P,delay=MS,lost=P (P: 0-1;
                         lost: a host frame never reaches the servos)
  --seed N               seed of the fault generator (default 1)
  --log FILE             log every frame in and out, hex, timestamped
  --reply-delay-us N     extra delay before every reply
  --adapter PROFILE      deliver replies as a USB adapter does: ideal (the pty&apos;s own
                         timing, the default), instant (the moment a frame is
                         complete, in no wire time), ftdi (16 ms latency timer),
                         ftdi-1ms, ch340, ch343, cp2102

Prints &quot;ready PATH&quot; once a client can open PATH; runs until SIGINT or SIGTERM;
SIGHUP power-cycles the servos. Reads commands on standard input, one a line, and
answers each with one line, &quot;ok ...&quot; or &quot;error ...&quot; (&quot;help&quot; lists them); the
end of standard input does not stop it.
</source>
        <translation>用法： servosim ptk --link PATH [--values KEY=V,...] [options]
       servosim feetech --link PATH --servo ID:MODEL[@BAUD] [--servo ...] [--state FILE] [options]
       servosim feetech --link PATH --robot so101 [--servo ...] [options]

Feetech 选项：
  --servo ID:MODEL[@BAUD]  总线上的一个舵机（BAUD：默认为该系列的默认波特率）
  --allow-shared-ids       允许两个 --servo 在同一波特率下共用一个 ID（应答会冲突）
  --robot NAME             按内置模板设置好的机械臂，舵盘处于静止位置：
                           so101、so100（从臂）、so101-leader、so100-leader
  --hand ID:FROM:TO:SECONDS[:CYCLES][:up|down]
                           手在 SECONDS 秒内将一个扭矩关闭的关节从 FROM 扫动到
                           TO 再返回，共 CYCLES 次（0 或 none：直到
                           松开）；up 或 down 在需要时跨越 4095/0 接缝
  --state FILE             在多次运行之间将舵机的 EEPROM 保存在 FILE 中
  --command LINE           在 &quot;ready&quot; 之前运行的一条标准输入命令，例如
                           &quot;break-chain 2&quot;、&quot;supply 12.6&quot;、&quot;block 3&quot;（可重复指定）

选项：
  --echo                 先将主机发送的每个字节回送（单线适配器）
  --faults SPEC          drop=P,corrupt=P,truncate=P,noise=P,delay=MS,lost=P（P：0-1；
                         lost：主机发出的帧从未到达舵机）
  --seed N               故障生成器的种子（默认 1）
  --log FILE             以十六进制记录每个收发的帧，带时间戳
  --reply-delay-us N     每次应答前的额外延时
  --adapter PROFILE      像 USB 适配器那样传送应答：ideal（pty 自身的
                         时序，默认值）、instant（帧一完整就应答，
                         不计线路时间）、ftdi（16 ms 延迟定时器）、ftdi-1ms、
                         ch340、ch343、cp2102

当客户端可以打开 PATH 时输出 &quot;ready PATH&quot;；一直运行到收到 SIGINT 或 SIGTERM；
SIGHUP 会使舵机断电重启。从标准输入读取命令，每行一条，并
对每条命令回复一行 &quot;ok ...&quot; 或 &quot;error ...&quot;（&quot;help&quot; 会列出所有命令）；
标准输入结束并不会使其停止。
</translation>
    </message>
</context>
<context>
    <name>util</name>
    <message>
        <source>odd number of hex digits in &quot;%1&quot;</source>
        <translation>&quot;%1&quot; 中的十六进制数字个数为奇数</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not hexadecimal</source>
        <translation>&quot;%1&quot; 不是十六进制</translation>
    </message>
    <message>
        <source>not valid JSON: %1 at offset %2</source>
        <translation>不是有效的 JSON：%1（偏移量 %2）</translation>
    </message>
    <message>
        <source>the format version is missing or not a whole number</source>
        <translation>缺少格式版本，或格式版本不是整数</translation>
    </message>
    <message>
        <source>unknown format version %1</source>
        <translation>未知格式版本 %1</translation>
    </message>
    <message>
        <source>unknown entry &quot;%1&quot;</source>
        <translation>未知条目 &quot;%1&quot;</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <source>%1 was not saved: %2</source>
        <translation>%1 未保存：%2</translation>
    </message>
    <message>
        <source>%1; it was not saved</source>
        <translation>%1；未保存</translation>
    </message>
    <message>
        <source>Could not open %1 for writing: %2.</source>
        <translation>无法打开 %1 进行写入：%2。</translation>
    </message>
</context>
</TS>
