<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de_DE">
<context>
    <name>ConnectionBar</name>
    <message>
        <location filename="../../ui/connectionbar.cpp" line="23"/>
        <source>Connection</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/connectionbar.cpp" line="28"/>
        <source>Port </source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/connectionbar.cpp" line="35"/>
        <source>The serial port of the USB programmer, or a simulated servo</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/connectionbar.cpp" line="45"/>
        <source>Baud </source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/connectionbar.cpp" line="52"/>
        <source>PTK servos talk at 115200 baud. On a Feetech bus this is the rate the port opens at; a scan visits the rates it is asked to.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/connectionbar.cpp" line="57"/>
        <source>Protocol </source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/connectionbar.cpp" line="60"/>
        <source>PTK RC servo</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/connectionbar.cpp" line="61"/>
        <source>Feetech bus</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/connectionbar.cpp" line="62"/>
        <source>PTK: one RC servo on a USB programmer. Feetech: SCS, STS, SMS and HLS servos on a serial bus.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/connectionbar.cpp" line="73"/>
        <source>Echo </source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/connectionbar.cpp" line="76"/>
        <source>Auto</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/connectionbar.cpp" line="77"/>
        <source>On</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/connectionbar.cpp" line="78"/>
        <source>Off</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/connectionbar.cpp" line="79"/>
        <source>Single-wire programmers send every byte back. Auto detects it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/connectionbar.cpp" line="83"/>
        <location filename="../../ui/connectionbar.cpp" line="141"/>
        <source>Connect</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/connectionbar.cpp" line="141"/>
        <source>Disconnect</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/connectionbar.cpp" line="168"/>
        <source>Simulated PTK servo</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/connectionbar.cpp" line="169"/>
        <source>Simulated Feetech bus</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>ControlPage</name>
    <message>
        <location filename="../../ui/controlpage.cpp" line="88"/>
        <source>× %1 %2</source>
        <comment>scale and unit of a register value</comment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="232"/>
        <source>Torque</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="238"/>
        <source>Off</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="239"/>
        <source>Torque off: the horn turns freely (torque enable 0).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="240"/>
        <source>On</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="241"/>
        <source>Torque on: the servo holds its goal position (torque enable 1).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="244"/>
        <source>Damping</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="245"/>
        <location filename="../../ui/controlpage.cpp" line="610"/>
        <source>Damping: the horn can be turned by hand against a resistance (torque enable 2).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="270"/>
        <source>Operating mode</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="277"/>
        <source>How the servo uses its goal registers. Stored in EEPROM.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="279"/>
        <source>Set mode…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="280"/>
        <source>Write the chosen operating mode to the servo&apos;s EEPROM.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="303"/>
        <source>Goal position</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="317"/>
        <source>Drag to move the servo: goals are sent as fast as the servo confirms them, always the newest one.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="326"/>
        <location filename="../../ui/controlpage.cpp" line="382"/>
        <location filename="../../ui/controlpage.cpp" line="384"/>
        <source> step</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="327"/>
        <source>Move</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="328"/>
        <source>Send this goal position with the speed and acceleration below.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="334"/>
        <source>Where the horn is: the monitor&apos;s newest sample, or the last read of the present position.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="336"/>
        <source>Goal</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="339"/>
        <source>Present</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="343"/>
        <source>Goal speed, in register units (0: the servo&apos;s maximum).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="346"/>
        <source>Acceleration, in register units (0: the servo&apos;s maximum).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="348"/>
        <location filename="../../ui/controlpage.cpp" line="404"/>
        <source>Speed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="351"/>
        <location filename="../../ui/controlpage.cpp" line="405"/>
        <source>Acceleration</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="373"/>
        <source>Step and sweep tests</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="386"/>
        <source>Goal speed of the test moves (0: the servo&apos;s maximum).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="388"/>
        <source>Acceleration of the test moves (0: the servo&apos;s maximum).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="395"/>
        <source> s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="397"/>
        <source>Step test: how long the response is recorded after the step.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="401"/>
        <source>Sweep: moves between the two positions, to and back counting as two.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="402"/>
        <source>From</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="403"/>
        <source>To</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="406"/>
        <source>Record</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="407"/>
        <source>Sweep legs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="419"/>
        <source>Step test…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="420"/>
        <source>Move to From, then step to To and measure the response.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="421"/>
        <source>Sweep…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="422"/>
        <source>Move back and forth between From and To.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="424"/>
        <source>Stop</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="425"/>
        <source>Stop the running test; the servo holds where it is.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="444"/>
        <source>From 10 % to 90 % of the step.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="446"/>
        <source>How far the peak went beyond the target, as a share of the step.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="449"/>
        <source>From the step command until the position stays within the settling band.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="452"/>
        <source>Target minus the mean position over the last tenth of the recording.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="454"/>
        <source>2 % of the step, at least 2 steps, either side of the target.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="455"/>
        <source>Rise time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="456"/>
        <source>Overshoot</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="457"/>
        <source>Settling time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="458"/>
        <source>Steady-state error</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="459"/>
        <location filename="../../ui/controlpage.cpp" line="489"/>
        <source>Settling band</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="485"/>
        <source>Position (step)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="487"/>
        <source>Target</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="501"/>
        <source>Time since the step (ms)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="578"/>
        <source>Servo ID %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="612"/>
        <source>%1 servos have no damping mode.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="620"/>
        <source>Stored in EEPROM: the servo keeps it when powered off.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="622"/>
        <source>%1 servos have no operating mode register: they hold positions.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="685"/>
        <source>Goals are limited to the servo&apos;s angle limits, %1 to %2 steps.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="688"/>
        <source>The servo has no angle limits (multi-turn) or they are not read yet: goals are limited to the register&apos;s range, %1 to %2.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="720"/>
        <source>Torque state not read yet.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="722"/>
        <source>Off: the horn turns freely.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="724"/>
        <source>On: the servo holds its goal position.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="726"/>
        <source>Damping: the horn resists being turned.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="728"/>
        <source>Torque enable is %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="796"/>
        <source>%1 step</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="821"/>
        <source>Select a servo in the tree to control it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="823"/>
        <source>The bus is not connected: connect and scan to control servos.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="825"/>
        <source>This servo&apos;s model is unknown: ServoBench does not move it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="862"/>
        <source>%1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="911"/>
        <source>No servo is selected.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="912"/>
        <source>The servo cannot be moved now: the bus is not connected or its model is unknown.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="915"/>
        <source>A test is moving %1: stop it first.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="918"/>
        <source>%1 has no goal position register.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="920"/>
        <source>Goal %1 is outside %2, %3 to %4 steps: nothing was sent.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="922"/>
        <source>the servo&apos;s angle limits</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="923"/>
        <source>the goal position range</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="944"/>
        <source>Torque is off: %1 keeps the goal but does not move until torque is on.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="974"/>
        <source>unknown</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="976"/>
        <source>Change the operating mode?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="977"/>
        <source>%1 will change from “%2” to “%3”.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="980"/>
        <source>The servo will move differently from now on: in speed or PWM mode the goal registers make it turn continuously instead of holding a position. The mode is written to EEPROM and kept after power-off.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="983"/>
        <source>Change mode</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="1012"/>
        <source>Writing to servo ID %1 failed: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="1029"/>
        <source>Off: All torque off was sent to every servo.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="1030"/>
        <source>All torque off: torque is off on every servo of the bus.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="1051"/>
        <source>The horn of %1 will move to %2, then step to %3 and hold there.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="1055"/>
        <source>The horn of %1 will move to %2, then sweep %3 times between %2 and %4.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="1060"/>
        <source>The servo will move</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="1062"/>
        <source>Keep hands, cables and other parts clear of the horn, and detach any load it could damage or be damaged by. Stop or All torque off halts it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="1065"/>
        <source>Move the servo</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="1109"/>
        <source>Step test done: %1 samples over %2 s.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="1116"/>
        <source>Sweep done: %1 of %2 legs reached their goal.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="1121"/>
        <source>A leg took %1 ms on average.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="1127"/>
        <source>Stopped: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="1149"/>
        <source>No test run yet for this servo.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="1156"/>
        <location filename="../../ui/controlpage.cpp" line="1162"/>
        <source>%1 ms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="1157"/>
        <source>did not reach 90 % of the step</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="1159"/>
        <source>%1 %</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="1163"/>
        <source>did not settle within %1 s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="1167"/>
        <source>%1 steps</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/controlpage.cpp" line="1169"/>
        <source>± %1 steps</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>Decoder</name>
    <message numerus="yes">
        <location filename="../../core/cli/decoder.cpp" line="35"/>
        <source>incomplete frame (%n byte(s))</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../../core/cli/decoder.cpp" line="36"/>
        <source>%n byte(s) that are not part of any frame</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <location filename="../../core/cli/decoder.cpp" line="103"/>
        <source>query %1 (command %2) asks for %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/decoder.cpp" line="111"/>
        <source>write %1 (command %2) %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/decoder.cpp" line="113"/>
        <source>with zero payload</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/decoder.cpp" line="117"/>
        <source>request with unknown command %1, payload %2 %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/decoder.cpp" line="128"/>
        <source>reply to %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/decoder.cpp" line="133"/>
        <source>reply (query unknown): words %1, %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/decoder.cpp" line="145"/>
        <source>ID %1 (broadcast)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/decoder.cpp" line="146"/>
        <source>ID %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/decoder.cpp" line="172"/>
        <source>status from %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/decoder.cpp" line="174"/>
        <source>no error</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/decoder.cpp" line="175"/>
        <source>error %1 (%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/decoder.cpp" line="178"/>
        <source>, data %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/decoder.cpp" line="192"/>
        <source>address %1 (%2), length %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/decoder.cpp" line="200"/>
        <source>address %1 (%2), data %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/decoder.cpp" line="213"/>
        <source>address %1 (%2), length %3, IDs %4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/decoder.cpp" line="225"/>
        <source>ID %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/decoder.cpp" line="228"/>
        <source>address %1 (%2), length %3; %4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/decoder.cpp" line="237"/>
        <source>current position becomes the middle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/decoder.cpp" line="238"/>
        <source>current position becomes %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/decoder.cpp" line="242"/>
        <source>parameters %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>DemoServos</name>
    <message>
        <location filename="../../core/sim/demoservos.cpp" line="26"/>
        <source>Cannot create a folder for the simulated servos: %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>Faults</name>
    <message>
        <location filename="../../core/sim/faults.cpp" line="27"/>
        <source>--faults: &quot;%1&quot; is not NAME=VALUE</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/sim/faults.cpp" line="32"/>
        <source>--faults: &quot;%1&quot; is not a number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/sim/faults.cpp" line="35"/>
        <source>--faults: delay is in milliseconds, 0 to 60000</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/sim/faults.cpp" line="40"/>
        <source>--faults: %1 is a probability from 0 to 1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/sim/faults.cpp" line="51"/>
        <source>--faults: unknown fault &quot;%1&quot; (drop, corrupt, truncate, noise, delay)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>FeetechBusClient</name>
    <message>
        <location filename="../../core/feetech/busclient.cpp" line="135"/>
        <location filename="../../core/feetech/busclient.cpp" line="342"/>
        <location filename="../../core/feetech/busclient.cpp" line="517"/>
        <location filename="../../core/feetech/busclient.cpp" line="628"/>
        <source>The bus is not connected.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/busclient.cpp" line="137"/>
        <location filename="../../core/feetech/busclient.cpp" line="337"/>
        <location filename="../../core/feetech/busclient.cpp" line="526"/>
        <location filename="../../core/feetech/busclient.cpp" line="589"/>
        <location filename="../../core/feetech/busclient.cpp" line="636"/>
        <source>No servo is selected.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/busclient.cpp" line="139"/>
        <location filename="../../core/feetech/busclient.cpp" line="489"/>
        <location filename="../../core/feetech/busclient.cpp" line="500"/>
        <source>Another operation is still running.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/busclient.cpp" line="141"/>
        <source>This servo&apos;s model is unknown; its memory is shown read-only.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/busclient.cpp" line="301"/>
        <location filename="../../core/feetech/busclient.cpp" line="434"/>
        <source>ID %1 is already in use on this bus.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/busclient.cpp" line="319"/>
        <location filename="../../core/feetech/busclient.cpp" line="402"/>
        <location filename="../../core/feetech/busclient.cpp" line="594"/>
        <source>Nothing to write.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/busclient.cpp" line="465"/>
        <source>This servo has no middle calibration (SCS servos have no offset register).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/busclient.cpp" line="519"/>
        <source>Choose at least one servo to monitor.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/busclient.cpp" line="521"/>
        <source>The rate cannot be negative.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/busclient.cpp" line="529"/>
        <source>Servo %1 is of an unknown model: its feedback cannot be decoded.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/busclient.cpp" line="630"/>
        <source>Nothing to move.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/busclient.cpp" line="640"/>
        <source>Servo %1 is of an unknown model; nothing is written to it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/busclient.cpp" line="645"/>
        <source>Servo %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>FeetechParameters</name>
    <message>
        <location filename="../../core/feetech/servoparameters.cpp" line="31"/>
        <source>Other EEPROM</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/servoparameters.cpp" line="31"/>
        <source>Other RAM</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/servoparameters.cpp" line="58"/>
        <source>Identity and link</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/servoparameters.cpp" line="61"/>
        <source>Travel and mode</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/servoparameters.cpp" line="65"/>
        <source>Control loop</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/servoparameters.cpp" line="71"/>
        <source>Limits and protection</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/servoparameters.cpp" line="129"/>
        <source>%1 is not a writable register of %2.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/servoparameters.cpp" line="135"/>
        <location filename="../../core/feetech/servoparameters.cpp" line="185"/>
        <source>%1 = %2 is out of range (%3 to %4).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/servoparameters.cpp" line="145"/>
        <source>%1 = %2 does not fit the register.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/servoparameters.cpp" line="166"/>
        <source>baud_rate: %1 bps is not a Feetech baud rate.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/servoparameters.cpp" line="180"/>
        <source>%1: &quot;%2&quot; is not a whole number.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/servoparameters.cpp" line="205"/>
        <source>bit %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/servoparameters.cpp" line="207"/>
        <source>none</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>FeetechSession</name>
    <message numerus="yes">
        <location filename="../../core/feetech/feetechsession.cpp" line="43"/>
        <source>no reply after %n attempt(s)</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="45"/>
        <source>the port is closed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="47"/>
        <source>cancelled</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="276"/>
        <source>Disconnected.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="289"/>
        <source>%1 Reconnecting when it comes back.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="304"/>
        <source>%1 is back. Scan again if servos were changed while it was away.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="342"/>
        <location filename="../../core/feetech/feetechsession.cpp" line="345"/>
        <source>Not connected.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="429"/>
        <location filename="../../core/feetech/feetechtelemetry.cpp" line="139"/>
        <source>The port cannot be set to %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="455"/>
        <source>%1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="467"/>
        <source>The servo&apos;s model has no known EEPROM lock register.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="470"/>
        <source>Locking the EEPROM</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="470"/>
        <source>Unlocking the EEPROM</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="492"/>
        <source>Reading %1 bytes at address %2: %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="520"/>
        <source>Reading the identity of servo %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="545"/>
        <source>Servo %1 does not answer.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="547"/>
        <source>ID %1 is already in use on this bus.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="599"/>
        <source>servo %1 at %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <location filename="../../core/feetech/feetechsession.cpp" line="632"/>
        <source>Scan cancelled; %n servo(s) found before.</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../../core/feetech/feetechsession.cpp" line="636"/>
        <source>Scan complete: %n servo(s) found.</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="644"/>
        <source>%1 is not a Feetech baud rate.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="790"/>
        <source>unknown (identity unreadable)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="830"/>
        <source>Servo %1 answers.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="831"/>
        <source>Servo %1 does not answer: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="856"/>
        <source>Read %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="871"/>
        <source>Servo %1 is of an unknown model; its memory is shown read-only and nothing is written to it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="884"/>
        <source>The ID and the baud rate change how the servo is reached; use Change ID or Change baud rate.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="901"/>
        <source>The EEPROM lock is opened and closed by ServoBench around each EEPROM write; it is not written by hand.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="904"/>
        <source>Torque enable 128 recalibrates the middle; use Calibrate middle.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="930"/>
        <source>Writing address %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="941"/>
        <source>Written and read back.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="961"/>
        <source>Servo %1 is of an unknown model; its ID is not changed.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="963"/>
        <source>ID %1 is out of range (0 to %2).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="965"/>
        <source>The servo already has ID %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="968"/>
        <source>ID %1 is already in use on this bus; nothing was written.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="993"/>
        <source>Servo %1 now answers as ID %2.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="1009"/>
        <source>The servo still has its old ID.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="1024"/>
        <source>Servo %1 is of an unknown model; its baud rate is not changed.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="1029"/>
        <source>%1 is not a baud rate this servo supports.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="1031"/>
        <source>The servo already runs at %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="1053"/>
        <source>The servo reports baud code %1 instead of %2.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="1065"/>
        <source>Servo %1 now runs at %2 and answers there.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="1084"/>
        <source>It still answers at %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="1086"/>
        <source>It answers at neither rate; scan all baud rates to find it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="1104"/>
        <source>Middle calibration is not available on this servo (SCS servos have no offset register).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="1114"/>
        <location filename="../../core/feetech/feetechsession.cpp" line="1118"/>
        <source>Middle calibration</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="1124"/>
        <source>The present position is now the middle.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="1143"/>
        <source>Servo %1 is of an unknown model; it is not reset.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="1151"/>
        <source>Factory reset</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="1168"/>
        <source>Factory values restored; servo %1 answers at %2.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="1186"/>
        <source>Servo %1 answers at no baud rate; scan the bus to find it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="1208"/>
        <source>Torque off</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="1210"/>
        <source>Reboot</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="1236"/>
        <source>Servo %1 restarted and answers again after %2 ms.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="1244"/>
        <source>Servo %1 has not answered within %2 ms of the restart.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="1263"/>
        <source>Clearing the status</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="1269"/>
        <source>Status of servo %1 cleared.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechtelemetry.cpp" line="255"/>
        <source>SYNC READ at %1: no answer from ID %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechtelemetry.cpp" line="322"/>
        <source>%1 answers again; it is back in the cycle.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechtelemetry.cpp" line="339"/>
        <source>%1 stopped answering; it is left out of the cycle and asked alone every %2 ms until it answers.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechtelemetry.cpp" line="423"/>
        <source>Torque off at %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechtelemetry.cpp" line="439"/>
        <source>%1 did not confirm (no reply).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechtelemetry.cpp" line="446"/>
        <source>%1 still has torque on.</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <location filename="../../core/feetech/feetechtelemetry.cpp" line="457"/>
        <source>Torque off: sent to the whole bus; %n servo(s) confirmed it.</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechtelemetry.cpp" line="459"/>
        <source>Torque off was sent to the whole bus, but: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechtelemetry.cpp" line="478"/>
        <source>The SYNC WRITE does not fit in one packet.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechtelemetry.cpp" line="485"/>
        <source>SYNC WRITE at %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <location filename="../../core/feetech/feetechtelemetry.cpp" line="490"/>
        <source>Sent to %n servo(s) in one SYNC WRITE.</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
</context>
<context>
    <name>FeetechTelemetry</name>
    <message>
        <location filename="../../core/feetech/telemetry.cpp" line="66"/>
        <source>Position</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/telemetry.cpp" line="68"/>
        <source>Speed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/telemetry.cpp" line="70"/>
        <source>Load</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/telemetry.cpp" line="72"/>
        <source>Voltage</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/telemetry.cpp" line="74"/>
        <source>Temperature</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/telemetry.cpp" line="76"/>
        <source>Current</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/telemetry.cpp" line="137"/>
        <source>none</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/telemetry.cpp" line="169"/>
        <source>Line %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/telemetry.cpp" line="174"/>
        <source>not a ServoBench telemetry recording (unexpected header)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/telemetry.cpp" line="183"/>
        <source>%1 cells instead of %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/telemetry.cpp" line="188"/>
        <source>the time is not a number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/telemetry.cpp" line="191"/>
        <source>the ID is not a servo ID</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/telemetry.cpp" line="199"/>
        <source>%1 is not a number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/telemetry.cpp" line="204"/>
        <source>the status is not a byte</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/telemetry.cpp" line="207"/>
        <source>moving is neither 0 nor 1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>FeetechWorkspace</name>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="73"/>
        <source>Scan…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="74"/>
        <source>Look for servos on the bus: choose IDs and baud rates</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="75"/>
        <source>Cancel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="75"/>
        <source>Stop the scan</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="83"/>
        <source>%v of %m IDs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="86"/>
        <source>Connect, then scan to find the servos.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="94"/>
        <source>Servo</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="94"/>
        <source>Model</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="94"/>
        <source>Family</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="94"/>
        <source>Firmware</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="101"/>
        <source>All torque off  (Esc)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="102"/>
        <source>Switch the torque of every servo on the bus off at once, ahead of anything else (also: Esc, from any page)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="130"/>
        <source>Change ID…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="131"/>
        <source>Give the servo another ID; an ID in use is refused</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="133"/>
        <source>Change baud rate…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="134"/>
        <source>Move the servo to another baud rate and follow it there</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="135"/>
        <source>Calibrate middle…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="136"/>
        <location filename="../../ui/feetechworkspace.cpp" line="501"/>
        <source>Make the horn&apos;s present position the middle (2048)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="137"/>
        <source>Factory reset…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="138"/>
        <source>Restore factory values (the ID is kept), after saving a backup profile</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="142"/>
        <source>Reboot</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="143"/>
        <source>Torque off, restart the servo and wait until it answers again</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="144"/>
        <source>Clear status</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="145"/>
        <source>Reset the servo&apos;s error status (instruction 0x0A)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="159"/>
        <source>The settings changed most, in real units. &lt;b&gt;EEPROM&lt;/b&gt; values are written with the lock opened and closed again and survive power-off. Changing the ID or the baud rate asks first, then follows the servo.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="163"/>
        <source>Settings</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="171"/>
        <source>Filter registers</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="173"/>
        <source>Refresh RAM live</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="176"/>
        <source>Read the RAM registers (present position, load, voltage…) several times a second while this table is shown</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="201"/>
        <source>Read</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="201"/>
        <source>Read every register of the servo</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="202"/>
        <source>Revert</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="202"/>
        <source>Drop every edit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="203"/>
        <source>Apply</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="204"/>
        <source>Write the edited registers, then read them back</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="213"/>
        <source>Memory table</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="215"/>
        <source>Control</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="217"/>
        <source>Monitor</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="219"/>
        <source>Joints</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="241"/>
        <source>Restarting the servo…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="243"/>
        <source>Clearing the status…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="274"/>
        <source>Working…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="284"/>
        <source>Scanning at %1…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="339"/>
        <source>Connect to the bus before scanning.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="360"/>
        <source>Bus</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="371"/>
        <source>unknown</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="373"/>
        <source>ID %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="377"/>
        <source>Model number %1 (major %2, minor %3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="383"/>
        <source>No register table is known for this model: its memory is shown as raw bytes, read-only.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="447"/>
        <source>servo %1 (%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="455"/>
        <source>Choose a servo in the tree.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="456"/>
        <source>No servo yet: connect to the bus and scan.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="462"/>
        <source>unknown family</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="463"/>
        <source>status not read yet</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="466"/>
        <source>status OK</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="467"/>
        <source>&lt;span style=&apos;color:#b3261e&apos;&gt;status: %1&lt;/span&gt;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="470"/>
        <source>&lt;b&gt;ID %1 · %2&lt;/b&gt; &amp;nbsp; model %3 · %4 family · firmware %5 · %6 · %7</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="480"/>
        <source>No register table is known for this model, so nothing is guessed: the Memory table shows its raw bytes, read-only.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="502"/>
        <source>SCS servos have no offset register: not available</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="536"/>
        <source>its ID from %1 to %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="538"/>
        <source>its baud rate from %1 to %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="542"/>
        <source>Change how the servo is reached?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="543"/>
        <source>This changes %1.&lt;br&gt;&lt;br&gt;ServoBench writes it to EEPROM with the lock opened and closed again, then finds the servo at its new address and confirms it there. Other programs and robot code must use the new address afterwards.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="546"/>
        <source> and </source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="553"/>
        <source>Nothing was written: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="577"/>
        <source>Change ID</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="578"/>
        <source>New ID for %1 (IDs found on this bus: %2).
An ID in use is refused.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="584"/>
        <source>ID %1 is already in use on this bus; nothing was written.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="603"/>
        <source>Change baud rate</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="604"/>
        <source>New baud rate for %1 (now %2). ServoBench follows the servo to the new rate and confirms it there.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="618"/>
        <source>Calibrate middle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="619"/>
        <source>The horn&apos;s present position becomes the middle (2048) of %1. Turn the horn to where the middle should be first; the new offset is stored in EEPROM.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="624"/>
        <source>Calibrating the middle…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="638"/>
        <location filename="../../ui/feetechworkspace.cpp" line="648"/>
        <source>Factory reset</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="639"/>
        <source>First save a backup profile of %1; the reset only starts once it is saved.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="649"/>
        <source>Backup saved to %1.&lt;br&gt;&lt;br&gt;Restore the factory values of %2? Everything but the ID returns to what the servo left the factory with, possibly including its baud rate; ServoBench looks for it at every rate afterwards.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="655"/>
        <source>Restoring factory values…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="684"/>
        <source>Choose a servo first.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="690"/>
        <source>Saved %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="697"/>
        <source>Only a servo of a known model can be saved as a profile.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="722"/>
        <source>Choose a servo of a known model first.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="726"/>
        <source>Wait for the running operation to finish before loading a profile.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="738"/>
        <source>The servo already holds every value of this profile</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="743"/>
        <source>Profile loaded as edits: review them, then Apply</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>JointTable</name>
    <message>
        <location filename="../../ui/jointtable.cpp" line="138"/>
        <source>Read positions</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/jointtable.cpp" line="139"/>
        <source>Read every servo&apos;s registers now: positions, limits and torque</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/jointtable.cpp" line="148"/>
        <source>ID</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/jointtable.cpp" line="148"/>
        <source>Model</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/jointtable.cpp" line="148"/>
        <source>Baud rate</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/jointtable.cpp" line="149"/>
        <source>Position (steps)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/jointtable.cpp" line="149"/>
        <source>Target (steps)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/jointtable.cpp" line="150"/>
        <source>Target range</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/jointtable.cpp" line="150"/>
        <source>Torque</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/jointtable.cpp" line="150"/>
        <source>Motion</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/jointtable.cpp" line="155"/>
        <source>Present position: live while the monitor watches the servo, otherwise the last value read (grey)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/jointtable.cpp" line="158"/>
        <source>Where Move all sends the servo: double-click or type to change it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/jointtable.cpp" line="160"/>
        <source>The servo&apos;s angle limits, or the goal register&apos;s range when the limits are unknown or both 0</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/jointtable.cpp" line="162"/>
        <source>Tick to switch torque on, untick to switch it off</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/jointtable.cpp" line="163"/>
        <source>Whether the servo reports that it is moving</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/jointtable.cpp" line="183"/>
        <source>Targets from present positions</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/jointtable.cpp" line="184"/>
        <source>Copy every servo&apos;s present position into its target</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/jointtable.cpp" line="186"/>
        <source>Load pose…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/jointtable.cpp" line="187"/>
        <source>Fill the targets from a pose file; nothing moves until Move all</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/jointtable.cpp" line="188"/>
        <source>Save pose…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/jointtable.cpp" line="188"/>
        <source>Save the targets as a pose file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/jointtable.cpp" line="193"/>
        <source>Move all</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/jointtable.cpp" line="194"/>
        <source>Send every target at once: one SYNC WRITE per baud rate</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/jointtable.cpp" line="255"/>
        <source>Targets only move servos when you press Move all.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/jointtable.cpp" line="363"/>
        <source>ID %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/jointtable.cpp" line="364"/>
        <source>ID %1 (%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/jointtable.cpp" line="444"/>
        <source>%1 family, firmware %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/jointtable.cpp" line="446"/>
        <source>Unknown model: it cannot be moved from here</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/jointtable.cpp" line="463"/>
        <source>Switching on…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/jointtable.cpp" line="463"/>
        <source>Switching off…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/jointtable.cpp" line="466"/>
        <source>Unknown</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/jointtable.cpp" line="468"/>
        <source>Off</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/jointtable.cpp" line="470"/>
        <source>On</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/jointtable.cpp" line="474"/>
        <source>Damping</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/jointtable.cpp" line="506"/>
        <source>Live, from the monitor</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/jointtable.cpp" line="507"/>
        <source>Last value read: it may be stale</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/jointtable.cpp" line="508"/>
        <source>Not read yet</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/jointtable.cpp" line="512"/>
        <source>Moving</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/jointtable.cpp" line="512"/>
        <source>Still</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/jointtable.cpp" line="542"/>
        <source>Unknown model: no goal register</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/jointtable.cpp" line="545"/>
        <source>%1 to %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/jointtable.cpp" line="547"/>
        <source>From the servo&apos;s angle limits</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/jointtable.cpp" line="548"/>
        <source>The goal register&apos;s range: the angle limits are not read yet or both 0</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/jointtable.cpp" line="559"/>
        <source>Outside the range %1 to %2: Move all will refuse it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/jointtable.cpp" line="563"/>
        <source>No target yet: type one, load a pose or take the present position</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/jointtable.cpp" line="578"/>
        <source>Scan the bus to list its servos here.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/jointtable.cpp" line="581"/>
        <source>&lt;b&gt;Live positions:&lt;/b&gt; the monitor is not running, so positions are the last values read (grey) and may be stale. Start the monitor to see live positions, or read them now.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/jointtable.cpp" line="585"/>
        <source>&lt;b&gt;Live positions&lt;/b&gt; from the monitor; servos it does not watch show the last value read, in grey.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/jointtable.cpp" line="588"/>
        <source>&lt;b&gt;Live positions&lt;/b&gt; from the monitor.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/jointtable.cpp" line="610"/>
        <source>Pose: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/jointtable.cpp" line="633"/>
        <source>Move all failed: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/jointtable.cpp" line="645"/>
        <source>%1: torque was not switched %2: %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/jointtable.cpp" line="646"/>
        <location filename="../../ui/jointtable.cpp" line="690"/>
        <source>on</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/jointtable.cpp" line="646"/>
        <location filename="../../ui/jointtable.cpp" line="690"/>
        <source>off</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/jointtable.cpp" line="682"/>
        <source>That servo is no longer on the bus.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/jointtable.cpp" line="689"/>
        <source>%1: torque not switched %2: %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/jointtable.cpp" line="713"/>
        <source>Targets set to the present positions of %1 servos.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/jointtable.cpp" line="716"/>
        <source>Targets set for %1 servos. No position is known yet for %2: read the positions first.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/jointtable.cpp" line="719"/>
        <location filename="../../ui/jointtable.cpp" line="784"/>
        <location filename="../../ui/jointtable.cpp" line="786"/>
        <location filename="../../ui/jointtable.cpp" line="790"/>
        <location filename="../../ui/jointtable.cpp" line="792"/>
        <location filename="../../ui/jointtable.cpp" line="879"/>
        <location filename="../../ui/jointtable.cpp" line="885"/>
        <location filename="../../ui/jointtable.cpp" line="891"/>
        <source>, </source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/jointtable.cpp" line="732"/>
        <source>The bus is not connected: nothing was sent.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/jointtable.cpp" line="734"/>
        <location filename="../../ui/jointtable.cpp" line="807"/>
        <source>No servos: scan the bus first.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/jointtable.cpp" line="750"/>
        <source>%1 has no target: type one, load a pose or use “Targets from present positions”. Nothing was sent.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/jointtable.cpp" line="754"/>
        <source>%1: the target %2 is outside its range %3 to %4. Nothing was sent.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/jointtable.cpp" line="763"/>
        <source>%1 is in %2 mode; a goal position only moves a servo in position mode. Nothing was sent.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/jointtable.cpp" line="776"/>
        <source>No servo here can be moved: their models are unknown.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/jointtable.cpp" line="779"/>
        <source>Nothing was sent: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/jointtable.cpp" line="784"/>
        <source>Targets sent to IDs %1 in one SYNC WRITE.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/jointtable.cpp" line="785"/>
        <source>Targets sent to IDs %1 in %2 SYNC WRITEs, one per baud rate.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/jointtable.cpp" line="789"/>
        <source>Torque is off on %1: it will not move until torque is on.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/jointtable.cpp" line="792"/>
        <source>Not moved (unknown model): %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/jointtable.cpp" line="802"/>
        <source>The bus is not connected.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/jointtable.cpp" line="815"/>
        <source>Reading %1 servos…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/jointtable.cpp" line="829"/>
        <source>No targets to save: set some first.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/jointtable.cpp" line="836"/>
        <source>Saved the pose “%1” with %2 targets to %3.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/jointtable.cpp" line="871"/>
        <source>Loaded the pose “%1”: %2 targets filled. Nothing moves until you press Move all.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/jointtable.cpp" line="878"/>
        <source>ID %1 at %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/jointtable.cpp" line="879"/>
        <source>Not on the bus: %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/jointtable.cpp" line="885"/>
        <source>Not in the pose (targets unchanged): %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/jointtable.cpp" line="891"/>
        <source>Outside their range (shown in red): %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/jointtable.cpp" line="922"/>
        <source>pose.json</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/jointtable.cpp" line="923"/>
        <source>Save pose</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/jointtable.cpp" line="924"/>
        <location filename="../../ui/jointtable.cpp" line="938"/>
        <source>ServoBench poses (*.json);;All files (*)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/jointtable.cpp" line="938"/>
        <source>Load pose</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>MainWindow</name>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="58"/>
        <source>ServoBench</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="107"/>
        <location filename="../../ui/mainwindow.cpp" line="335"/>
        <source>Not connected</source>
        <translation>Nicht verbunden</translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="132"/>
        <source>Read all parameters</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="134"/>
        <source>Read failed: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="162"/>
        <source>&amp;File</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="163"/>
        <source>&amp;Load profile…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="165"/>
        <source>&amp;Save profile…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="168"/>
        <source>&amp;Quit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="172"/>
        <source>&amp;Link</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="173"/>
        <source>&amp;Poll the servo</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="177"/>
        <source>Keep reading the eight queries so the values stay live</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="180"/>
        <source>&amp;Fast polling (queries back to back)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="188"/>
        <source>&amp;Scan the Feetech bus…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="194"/>
        <source>Disconnect from the PTK servo before scanning a Feetech bus.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="203"/>
        <source>All &amp;torque off</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="207"/>
        <source>Switch the torque of every servo on the Feetech bus off</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="212"/>
        <source>Torque off: sent to every servo…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="216"/>
        <source>&amp;View</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="220"/>
        <source>&amp;Help</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="221"/>
        <source>&amp;About ServoBench</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="223"/>
        <source>About &amp;Qt</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="228"/>
        <source>About ServoBench</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="229"/>
        <source>&lt;p&gt;&lt;b&gt;ServoBench %1&lt;/b&gt;&lt;/p&gt;&lt;p&gt;Programs and monitors PTK RC servos and Feetech serial-bus servos on Linux, Windows and macOS.&lt;/p&gt;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="290"/>
        <source>Choose a serial port first.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="302"/>
        <source>The simulated servos could not start: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="459"/>
        <source>Wait for the running read or Apply to finish before loading a profile.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="489"/>
        <source>Some changes have not been written to the servos. Quit anyway?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="305"/>
        <source>simulated PTK servo</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="305"/>
        <source>simulated Feetech bus</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="309"/>
        <source>Enter a baud rate.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="338"/>
        <source>Connecting to %1…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="341"/>
        <source>Open: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="342"/>
        <source>Connected: %1 at %2 baud</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="345"/>
        <source>No reply on %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="348"/>
        <source>Disconnected: %1 went away, waiting for it to return</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="370"/>
        <source>sent %1 · ok %2 · checksum errors %3 · timeouts %4 · retries %5 · discarded %6 B</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="386"/>
        <source>%1 queries/s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="394"/>
        <source>Nothing was written: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="397"/>
        <source>Writing N1…N12, then reading back…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="409"/>
        <source>The servo did not take every value: the fields marked Mismatch hold something else than was written.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="412"/>
        <source>Written and verified</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="441"/>
        <source>Saved %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="469"/>
        <source>The servo already holds every value of this profile</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="475"/>
        <source>Profile loaded as edits: review them, then Apply</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="488"/>
        <source>Unapplied changes</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>MonitorPage</name>
    <message>
        <location filename="../../ui/monitorpage.cpp" line="87"/>
        <source>Servos</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/monitorpage.cpp" line="91"/>
        <source>The servos to stream; ticking or unticking one while streaming restarts the stream</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/monitorpage.cpp" line="98"/>
        <source>Plot</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/monitorpage.cpp" line="105"/>
        <source>Plot the %1 in %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/monitorpage.cpp" line="116"/>
        <source>Stream</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/monitorpage.cpp" line="120"/>
        <source>Samples per second for each servo</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/monitorpage.cpp" line="122"/>
        <source>%1 Hz</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/monitorpage.cpp" line="123"/>
        <source>As fast as the bus allows</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/monitorpage.cpp" line="126"/>
        <source>Rate:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/monitorpage.cpp" line="128"/>
        <location filename="../../ui/monitorpage.cpp" line="749"/>
        <source>Start</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/monitorpage.cpp" line="129"/>
        <source>Start or stop streaming the ticked servos&apos; feedback</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/monitorpage.cpp" line="137"/>
        <source>View</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/monitorpage.cpp" line="141"/>
        <source>How many seconds of history the plot shows</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/monitorpage.cpp" line="143"/>
        <source>%1 s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/monitorpage.cpp" line="146"/>
        <source>Window:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/monitorpage.cpp" line="148"/>
        <location filename="../../ui/monitorpage.cpp" line="754"/>
        <source>Pause</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/monitorpage.cpp" line="149"/>
        <source>Freeze the plot; samples are still received and recorded</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/monitorpage.cpp" line="152"/>
        <source>Reset zoom</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/monitorpage.cpp" line="153"/>
        <source>Back to the live view over the whole window</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/monitorpage.cpp" line="160"/>
        <source>Export PNG…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/monitorpage.cpp" line="161"/>
        <source>Save the charts as they are shown as one PNG image</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/monitorpage.cpp" line="166"/>
        <source>Recording</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/monitorpage.cpp" line="169"/>
        <location filename="../../ui/monitorpage.cpp" line="758"/>
        <source>Record CSV…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/monitorpage.cpp" line="170"/>
        <source>Write every sample of the ticked servos to a CSV file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/monitorpage.cpp" line="201"/>
        <source>Servo</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/monitorpage.cpp" line="204"/>
        <source>%1 (%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/monitorpage.cpp" line="206"/>
        <source>Moving</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/monitorpage.cpp" line="206"/>
        <source>Status</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/monitorpage.cpp" line="206"/>
        <source>Samples/s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/monitorpage.cpp" line="206"/>
        <source>Missed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/monitorpage.cpp" line="206"/>
        <source>State</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/monitorpage.cpp" line="209"/>
        <source>The servo&apos;s protection bits that tripped (register 65)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/monitorpage.cpp" line="211"/>
        <source>Cycles in which the servo was asked and did not answer</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/monitorpage.cpp" line="343"/>
        <source>There is no bus to monitor.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/monitorpage.cpp" line="345"/>
        <source>Tick at least one servo to monitor.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/monitorpage.cpp" line="367"/>
        <source>Monitoring did not start: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/monitorpage.cpp" line="397"/>
        <source>No file name was given for the recording.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/monitorpage.cpp" line="400"/>
        <source>Could not open %1 for writing: %2.</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <location filename="../../ui/monitorpage.cpp" line="434"/>
        <source>%Ln row(s) saved to %1.</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <location filename="../../ui/monitorpage.cpp" line="446"/>
        <source>Plot saved to %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/monitorpage.cpp" line="504"/>
        <source>—</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/monitorpage.cpp" line="517"/>
        <source>ID %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/monitorpage.cpp" line="523"/>
        <source>yes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/monitorpage.cpp" line="523"/>
        <source>no</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/monitorpage.cpp" line="535"/>
        <source>Not answering</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/monitorpage.cpp" line="538"/>
        <location filename="../../ui/monitorpage.cpp" line="772"/>
        <source>Stopped</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/monitorpage.cpp" line="540"/>
        <source>Waiting</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/monitorpage.cpp" line="542"/>
        <source>OK</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/monitorpage.cpp" line="572"/>
        <source>ID %1 at %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/monitorpage.cpp" line="604"/>
        <source>unknown model</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/monitorpage.cpp" line="606"/>
        <source>ID %1 · %2 · %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/monitorpage.cpp" line="619"/>
        <source>Unknown model: its feedback cannot be decoded</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/monitorpage.cpp" line="624"/>
        <source>Scan the bus to find servos.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/monitorpage.cpp" line="680"/>
        <source>Recording stopped: the bus was disconnected.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/monitorpage.cpp" line="702"/>
        <source>Export plot</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/monitorpage.cpp" line="703"/>
        <source>PNG images (*.png)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/monitorpage.cpp" line="716"/>
        <source>Record telemetry</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/monitorpage.cpp" line="718"/>
        <source>CSV files (*.csv)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/monitorpage.cpp" line="729"/>
        <source>Monitoring stopped: no servo is ticked.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/monitorpage.cpp" line="749"/>
        <source>Stop</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/monitorpage.cpp" line="754"/>
        <source>Resume</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/monitorpage.cpp" line="758"/>
        <source>Stop recording</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/monitorpage.cpp" line="767"/>
        <source>Streaming · %1 cycles/s · %2 samples/s · %3 missed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/monitorpage.cpp" line="775"/>
        <source> · plot paused (samples are still received)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/monitorpage.cpp" line="784"/>
        <source>Not recording.</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <location filename="../../ui/monitorpage.cpp" line="787"/>
        <source>Recording to %1: %Ln row(s).</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../../ui/monitorpage.cpp" line="811"/>
        <source>Recording to %1 failed after %Ln row(s): %2</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <location filename="../../ui/monitorpage.cpp" line="813"/>
        <source>Recording failed.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/monitorpage.cpp" line="860"/>
        <source>none</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>PacketLogDock</name>
    <message>
        <location filename="../../ui/packetlogdock.cpp" line="68"/>
        <source>Packet log</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/packetlogdock.cpp" line="93"/>
        <source>Pause</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/packetlogdock.cpp" line="96"/>
        <source>Freeze the log to read it; frames arriving meanwhile are kept and appear when you resume</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/packetlogdock.cpp" line="102"/>
        <source>Clear</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/packetlogdock.cpp" line="104"/>
        <source>Remove every frame from the log and reset the counts</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/packetlogdock.cpp" line="108"/>
        <source>Export…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/packetlogdock.cpp" line="110"/>
        <source>Save the frames shown to a tab-separated text file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/packetlogdock.cpp" line="115"/>
        <source>Errors only</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/packetlogdock.cpp" line="118"/>
        <source>Show only frames with an error (bad checksum, timeout, unexpected bytes)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/packetlogdock.cpp" line="153"/>
        <source>Direction</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/packetlogdock.cpp" line="153"/>
        <source>→ out</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/packetlogdock.cpp" line="205"/>
        <source>%1, %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <location filename="../../ui/packetlogdock.cpp" line="205"/>
        <source>%n frame(s)</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../../ui/packetlogdock.cpp" line="206"/>
        <source>%n error(s)</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <location filename="../../ui/packetlogdock.cpp" line="208"/>
        <source>%1 (paused)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/packetlogdock.cpp" line="211"/>
        <source>New frames are kept while paused and appear when you resume</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <location filename="../../ui/packetlogdock.cpp" line="213"/>
        <source>The log keeps the newest %n frame(s); older ones were dropped</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <location filename="../../ui/packetlogdock.cpp" line="225"/>
        <location filename="../../ui/packetlogdock.cpp" line="231"/>
        <source>Export packet log</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/packetlogdock.cpp" line="226"/>
        <source>Tab-separated text (*.tsv *.txt);;All files (*)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>ParameterPage</name>
    <message>
        <location filename="../../ui/parameterpage.cpp" line="170"/>
        <source>Load profile…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/parameterpage.cpp" line="171"/>
        <source>Load parameter values from a profile file as edits</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/parameterpage.cpp" line="172"/>
        <source>Save profile…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/parameterpage.cpp" line="173"/>
        <source>Save the servo&apos;s parameter values to a profile file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/parameterpage.cpp" line="174"/>
        <source>Read</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/parameterpage.cpp" line="174"/>
        <source>Read every parameter from the servo</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/parameterpage.cpp" line="175"/>
        <source>Revert</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/parameterpage.cpp" line="176"/>
        <source>Drop every edit and show the servo&apos;s values again</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/parameterpage.cpp" line="177"/>
        <source>Apply</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/parameterpage.cpp" line="178"/>
        <source>Write the edited parameters to the servo, then read them back to verify</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/parameterpage.cpp" line="190"/>
        <source>%v of %m</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/parameterpage.cpp" line="239"/>
        <source>&lt;b&gt;Device&lt;/b&gt; is what the servo reports. Edits are written only when you press &lt;b&gt;Apply&lt;/b&gt;, then read back and verified.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/parameterpage.cpp" line="289"/>
        <location filename="../../ui/parameterpage.cpp" line="348"/>
        <source>Device</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/parameterpage.cpp" line="290"/>
        <source>New value</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/parameterpage.cpp" line="291"/>
        <source>State</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/parameterpage.cpp" line="312"/>
        <source>EEPROM</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/parameterpage.cpp" line="318"/>
        <source>Kept in the servo&apos;s EEPROM: written with the lock opened and closed again, and kept after power-off</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/parameterpage.cpp" line="402"/>
        <source>%1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/parameterpage.cpp" line="402"/>
        <source> or </source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/parameterpage.cpp" line="428"/>
        <source>%1: %2 to %3%4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/parameterpage.cpp" line="480"/>
        <source>Refused</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/parameterpage.cpp" line="520"/>
        <location filename="../../ui/parameterpage.cpp" line="577"/>
        <location filename="../../ui/parameterpage.cpp" line="580"/>
        <source>—</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/parameterpage.cpp" line="521"/>
        <source>Not read from the servo yet</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/parameterpage.cpp" line="529"/>
        <source>Changed here; written to the servo when you press Apply</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/parameterpage.cpp" line="533"/>
        <source>Being written to the servo</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/parameterpage.cpp" line="537"/>
        <source>Written and read back with the same value</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/parameterpage.cpp" line="541"/>
        <source>The value read back differs from the value written</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/parameterpage.cpp" line="545"/>
        <source>The write did not go out; the edit is kept so you can try again</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>Pose</name>
    <message>
        <location filename="../../core/feetech/pose.cpp" line="62"/>
        <source>not a JSON object</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/pose.cpp" line="68"/>
        <source>unknown entry &quot;%1&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/pose.cpp" line="73"/>
        <source>&quot;%1&quot; is missing</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/pose.cpp" line="82"/>
        <source>&quot;%1&quot;: %2 is not a servo ID (0 to %3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/pose.cpp" line="92"/>
        <source>&quot;%1&quot;: %2 is not a Feetech baud rate in bps</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/pose.cpp" line="101"/>
        <source>&quot;%1&quot;: %2 is not an integer number of steps</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/pose.cpp" line="106"/>
        <source>&quot;%1&quot;: %2 is out of range (%3 to %4)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/pose.cpp" line="177"/>
        <source>&quot;%1&quot; must be text</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/pose.cpp" line="182"/>
        <source>the pose has no &quot;%1&quot; list</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/pose.cpp" line="190"/>
        <source>servo entry %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/pose.cpp" line="193"/>
        <source>servo entry %1: ID %2 at %3 bps is already in the pose</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/pose.cpp" line="219"/>
        <source>too large to be a pose</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>Profile</name>
    <message>
        <location filename="../../core/profile/profile.cpp" line="89"/>
        <source>expected true or false</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/profile/profile.cpp" line="96"/>
        <source>expected a number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/profile/profile.cpp" line="105"/>
        <source>%1 is out of range (%2 to %3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/profile/profile.cpp" line="113"/>
        <source>%1 is not a whole number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/profile/profile.cpp" line="114"/>
        <source>%1 is not a multiple of %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/profile/profile.cpp" line="188"/>
        <location filename="../../core/profile/profile.cpp" line="257"/>
        <source>unknown parameter &quot;%1&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/profile/profile.cpp" line="200"/>
        <source>%1: the raw value %2 cannot be kept in a profile</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/profile/profile.cpp" line="226"/>
        <source>the profile names no servo family</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/profile/profile.cpp" line="229"/>
        <source>the profile is for &quot;%1&quot; servos, not &quot;%2&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/profile/profile.cpp" line="232"/>
        <location filename="../../core/profile/profile.cpp" line="234"/>
        <location filename="../../core/profile/profile.cpp" line="237"/>
        <source>&quot;%1&quot; must be text</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/profile/profile.cpp" line="241"/>
        <source>&quot;%1&quot;: &quot;%2&quot; is not an ISO 8601 date and time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/profile/profile.cpp" line="247"/>
        <source>the profile has no &quot;%1&quot; object</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/profile/profile.cpp" line="266"/>
        <source>%1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/profile/profile.cpp" line="282"/>
        <source>too large to be a profile</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>ProfileActions</name>
    <message>
        <location filename="../../ui/profileactions.cpp" line="30"/>
        <source>Save profile</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/profileactions.cpp" line="32"/>
        <location filename="../../ui/profileactions.cpp" line="38"/>
        <source>ServoBench profiles (*.json)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/profileactions.cpp" line="37"/>
        <source>Load profile</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/profileactions.cpp" line="49"/>
        <source>Read the servo before saving a profile: not every value is known.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/profileactions.cpp" line="65"/>
        <source>The profile was not loaded: %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>ProfileDiffDialog</name>
    <message>
        <location filename="../../ui/profilediffdialog.cpp" line="31"/>
        <source>Load profile</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <location filename="../../ui/profilediffdialog.cpp" line="34"/>
        <source>%n parameter(s) in %1 differ from the servo. Loading makes them edits; nothing is written until you press Apply.</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <location filename="../../ui/profilediffdialog.cpp" line="43"/>
        <source>Parameter</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/profilediffdialog.cpp" line="43"/>
        <source>On the servo</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/profilediffdialog.cpp" line="43"/>
        <source>In the file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/profilediffdialog.cpp" line="54"/>
        <source>not read</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/profilediffdialog.cpp" line="62"/>
        <source>Load as edits</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>PseudoTerminal</name>
    <message>
        <location filename="../../core/sim/pseudoterminal.cpp" line="57"/>
        <source>cannot open a pseudo-terminal: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/sim/pseudoterminal.cpp" line="61"/>
        <source>cannot unlock the pseudo-terminal: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/sim/pseudoterminal.cpp" line="65"/>
        <source>cannot name the pseudo-terminal&apos;s slave</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/sim/pseudoterminal.cpp" line="85"/>
        <source>cannot replace the old link %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/sim/pseudoterminal.cpp" line="89"/>
        <source>%1 exists and is not a symlink; choose another --link path</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/sim/pseudoterminal.cpp" line="92"/>
        <source>cannot create the link %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>PtkClient</name>
    <message>
        <location filename="../../core/ptk/ptkclient.cpp" line="108"/>
        <source>The servo is not connected.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/ptk/ptkclient.cpp" line="110"/>
        <source>A read or write is already running.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/ptk/ptkclient.cpp" line="112"/>
        <source>There are no changes to apply.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/ptk/ptkclient.cpp" line="115"/>
        <source>%1 has not been read yet.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>PtkSession</name>
    <message>
        <location filename="../../core/ptk/ptksession.cpp" line="117"/>
        <source>Disconnected during Apply; the servo may hold only part of the new values.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/ptk/ptksession.cpp" line="120"/>
        <source>Disconnected during the read.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/ptk/ptksession.cpp" line="219"/>
        <location filename="../../core/ptk/ptksession.cpp" line="281"/>
        <source>Not connected.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/ptk/ptksession.cpp" line="223"/>
        <location filename="../../core/ptk/ptksession.cpp" line="285"/>
        <source>Busy: a read or write is already running.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/ptk/ptksession.cpp" line="243"/>
        <source>No answer to the query for %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/ptk/ptksession.cpp" line="248"/>
        <source>Written, but not verified. %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/ptk/ptksession.cpp" line="264"/>
        <source>The link went down before the values could be read back.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/ptk/ptksession.cpp" line="267"/>
        <source>The link went down.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/ptk/ptksession.cpp" line="293"/>
        <source>%1 has not been read yet; nothing was written.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/ptk/ptksession.cpp" line="301"/>
        <source>%1; nothing was written.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/ptk/ptksession.cpp" line="331"/>
        <source>The link went down while writing %1; the servo may hold only part of the new values.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/ptk/ptksession.cpp" line="353"/>
        <source>The port is open but the servo does not answer. Check that it is powered and plugged into the programmer.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/ptk/ptksession.cpp" line="375"/>
        <source>The link went down during Apply: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/ptk/ptksession.cpp" line="380"/>
        <source>%1 Reconnecting when it comes back.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>RegisterTable</name>
    <message>
        <location filename="../../core/feetech/registertable.cpp" line="80"/>
        <source>not valid JSON at offset %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/registertable.cpp" line="86"/>
        <source>the document is not a JSON object</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/registertable.cpp" line="91"/>
        <source>unsupported &quot;format&quot; (expected 1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/registertable.cpp" line="117"/>
        <source>register &quot;%1&quot; (address %2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/registertable.cpp" line="126"/>
        <source>unknown field &quot;%1&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/registertable.cpp" line="129"/>
        <source>the key must be snake_case</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/registertable.cpp" line="131"/>
        <source>the address must be a whole number from 0 to 255</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/registertable.cpp" line="135"/>
        <source>the size must be 1 or 2 bytes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/registertable.cpp" line="138"/>
        <source>the register runs past address 255</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/registertable.cpp" line="141"/>
        <source>the label is missing</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/registertable.cpp" line="149"/>
        <source>storage must be &quot;eeprom&quot; or &quot;ram&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/registertable.cpp" line="156"/>
        <source>access must be &quot;ro&quot; or &quot;rw&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/registertable.cpp" line="160"/>
        <source>the unit must be a string</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/registertable.cpp" line="164"/>
        <source>the scale must be a positive number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/registertable.cpp" line="170"/>
        <source>the sign bit must lie inside the register</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/registertable.cpp" line="181"/>
        <source>min and max must be whole numbers</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/registertable.cpp" line="185"/>
        <source>min is greater than max</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/registertable.cpp" line="187"/>
        <source>the range %1..%2 does not fit a %3-byte register</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/registertable.cpp" line="196"/>
        <source>the default does not fit the register</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/registertable.cpp" line="205"/>
        <source>a choice needs a value that fits the register and a label</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/registertable.cpp" line="214"/>
        <source>a bit needs an index inside the register and a label</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/registertable.cpp" line="248"/>
        <source>unknown family &quot;%1&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/registertable.cpp" line="259"/>
        <source>byte_order must be &quot;little&quot; or &quot;big&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/registertable.cpp" line="265"/>
        <source>there are no registers</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/registertable.cpp" line="272"/>
        <source>every register must be a JSON object</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/registertable.cpp" line="278"/>
        <source>the key &quot;%1&quot; is used twice</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/registertable.cpp" line="290"/>
        <source>registers &quot;%1&quot; and &quot;%2&quot; overlap at address %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/registertable.cpp" line="366"/>
        <source>families_by_major: &quot;%1&quot; is not a major number with a family</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/registertable.cpp" line="382"/>
        <source>model &quot;%1&quot;: needs a name and major and minor numbers 0-255</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/registertable.cpp" line="392"/>
        <source>model &quot;%1&quot;: unknown family</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/registertable.cpp" line="397"/>
        <source>model %1/%2 is listed twice</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/registertable.cpp" line="431"/>
        <source>%1 (model %2/%3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/registertable.cpp" line="432"/>
        <source>Unknown model %1/%2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/registertable.cpp" line="461"/>
        <source>Raw bytes (unknown model)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/registertable.cpp" line="466"/>
        <source>Byte %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/registertable.cpp" line="506"/>
        <source>%1 Mbps</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/registertable.cpp" line="507"/>
        <source>%L1 bps</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>RegisterTableModel</name>
    <message>
        <location filename="../../ui/registertablemodel.cpp" line="139"/>
        <source>%1 to %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/registertablemodel.cpp" line="141"/>
        <source> (× %1 %2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/registertablemodel.cpp" line="145"/>
        <source>On the servo: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/registertablemodel.cpp" line="168"/>
        <source>EEPROM</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/registertablemodel.cpp" line="168"/>
        <source>RAM</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/registertablemodel.cpp" line="170"/>
        <source>RW</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/registertablemodel.cpp" line="170"/>
        <source>RO</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/registertablemodel.cpp" line="173"/>
        <location filename="../../ui/registertablemodel.cpp" line="182"/>
        <source>—</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/registertablemodel.cpp" line="208"/>
        <source>%1: &quot;%2&quot; is not a number.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/registertablemodel.cpp" line="236"/>
        <source>Addr</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/registertablemodel.cpp" line="238"/>
        <source>Key</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/registertablemodel.cpp" line="240"/>
        <source>Register</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/registertablemodel.cpp" line="242"/>
        <source>Size</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/registertablemodel.cpp" line="244"/>
        <source>Area</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/registertablemodel.cpp" line="246"/>
        <source>Access</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/registertablemodel.cpp" line="248"/>
        <source>Raw</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/registertablemodel.cpp" line="250"/>
        <source>Value</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/registertablemodel.cpp" line="252"/>
        <source>State</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>RequestEngine</name>
    <message>
        <location filename="../../core/link/requestengine.cpp" line="155"/>
        <source>stray input discarded before a request</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/link/requestengine.cpp" line="218"/>
        <source>late reply, discarded</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/link/requestengine.cpp" line="219"/>
        <source>received while no request was waiting</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/link/requestengine.cpp" line="268"/>
        <source>unexpected frame, ignored</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/link/requestengine.cpp" line="275"/>
        <source>bad checksum</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/link/requestengine.cpp" line="281"/>
        <source>bytes that form no frame</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/link/requestengine.cpp" line="309"/>
        <source>no reply (attempt %1 of %2)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>ScanDialog</name>
    <message>
        <location filename="../../ui/scandialog.cpp" line="20"/>
        <source>Scan the bus</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/scandialog.cpp" line="24"/>
        <source>Servo IDs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/scandialog.cpp" line="34"/>
        <source>From</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/scandialog.cpp" line="36"/>
        <source>to</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/scandialog.cpp" line="41"/>
        <source>Baud rates</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/scandialog.cpp" line="45"/>
        <source>%L1 bps</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/scandialog.cpp" line="53"/>
        <source>All</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/scandialog.cpp" line="54"/>
        <source>None</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/scandialog.cpp" line="67"/>
        <source>Skip baud rates where nothing answers a broadcast PING</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/scandialog.cpp" line="70"/>
        <source>Every servo answers a broadcast PING. When no byte at all comes back at a rate, no servo listens there and its IDs need not be asked one by one. Turn off to ask every ID regardless.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/scandialog.cpp" line="83"/>
        <source>Scan</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/scandialog.cpp" line="114"/>
        <source>Choose at least one baud rate.</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <location filename="../../ui/scandialog.cpp" line="117"/>
        <source>%n ID(s) at %1 baud rate(s). Missing IDs cost a few milliseconds each: the wait adapts to how fast the servos answer.</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
</context>
<context>
    <name>SerialLink</name>
    <message>
        <location filename="../../core/link/transport.cpp" line="131"/>
        <source>%1 does not exist. Is the adapter plugged in?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/link/transport.cpp" line="134"/>
        <source>Permission denied on %1. Either another program has it open, or you are not in the group that may use serial ports: run &quot;sudo usermod -aG dialout $USER&quot;, then log out and back in.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/link/transport.cpp" line="139"/>
        <source>Permission denied on %1: another program may have it open.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/link/transport.cpp" line="142"/>
        <source>%1 is already open.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/link/transport.cpp" line="144"/>
        <source>%1 is not open.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/link/transport.cpp" line="146"/>
        <source>Could not write to %1 (%2).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/link/transport.cpp" line="148"/>
        <source>Could not read from %1 (%2).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/link/transport.cpp" line="150"/>
        <source>%1 went away: the adapter was unplugged or the device closed.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/link/transport.cpp" line="153"/>
        <source>%1 does not support this setting (%2).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/link/transport.cpp" line="155"/>
        <source>%1 timed out.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/link/transport.cpp" line="159"/>
        <source>%1: %2</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>SimLog</name>
    <message>
        <location filename="../../core/sim/simlog.cpp" line="15"/>
        <source>cannot write the log %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>TelemetryPlot</name>
    <message>
        <location filename="../../ui/telemetryplot.cpp" line="334"/>
        <source>There is nothing to export: choose at least one quantity to plot.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/telemetryplot.cpp" line="336"/>
        <source>No file name was given for the image.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/telemetryplot.cpp" line="343"/>
        <source>The plot could not be drawn into an image (it has no size).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/telemetryplot.cpp" line="346"/>
        <source>Could not save the plot to %1: %2.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/telemetryplot.cpp" line="471"/>
        <source>%1 (%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/telemetryplot.cpp" line="501"/>
        <source>Drag across a time span to zoom in, right-click to zoom out, or turn the wheel; Reset zoom goes back to live data</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/telemetryplot.cpp" line="508"/>
        <source>Time (s)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/telemetryplot.cpp" line="546"/>
        <source>ID %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/telemetryplot.cpp" line="547"/>
        <source>ID %1 · %2</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>Tr</name>
    <message>
        <location filename="../../core/cli/ptkcommands.cpp" line="456"/>
        <source>--echo must be auto, on or off</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/pose.cpp" line="127"/>
        <source>not a ServoBench pose (the document is not a JSON object)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/pose.cpp" line="128"/>
        <source>not a ServoBench pose (&quot;%1&quot; is not &quot;%2&quot;)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/pose.cpp" line="129"/>
        <source>the pose has format version %1 and was written by a newer ServoBench; this version reads format version %2 and older</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/profile/profile.cpp" line="138"/>
        <source>not a ServoBench profile (the document is not a JSON object)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/profile/profile.cpp" line="139"/>
        <source>not a ServoBench profile (&quot;%1&quot; is not &quot;%2&quot;)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/profile/profile.cpp" line="140"/>
        <source>the profile has format version %1 and was written by a newer ServoBench; this version reads format version %2 and older</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>VirtualFeetechBus</name>
    <message>
        <location filename="../../core/sim/virtualfeetechbus.cpp" line="88"/>
        <source>a Feetech bus needs at least one servo</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/sim/virtualfeetechbus.cpp" line="95"/>
        <source>servo %1: model %2 has no register table to simulate</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/sim/virtualfeetechbus.cpp" line="98"/>
        <source>servo %1: unknown model &quot;%2&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/sim/virtualfeetechbus.cpp" line="101"/>
        <source>servo ID %1 is out of range: IDs are 0 to %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/sim/virtualfeetechbus.cpp" line="107"/>
        <source>servo %1: %2 bps is not a Feetech baud rate (%3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/sim/virtualfeetechbus.cpp" line="112"/>
        <source>two servos have ID %1 at %2 bps</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/sim/virtualfeetechbus.cpp" line="301"/>
        <location filename="../../core/sim/virtualfeetechbus.cpp" line="307"/>
        <source>cannot write the state file %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/sim/virtualfeetechbus.cpp" line="317"/>
        <source>state file %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/sim/virtualfeetechbus.cpp" line="326"/>
        <source>not valid JSON (%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/sim/virtualfeetechbus.cpp" line="329"/>
        <source>not a format %1 simulator state</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/sim/virtualfeetechbus.cpp" line="333"/>
        <source>it holds %1 servos, the bus has %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/sim/virtualfeetechbus.cpp" line="341"/>
        <source>servo %1 is a %2 in the file but a %3 on the bus</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/sim/virtualfeetechbus.cpp" line="346"/>
        <source>servo %1: the EEPROM image is not %2 hex bytes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/sim/virtualfeetechbus.cpp" line="356"/>
        <source>servo %1: the EEPROM image is of model %2/%3, not %4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/sim/virtualfeetechbus.cpp" line="364"/>
        <source>servo %1: the EEPROM image holds an invalid ID or baud code</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>feetech</name>
    <message>
        <location filename="../../core/feetech/feetechpacket.cpp" line="155"/>
        <source>voltage</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechpacket.cpp" line="155"/>
        <source>encoder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechpacket.cpp" line="156"/>
        <source>temperature</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechpacket.cpp" line="156"/>
        <source>current</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechpacket.cpp" line="157"/>
        <source>angle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechpacket.cpp" line="157"/>
        <source>overload</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechpacket.cpp" line="158"/>
        <source>bit 6</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechpacket.cpp" line="158"/>
        <source>bit 7</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>feetech::MotionTest</name>
    <message>
        <location filename="../../core/feetech/motiontest.cpp" line="63"/>
        <source>All torque off: the test was stopped.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/motiontest.cpp" line="66"/>
        <source>%1 is no longer on the bus: the test was stopped.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/motiontest.cpp" line="89"/>
        <source>A test is already running.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/motiontest.cpp" line="91"/>
        <source>The bus is not connected.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/motiontest.cpp" line="93"/>
        <source>No servo is selected.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/motiontest.cpp" line="96"/>
        <source>This servo&apos;s model is unknown: ServoBench does not move it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/motiontest.cpp" line="100"/>
        <source>This servo has no goal position register.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/motiontest.cpp" line="103"/>
        <source>Servo ID %1 is not in position mode: set its operating mode to position first.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/motiontest.cpp" line="108"/>
        <source>the servo&apos;s angle limits</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/motiontest.cpp" line="108"/>
        <source>the goal position range</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/motiontest.cpp" line="109"/>
        <source>From (%1) and to (%2) must lie within %3, %4 to %5 steps.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/motiontest.cpp" line="118"/>
        <source>From and to must be more than %1 steps apart.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/motiontest.cpp" line="123"/>
        <source>%1 must lie between %2 and %3.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/motiontest.cpp" line="130"/>
        <source>The recording must last more than 0 and at most %1 seconds.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/motiontest.cpp" line="133"/>
        <source>A sweep has 1 to %1 legs.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/motiontest.cpp" line="196"/>
        <source>The test was stopped.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/motiontest.cpp" line="206"/>
        <source>Servo ID %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/motiontest.cpp" line="214"/>
        <source>%1 is no longer on the bus.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/motiontest.cpp" line="283"/>
        <source>Moving to the start position %1…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/motiontest.cpp" line="348"/>
        <source>Step to %1: recording for %2 s…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/motiontest.cpp" line="357"/>
        <source>Too few position samples arrived during the recording (%1): does %2 answer?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/motiontest.cpp" line="363"/>
        <source>Step test done.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/motiontest.cpp" line="381"/>
        <source>Sweep leg %1 of %2: moving to %3…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/motiontest.cpp" line="393"/>
        <source>Sweep done: %1 of %2 legs reached their goal.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/motiontest.cpp" line="407"/>
        <source>No position samples arrived from %1: is it answering?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/motiontest.cpp" line="411"/>
        <source>%1 did not settle at %2 within %3 s; going on from %4.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/motiontest.cpp" line="445"/>
        <source>Writing to %1 failed: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/motiontest.cpp" line="452"/>
        <source>The bus was disconnected: the test was stopped.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <location filename="../../app/servobench.cpp" line="25"/>
        <source>Programmer and live monitor for PTK and Feetech servos</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../app/servobench.cpp" line="30"/>
        <source>Start the simulated servos and connect to the PTK servo (the Feetech bus is in the port list).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../app/servobench.cpp" line="35"/>
        <source>Start the simulated servos, connect to the Feetech bus and scan it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../app/servobench.cpp" line="39"/>
        <source>Connect to PORT at start.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>model::ParameterModel</name>
    <message>
        <location filename="../../core/model/parametermodel.cpp" line="79"/>
        <source>unknown parameter &quot;%1&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/model/parametermodel.cpp" line="82"/>
        <source>%1 is read-only</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/model/parametermodel.cpp" line="85"/>
        <source>%1 must be between %2 and %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/model/parametermodel.cpp" line="170"/>
        <source>Edited</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/model/parametermodel.cpp" line="172"/>
        <source>Writing</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/model/parametermodel.cpp" line="174"/>
        <source>Verified</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/model/parametermodel.cpp" line="176"/>
        <source>Mismatch</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/model/parametermodel.cpp" line="178"/>
        <source>Failed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/model/parametermodel.cpp" line="246"/>
        <source>%1: %2 to %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/model/parametermodel.cpp" line="261"/>
        <source>Key</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/model/parametermodel.cpp" line="263"/>
        <source>Parameter</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/model/parametermodel.cpp" line="265"/>
        <source>Device</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/model/parametermodel.cpp" line="267"/>
        <source>Edit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/model/parametermodel.cpp" line="269"/>
        <source>Unit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/model/parametermodel.cpp" line="271"/>
        <source>State</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>ptk</name>
    <message>
        <location filename="../../core/ptk/ptkparameters.cpp" line="15"/>
        <source>Gain</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/ptk/ptkparameters.cpp" line="16"/>
        <source>Damping</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/ptk/ptkparameters.cpp" line="18"/>
        <source>Deadband</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/ptk/ptkparameters.cpp" line="20"/>
        <source>Neutral</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/ptk/ptkparameters.cpp" line="22"/>
        <source>Minimum angle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/ptk/ptkparameters.cpp" line="24"/>
        <source>Maximum angle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/ptk/ptkparameters.cpp" line="26"/>
        <source>Minimum pulse width</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/ptk/ptkparameters.cpp" line="28"/>
        <source>Maximum pulse width</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/ptk/ptkparameters.cpp" line="30"/>
        <source>Inversion</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/ptk/ptkparameters.cpp" line="32"/>
        <source>Maximum power</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/ptk/ptkparameters.cpp" line="34"/>
        <source>Overload protection power</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/ptk/ptkparameters.cpp" line="36"/>
        <source>Overload protection time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/ptk/ptkparameters.cpp" line="38"/>
        <source>Soft start</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/ptk/ptkparameters.cpp" line="119"/>
        <source>Off</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/ptk/ptkparameters.cpp" line="120"/>
        <source>On</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/ptk/ptkparameters.cpp" line="138"/>
        <source>&quot;%1&quot; is not NAME=VALUE</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/ptk/ptkparameters.cpp" line="146"/>
        <source>unknown parameter &quot;%1&quot; (known: %2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/ptk/ptkparameters.cpp" line="162"/>
        <source>%1: &quot;%2&quot; is not a number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/ptk/ptkparameters.cpp" line="175"/>
        <source>Response</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/ptk/ptkparameters.cpp" line="177"/>
        <source>Travel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/ptk/ptkparameters.cpp" line="179"/>
        <source>Power</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/ptk/ptkparameters.cpp" line="242"/>
        <source>%1 must be between %2 and %3%4</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>seriallink::PacketLogModel</name>
    <message>
        <location filename="../../core/link/packetlogmodel.cpp" line="152"/>
        <source>The log could not be written.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/link/packetlogmodel.cpp" line="177"/>
        <location filename="../../core/link/packetlogmodel.cpp" line="184"/>
        <location filename="../../core/link/packetlogmodel.cpp" line="189"/>
        <source>Cannot write %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/link/packetlogmodel.cpp" line="199"/>
        <source>→ out</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/link/packetlogmodel.cpp" line="201"/>
        <source>← in</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/link/packetlogmodel.cpp" line="203"/>
        <source>echo</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/link/packetlogmodel.cpp" line="205"/>
        <source>stray</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <location filename="../../core/link/packetlogmodel.cpp" line="244"/>
        <source>%n byte(s)</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <location filename="../../core/link/packetlogmodel.cpp" line="268"/>
        <source>Time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/link/packetlogmodel.cpp" line="270"/>
        <source>Direction</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/link/packetlogmodel.cpp" line="272"/>
        <source>Bytes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/link/packetlogmodel.cpp" line="274"/>
        <source>Meaning</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/link/packetlogmodel.cpp" line="276"/>
        <source>Error</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>servoctl</name>
    <message>
        <location filename="../../core/cli/arguments.cpp" line="37"/>
        <source>--%1 takes no value</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/arguments.cpp" line="42"/>
        <source>--%1 needs a value</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/arguments.cpp" line="47"/>
        <source>unknown option --%1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/arguments.cpp" line="56"/>
        <source>--%1: &quot;%2&quot; is not a number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/arguments.cpp" line="58"/>
        <source>--%1: %2 is out of range (%3 to %4)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/arguments.cpp" line="92"/>
        <source>--ids: &quot;%1&quot; is not an ID</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/arguments.cpp" line="94"/>
        <source>--ids: ID %1 is over %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/arguments.cpp" line="103"/>
        <source>--ids: the range %1 runs backwards</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/arguments.cpp" line="111"/>
        <source>--ids needs at least one ID</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/ptkcommands.cpp" line="82"/>
        <source>ptk commands need --port PATH (see servoctl ports)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="54"/>
        <source>%1 bps</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="86"/>
        <source>unknown model, raw bytes only</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="87"/>
        <source>servo %1 at %2: %3 (%4), firmware %5</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="153"/>
        <source>feetech commands need --port PATH (see servoctl ports)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="171"/>
        <source>%1 could not be opened</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="183"/>
        <source>%1 (at %2; servoctl feetech scan --baud all looks at every rate)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="196"/>
        <source>servo %1 answers PING but its identity (addresses 0-8) could not be read: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="247"/>
        <location filename="../../core/cli/ptkcommands.cpp" line="173"/>
        <source>the servo did not finish in time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="306"/>
        <source>feetech needs a command (try servoctl --help)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="332"/>
        <source>unknown feetech command &quot;%1&quot;: use %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="365"/>
        <source>%1 takes no arguments</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="366"/>
        <source>%1 needs %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="383"/>
        <source>%1: &quot;%2&quot; is not a Feetech baud rate (%3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="390"/>
        <source>%1 needs --id N</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="445"/>
        <source>--ids: a scan covers one range of IDs, such as 0-20</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="459"/>
        <source>id</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="460"/>
        <source>baud</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="461"/>
        <source>model</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="462"/>
        <source>number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="463"/>
        <source>family</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="464"/>
        <source>firmware</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="494"/>
        <source>no servo answered (try --baud all, or check power and wiring)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="513"/>
        <source>%1; answered in %2 ms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="546"/>
        <source>no register table is known for this model: the bytes are shown as they are, and nothing can be written</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="550"/>
        <source>addr</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="551"/>
        <source>key</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="552"/>
        <source>value</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="553"/>
        <source>meaning</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="570"/>
        <source>%1 needs the register KEYs to read</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="573"/>
        <source>%1: &quot;%2&quot; is not a register key</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="585"/>
        <location filename="../../core/cli/feetechcommands.cpp" line="711"/>
        <source>%1 servos have no register &quot;%2&quot; (servoctl feetech read lists them)</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <location filename="../../core/cli/feetechcommands.cpp" line="662"/>
        <source>written to servo %1 and verified: %n register(s)</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="678"/>
        <source>%1 needs KEY=VALUE arguments</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="683"/>
        <source>&quot;%1&quot; is not KEY=VALUE</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="686"/>
        <source>the ID changes how the servo is reached: use servoctl feetech set-id --id N NEW</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="689"/>
        <source>the baud rate changes how the servo is reached: use servoctl feetech set-baud --id N BAUD</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="693"/>
        <source>%1 is given twice</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="703"/>
        <location filename="../../core/cli/feetechcommands.cpp" line="844"/>
        <source>servo %1 is of an unknown model (%2); nothing is written to it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="715"/>
        <source>%1 is read-only</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="751"/>
        <source>%1 = %2 is outside its range (%3 to %4) and is left out of the profile</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="777"/>
        <location filename="../../core/cli/feetechcommands.cpp" line="835"/>
        <source>one FILE</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="786"/>
        <source>servo %1 is of an unknown model (%2): no profile can be saved</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="800"/>
        <source>saved servo %1 (%2) to %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="853"/>
        <source>note: the profile was saved from a %1, this servo is a %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="879"/>
        <source>servo %1 already holds every value of %2; nothing written</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="939"/>
        <source>the NEW ID</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="942"/>
        <source>%1: &quot;%2&quot; is not an ID (0 to %3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="952"/>
        <source>servo %1 already has ID %1; nothing written</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="962"/>
        <source>the new BAUD rate in bits per second</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="971"/>
        <source>servo %1 already runs at %2; nothing written</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="976"/>
        <source>%1 servos do not support %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="1011"/>
        <source>--backup needs a FILE</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="1025"/>
        <source>servo %1 is of an unknown model (%2): no backup can be saved, so it is not reset</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="1034"/>
        <source>the backup could not be saved, so the servo was not reset: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="1036"/>
        <source>backup of servo %1 saved to %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="1069"/>
        <source>%1 needs --ids LIST (such as 1,2,5-7)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="1073"/>
        <source>--ids names servo %1 twice</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="1093"/>
        <source>servo %1 is of an unknown model (%2): its feedback cannot be decoded</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="1125"/>
        <source>servoctl: servo %1 stopped answering</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="1126"/>
        <source>servoctl: servo %1 answers again</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="1141"/>
        <source>servoctl: %1 samples in %2 s (%3 per second); %4 missed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="1153"/>
        <source>no servo answered the telemetry requests</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="1169"/>
        <source>--rate must be a number of samples per second from 1 to 1000, or max</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/ptkcommands.cpp" line="202"/>
        <source>ptk needs a command: read, write, save, load or monitor</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/ptkcommands.cpp" line="206"/>
        <source>ptk takes no --rate: the servo is polled every 50 ms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/ptkcommands.cpp" line="209"/>
        <source>only ptk monitor takes --duration</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/ptkcommands.cpp" line="221"/>
        <source>unknown ptk command &quot;%1&quot;: use read, write, save, load or monitor</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/ptkcommands.cpp" line="256"/>
        <source>ptk read takes no arguments</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="648"/>
        <location filename="../../core/cli/ptkcommands.cpp" line="287"/>
        <source>%1: wrote %2, the servo holds %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="651"/>
        <location filename="../../core/cli/ptkcommands.cpp" line="289"/>
        <source>nothing</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/ptkcommands.cpp" line="298"/>
        <source>written and verified</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="670"/>
        <location filename="../../core/cli/ptkcommands.cpp" line="303"/>
        <source>verification failed: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/ptkcommands.cpp" line="311"/>
        <source>ptk write needs NAME=VALUE arguments (names: %1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/ptkcommands.cpp" line="319"/>
        <source>ptk save needs one FILE</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="398"/>
        <location filename="../../core/cli/ptkcommands.cpp" line="324"/>
        <source>the folder of %1 does not exist</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/ptkcommands.cpp" line="340"/>
        <source>saved %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/ptkcommands.cpp" line="348"/>
        <source>ptk load needs one FILE</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/ptkcommands.cpp" line="363"/>
        <source>ptk monitor takes no arguments</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/arguments.cpp" line="82"/>
        <source>--duration must be a number of seconds above 0</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="1079"/>
        <location filename="../../core/cli/ptkcommands.cpp" line="367"/>
        <source>choose --csv or --json, not both</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/ptkcommands.cpp" line="398"/>
        <source>the servo did not answer</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="101"/>
        <source>no command given (try servoctl --help)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="114"/>
        <source>unknown command &quot;%1&quot; (try servoctl --help)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="351"/>
        <location filename="../../core/cli/feetechcommands.cpp" line="355"/>
        <location filename="../../core/cli/servoctl.cpp" line="130"/>
        <source>%1 takes no --%2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="32"/>
        <source>usage: servoctl [--port PATH] [--baud N] [--json] [--trace] &lt;command&gt; [args]

commands:
  ports                                  list serial ports
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
  feetech set-id --id N NEW              give the servo a new ID (refused if taken)
  feetech set-baud --id N BAUD           move the servo to another baud rate (bps)
  feetech calibrate-middle --id N        make the present position the middle
  feetech factory-reset --id N [--backup FILE]
                                         save a backup profile, then restore factory values
  feetech reboot --id N                  restart the servo and wait for it
  feetech monitor --ids LIST [--rate HZ|max] [--duration S] [--csv]
                                         stream position, speed, load, voltage,
                                         temperature and current (SYNC READ)
  decode [--family ptk|feetech] HEX...   split bytes into frames and explain each
  packet ptk query CMD                   print a PTK query frame (CMD: 0x38, 56 or N1..N8)
  packet ptk write NAME=VALUE...         print the PTK write frames carrying these values
  packet feetech INSTRUCTION [--id N] [--addr A] [--data HEX] [--len N] [--ids LIST]
      INSTRUCTION: ping read write reg-write action sync-write sync-read
                   recovery reboot reset calibrate

options: --port PATH (device commands), --baud N (PTK: 115200; Feetech: the servo&apos;s
         rate, 1000000),
         --echo auto|on|off (single-wire adapter echo; default auto)

exit status: 0 done, 1 device or link failure, 2 usage error (nothing sent)
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="146"/>
        <source>ports takes no arguments</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="166"/>
        <source>no serial ports found</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="181"/>
        <source>decode needs the bytes to decode, as hex</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="194"/>
        <source>--family must be ptk or feetech</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="198"/>
        <source>no PTK (AF FA) or Feetech (FF FF) header found; name the protocol with --family</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="212"/>
        <source> [checksum ok]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="213"/>
        <source> [BAD CHECKSUM]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="240"/>
        <source>packet needs a protocol: ptk or feetech</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="245"/>
        <source>unknown protocol &quot;%1&quot;: use ptk or feetech</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="252"/>
        <source>packet ptk needs query CMD or write NAME=VALUE...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="255"/>
        <source>packet ptk query needs exactly one command</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="265"/>
        <source>&quot;%1&quot; is not a command byte (0-255) or N1..N8</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="273"/>
        <source>unknown PTK packet &quot;%1&quot;: use query or write</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="279"/>
        <source>packet ptk write needs NAME=VALUE arguments</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="295"/>
        <source>write %1 also carries %2; give it too</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="306"/>
        <source>packet feetech needs one instruction (try servoctl --help)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="313"/>
        <source>%1 needs --id</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="319"/>
        <source>%1 needs a unicast ID (0-253), not %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="325"/>
        <source>%1 needs --addr</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="330"/>
        <source>%1 needs --data</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="333"/>
        <source>--data is empty</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="338"/>
        <source>%1 needs --len</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="344"/>
        <source>the packet would be %1 bytes; the limit is %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="392"/>
        <source>calibrate --data is a 2-byte position in the family&apos;s byte order</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="400"/>
        <location filename="../../core/cli/servoctl.cpp" line="413"/>
        <source>%1 needs --ids</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="423"/>
        <source>--data must hold %1 or %2 bytes (--len %1 for %3 servos)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="433"/>
        <source>the SYNC WRITE would exceed %1 bytes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="437"/>
        <source>unknown Feetech instruction &quot;%1&quot; (try servoctl --help)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>servosim</name>
    <message>
        <location filename="../../core/sim/simoptions.cpp" line="19"/>
        <source>usage: servosim ptk --link PATH [--values KEY=V,...] [options]
       servosim feetech --link PATH --servo ID:MODEL[@BAUD] [--servo ...] [--state FILE] [options]

options:
  --echo                 send every host byte back first (single-wire adapter)
  --faults SPEC          drop=P,corrupt=P,truncate=P,noise=P,delay=MS
  --seed N               seed of the fault generator (default 1)
  --log FILE             log every frame in and out, hex, timestamped
  --reply-delay-us N     extra delay before every reply

Prints &quot;ready PATH&quot; once a client can open PATH; runs until SIGINT or SIGTERM;
SIGHUP power-cycles the servos.
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/sim/simoptions.cpp" line="44"/>
        <source>name a protocol: ptk or feetech</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/sim/simoptions.cpp" line="51"/>
        <source>unknown protocol &quot;%1&quot;: use ptk or feetech</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/sim/simoptions.cpp" line="71"/>
        <source>unknown option &quot;%1&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/sim/simoptions.cpp" line="74"/>
        <source>%1 needs a value</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/sim/simoptions.cpp" line="85"/>
        <source>--seed must be a whole number from 0 to 4294967295</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/sim/simoptions.cpp" line="92"/>
        <source>--reply-delay-us must be 0 to 10000000</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/sim/simoptions.cpp" line="96"/>
        <source>--values is for the PTK servo</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/sim/simoptions.cpp" line="100"/>
        <source>--state is for a Feetech bus</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/sim/simoptions.cpp" line="104"/>
        <source>--servo is for a Feetech bus</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/sim/simoptions.cpp" line="110"/>
        <source>--servo &quot;%1&quot; is not ID:MODEL[@BAUD]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/sim/simoptions.cpp" line="112"/>
        <source>--servo &quot;%1&quot;: ID %2 is over 253</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/sim/simoptions.cpp" line="117"/>
        <source>--servo &quot;%1&quot; names no model</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/sim/simoptions.cpp" line="121"/>
        <source>--servo &quot;%1&quot;: bad baud rate</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/sim/simoptions.cpp" line="128"/>
        <source>--link PATH is required</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/sim/simoptions.cpp" line="130"/>
        <source>a Feetech bus needs at least one --servo ID:MODEL[@BAUD]</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>util</name>
    <message>
        <location filename="../../core/util/hex.cpp" line="44"/>
        <source>odd number of hex digits in &quot;%1&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/util/hex.cpp" line="53"/>
        <source>&quot;%1&quot; is not hexadecimal</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/util/jsonfile.cpp" line="77"/>
        <source>not valid JSON: %1 at offset %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/util/jsonfile.cpp" line="92"/>
        <source>the format version is missing or not a whole number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/util/jsonfile.cpp" line="97"/>
        <source>unknown format version %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/util/jsonfile.cpp" line="102"/>
        <source>unknown entry &quot;%1&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/util/jsonfile.cpp" line="123"/>
        <source>%1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/util/jsonfile.cpp" line="128"/>
        <source>%1 was not saved: %2</source>
        <translation type="unfinished"></translation>
    </message>
</context>
</TS>
