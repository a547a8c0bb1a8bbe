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
        <location filename="../../core/feetech/busclient.cpp" line="123"/>
        <location filename="../../core/feetech/busclient.cpp" line="322"/>
        <source>The bus is not connected.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/busclient.cpp" line="125"/>
        <location filename="../../core/feetech/busclient.cpp" line="317"/>
        <source>No servo is selected.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/busclient.cpp" line="127"/>
        <location filename="../../core/feetech/busclient.cpp" line="469"/>
        <location filename="../../core/feetech/busclient.cpp" line="480"/>
        <source>Another operation is still running.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/busclient.cpp" line="129"/>
        <source>This servo&apos;s model is unknown; its memory is shown read-only.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/busclient.cpp" line="281"/>
        <location filename="../../core/feetech/busclient.cpp" line="414"/>
        <source>ID %1 is already in use on this bus.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/busclient.cpp" line="299"/>
        <location filename="../../core/feetech/busclient.cpp" line="382"/>
        <source>Nothing to write.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/busclient.cpp" line="445"/>
        <source>This servo has no middle calibration (SCS servos have no offset register).</source>
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
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="41"/>
        <source>%1 Mbps</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="42"/>
        <source>%1 bps</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <location filename="../../core/feetech/feetechsession.cpp" line="51"/>
        <source>no reply after %n attempt(s)</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="53"/>
        <source>the port is closed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="55"/>
        <source>cancelled</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="286"/>
        <source>Disconnected.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="299"/>
        <source>%1 Reconnecting when it comes back.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="314"/>
        <source>%1 is back. Scan again if servos were changed while it was away.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="338"/>
        <location filename="../../core/feetech/feetechsession.cpp" line="341"/>
        <source>Not connected.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="425"/>
        <source>The port cannot be set to %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="451"/>
        <source>%1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="463"/>
        <source>The servo&apos;s model has no known EEPROM lock register.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="466"/>
        <source>Locking the EEPROM</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="466"/>
        <source>Unlocking the EEPROM</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="488"/>
        <source>Reading %1 bytes at address %2: %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="516"/>
        <source>Reading the identity of servo %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="541"/>
        <source>Servo %1 does not answer.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="543"/>
        <source>ID %1 is already in use on this bus.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="573"/>
        <source>servo %1 at %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <location filename="../../core/feetech/feetechsession.cpp" line="606"/>
        <source>Scan cancelled; %n servo(s) found before.</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../../core/feetech/feetechsession.cpp" line="610"/>
        <source>Scan complete: %n servo(s) found.</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="618"/>
        <source>%1 is not a Feetech baud rate.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="764"/>
        <source>unknown (identity unreadable)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="804"/>
        <source>Servo %1 answers.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="805"/>
        <source>Servo %1 does not answer: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="830"/>
        <source>Read %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="845"/>
        <source>Servo %1 is of an unknown model; its memory is shown read-only and nothing is written to it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="858"/>
        <source>The ID and the baud rate change how the servo is reached; use Change ID or Change baud rate.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="875"/>
        <source>The EEPROM lock is opened and closed by ServoBench around each EEPROM write; it is not written by hand.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="878"/>
        <source>Torque enable 128 recalibrates the middle; use Calibrate middle.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="904"/>
        <source>Writing address %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="915"/>
        <source>Written and read back.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="935"/>
        <source>Servo %1 is of an unknown model; its ID is not changed.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="937"/>
        <source>ID %1 is out of range (0 to %2).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="939"/>
        <source>The servo already has ID %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="942"/>
        <source>ID %1 is already in use on this bus; nothing was written.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="981"/>
        <source>Servo %1 now answers as ID %2.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="997"/>
        <source>The servo still has its old ID.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="1012"/>
        <source>Servo %1 is of an unknown model; its baud rate is not changed.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="1017"/>
        <source>%1 is not a baud rate this servo supports.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="1019"/>
        <source>The servo already runs at %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="1054"/>
        <source>The servo reports baud code %1 instead of %2.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="1066"/>
        <source>Servo %1 now runs at %2 and answers there.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="1085"/>
        <source>It still answers at %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="1087"/>
        <source>It answers at neither rate; scan all baud rates to find it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="1105"/>
        <source>Middle calibration is not available on this servo (SCS servos have no offset register).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="1115"/>
        <location filename="../../core/feetech/feetechsession.cpp" line="1119"/>
        <source>Middle calibration</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="1125"/>
        <source>The present position is now the middle.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="1144"/>
        <source>Servo %1 is of an unknown model; it is not reset.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="1152"/>
        <source>Factory reset</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="1169"/>
        <source>Factory values restored; servo %1 answers at %2.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="1187"/>
        <source>Servo %1 answers at no baud rate; scan the bus to find it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="1209"/>
        <source>Torque off</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="1211"/>
        <source>Reboot</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="1237"/>
        <source>Servo %1 restarted and answers again after %2 ms.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="1245"/>
        <source>Servo %1 has not answered within %2 ms of the restart.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="1264"/>
        <source>Clearing the status</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/feetech/feetechsession.cpp" line="1270"/>
        <source>Status of servo %1 cleared.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>FeetechWorkspace</name>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="43"/>
        <source>%1 Mbps</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="44"/>
        <source>%L1 bps</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="83"/>
        <source>Scan…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="84"/>
        <source>Look for servos on the bus: choose IDs and baud rates</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="85"/>
        <source>Cancel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="85"/>
        <source>Stop the scan</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="93"/>
        <source>%v of %m IDs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="96"/>
        <source>Connect, then scan to find the servos.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="104"/>
        <source>Servo</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="104"/>
        <source>Model</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="104"/>
        <source>Family</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="104"/>
        <source>Firmware</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="123"/>
        <source>Change ID…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="124"/>
        <source>Give the servo another ID; an ID in use is refused</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="126"/>
        <source>Change baud rate…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="127"/>
        <source>Move the servo to another baud rate and follow it there</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="128"/>
        <source>Calibrate middle…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="129"/>
        <location filename="../../ui/feetechworkspace.cpp" line="484"/>
        <source>Make the horn&apos;s present position the middle (2048)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="130"/>
        <source>Factory reset…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="131"/>
        <source>Restore factory values (the ID is kept), after saving a backup profile</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="135"/>
        <source>Reboot</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="136"/>
        <source>Torque off, restart the servo and wait until it answers again</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="137"/>
        <source>Clear status</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="138"/>
        <source>Reset the servo&apos;s error status (instruction 0x0A)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="152"/>
        <source>The settings changed most, in real units. &lt;b&gt;EEPROM&lt;/b&gt; values are written with the lock opened and closed again and survive power-off. Changing the ID or the baud rate asks first, then follows the servo.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="156"/>
        <source>Settings</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="164"/>
        <source>Filter registers</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="166"/>
        <source>Refresh RAM live</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="169"/>
        <source>Read the RAM registers (present position, load, voltage…) several times a second while this table is shown</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="194"/>
        <source>Read</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="194"/>
        <source>Read every register of the servo</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="195"/>
        <source>Revert</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="195"/>
        <source>Drop every edit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="196"/>
        <source>Apply</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="197"/>
        <source>Write the edited registers, then read them back</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="206"/>
        <source>Memory table</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="227"/>
        <source>Restarting the servo…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="229"/>
        <source>Clearing the status…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="260"/>
        <source>Working…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="270"/>
        <source>Scanning at %1…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="325"/>
        <source>Connect to the bus before scanning.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="346"/>
        <source>Bus</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="357"/>
        <source>unknown</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="359"/>
        <source>ID %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="363"/>
        <source>Model number %1 (major %2, minor %3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="369"/>
        <source>No register table is known for this model: its memory is shown as raw bytes, read-only.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="431"/>
        <source>servo %1 (%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="439"/>
        <source>Choose a servo in the tree.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="440"/>
        <source>No servo yet: connect to the bus and scan.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="446"/>
        <source>unknown family</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="447"/>
        <source>status not read yet</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="450"/>
        <source>status OK</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="451"/>
        <source>&lt;span style=&apos;color:#b3261e&apos;&gt;status: %1&lt;/span&gt;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="454"/>
        <source>&lt;b&gt;ID %1 · %2&lt;/b&gt; &amp;nbsp; model %3 · %4 family · firmware %5 · %6 · %7</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="464"/>
        <source>No register table is known for this model, so nothing is guessed: the Memory table shows its raw bytes, read-only.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="485"/>
        <source>SCS servos have no offset register: not available</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="519"/>
        <source>its ID from %1 to %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="522"/>
        <source>its baud rate from %1 to %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="525"/>
        <source>Change how the servo is reached?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="526"/>
        <source>This changes %1.&lt;br&gt;&lt;br&gt;ServoBench writes it to EEPROM with the lock opened and closed again, then finds the servo at its new address and confirms it there. Other programs and robot code must use the new address afterwards.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="529"/>
        <source> and </source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="536"/>
        <source>Nothing was written: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="560"/>
        <source>Change ID</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="561"/>
        <source>New ID for %1 (IDs found on this bus: %2).
An ID in use is refused.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="567"/>
        <source>ID %1 is already in use on this bus; nothing was written.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="586"/>
        <source>Change baud rate</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="587"/>
        <source>New baud rate for %1 (now %2). ServoBench follows the servo to the new rate and confirms it there.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="601"/>
        <source>Calibrate middle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="602"/>
        <source>The horn&apos;s present position becomes the middle (2048) of %1. Turn the horn to where the middle should be first; the new offset is stored in EEPROM.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="607"/>
        <source>Calibrating the middle…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="621"/>
        <location filename="../../ui/feetechworkspace.cpp" line="631"/>
        <source>Factory reset</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="622"/>
        <source>First save a backup profile of %1; the reset only starts once it is saved.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="632"/>
        <source>Backup saved to %1.&lt;br&gt;&lt;br&gt;Restore the factory values of %2? Everything but the ID returns to what the servo left the factory with, possibly including its baud rate; ServoBench looks for it at every rate afterwards.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="638"/>
        <source>Restoring factory values…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="660"/>
        <source>Choose a servo first.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="666"/>
        <source>Saved %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="673"/>
        <source>Only a servo of a known model can be saved as a profile.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="698"/>
        <source>Choose a servo of a known model first.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="702"/>
        <source>Wait for the running operation to finish before loading a profile.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="714"/>
        <source>The servo already holds every value of this profile</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/feetechworkspace.cpp" line="719"/>
        <source>Profile loaded as edits: review them, then Apply</source>
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
        <location filename="../../ui/mainwindow.cpp" line="105"/>
        <location filename="../../ui/mainwindow.cpp" line="307"/>
        <source>Not connected</source>
        <translation>Nicht verbunden</translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="130"/>
        <source>Read all parameters</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="132"/>
        <source>Read failed: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="155"/>
        <source>&amp;File</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="156"/>
        <source>&amp;Load profile…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="158"/>
        <source>&amp;Save profile…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="161"/>
        <source>&amp;Quit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="165"/>
        <source>&amp;Link</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="166"/>
        <source>&amp;Poll the servo</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="170"/>
        <source>Keep reading the eight queries so the values stay live</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="173"/>
        <source>&amp;Fast polling (queries back to back)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="181"/>
        <source>&amp;Scan the Feetech bus…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="187"/>
        <source>Disconnect from the PTK servo before scanning a Feetech bus.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="194"/>
        <source>&amp;View</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="198"/>
        <source>&amp;Help</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="199"/>
        <source>&amp;About ServoBench</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="201"/>
        <source>About &amp;Qt</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="206"/>
        <source>About ServoBench</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="207"/>
        <source>&lt;p&gt;&lt;b&gt;ServoBench %1&lt;/b&gt;&lt;/p&gt;&lt;p&gt;Programs and monitors PTK RC servos and Feetech serial-bus servos on Linux, Windows and macOS.&lt;/p&gt;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="262"/>
        <source>Choose a serial port first.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="274"/>
        <source>The simulated servos could not start: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="431"/>
        <source>Wait for the running read or Apply to finish before loading a profile.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="461"/>
        <source>Some changes have not been written to the servos. Quit anyway?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="277"/>
        <source>simulated PTK servo</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="277"/>
        <source>simulated Feetech bus</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="281"/>
        <source>Enter a baud rate.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="310"/>
        <source>Connecting to %1…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="313"/>
        <source>Open: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="314"/>
        <source>Connected: %1 at %2 baud</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="317"/>
        <source>No reply on %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="320"/>
        <source>Disconnected: %1 went away, waiting for it to return</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="342"/>
        <source>sent %1 · ok %2 · checksum errors %3 · timeouts %4 · retries %5 · discarded %6 B</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="358"/>
        <source>%1 queries/s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="366"/>
        <source>Nothing was written: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="369"/>
        <source>Writing N1…N12, then reading back…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="381"/>
        <source>The servo did not take every value: the fields marked Mismatch hold something else than was written.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="384"/>
        <source>Written and verified</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="413"/>
        <source>Saved %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="441"/>
        <source>The servo already holds every value of this profile</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="447"/>
        <source>Profile loaded as edits: review them, then Apply</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="460"/>
        <source>Unapplied changes</source>
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
    <name>Profile</name>
    <message>
        <location filename="../../core/profile/profile.cpp" line="104"/>
        <source>expected true or false</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/profile/profile.cpp" line="111"/>
        <source>expected a number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/profile/profile.cpp" line="120"/>
        <source>%1 is out of range (%2 to %3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/profile/profile.cpp" line="128"/>
        <source>%1 is not a whole number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/profile/profile.cpp" line="129"/>
        <source>%1 is not a multiple of %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/profile/profile.cpp" line="185"/>
        <source>%1 was not saved: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/profile/profile.cpp" line="191"/>
        <location filename="../../core/profile/profile.cpp" line="302"/>
        <source>unknown parameter &quot;%1&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/profile/profile.cpp" line="203"/>
        <source>%1: the raw value %2 cannot be kept in a profile</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/profile/profile.cpp" line="233"/>
        <source>not valid JSON: %1 at offset %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/profile/profile.cpp" line="237"/>
        <source>not a ServoBench profile (the document is not a JSON object)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/profile/profile.cpp" line="243"/>
        <source>not a ServoBench profile (&quot;%1&quot; is not &quot;%2&quot;)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/profile/profile.cpp" line="248"/>
        <source>the format version is missing or not a whole number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/profile/profile.cpp" line="250"/>
        <source>the profile has format version %1 and was written by a newer ServoBench; this version reads format version %2 and older</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/profile/profile.cpp" line="255"/>
        <source>unknown format version %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/profile/profile.cpp" line="265"/>
        <source>unknown entry &quot;%1&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/profile/profile.cpp" line="271"/>
        <source>the profile names no servo family</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/profile/profile.cpp" line="274"/>
        <source>the profile is for &quot;%1&quot; servos, not &quot;%2&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/profile/profile.cpp" line="277"/>
        <location filename="../../core/profile/profile.cpp" line="279"/>
        <location filename="../../core/profile/profile.cpp" line="282"/>
        <source>&quot;%1&quot; must be text</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/profile/profile.cpp" line="286"/>
        <source>&quot;%1&quot;: &quot;%2&quot; is not an ISO 8601 date and time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/profile/profile.cpp" line="292"/>
        <source>the profile has no &quot;%1&quot; object</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/profile/profile.cpp" line="311"/>
        <location filename="../../core/profile/profile.cpp" line="326"/>
        <source>%1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/profile/profile.cpp" line="333"/>
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
        <location filename="../../core/ptk/ptksession.cpp" line="120"/>
        <source>Disconnected during Apply; the servo may hold only part of the new values.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/ptk/ptksession.cpp" line="123"/>
        <source>Disconnected during the read.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/ptk/ptksession.cpp" line="222"/>
        <location filename="../../core/ptk/ptksession.cpp" line="284"/>
        <source>Not connected.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/ptk/ptksession.cpp" line="226"/>
        <location filename="../../core/ptk/ptksession.cpp" line="288"/>
        <source>Busy: a read or write is already running.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/ptk/ptksession.cpp" line="246"/>
        <source>No answer to the query for %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/ptk/ptksession.cpp" line="251"/>
        <source>Written, but not verified. %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/ptk/ptksession.cpp" line="267"/>
        <source>The link went down before the values could be read back.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/ptk/ptksession.cpp" line="270"/>
        <source>The link went down.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/ptk/ptksession.cpp" line="296"/>
        <source>%1 has not been read yet; nothing was written.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/ptk/ptksession.cpp" line="304"/>
        <source>%1; nothing was written.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/ptk/ptksession.cpp" line="334"/>
        <source>The link went down while writing %1; the servo may hold only part of the new values.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/ptk/ptksession.cpp" line="356"/>
        <source>The port is open but the servo does not answer. Check that it is powered and plugged into the programmer.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/ptk/ptksession.cpp" line="378"/>
        <source>The link went down during Apply: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/ptk/ptksession.cpp" line="383"/>
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
        <location filename="../../core/link/requestengine.cpp" line="144"/>
        <source>stray input discarded before a request</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/link/requestengine.cpp" line="205"/>
        <source>late reply, discarded</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/link/requestengine.cpp" line="206"/>
        <source>received while no request was waiting</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/link/requestengine.cpp" line="240"/>
        <source>unexpected frame, ignored</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/link/requestengine.cpp" line="247"/>
        <source>bad checksum</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/link/requestengine.cpp" line="253"/>
        <source>bytes that form no frame</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/link/requestengine.cpp" line="275"/>
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
        <location filename="../../core/link/transport.cpp" line="102"/>
        <source>%1 does not exist. Is the adapter plugged in?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/link/transport.cpp" line="105"/>
        <source>Permission denied on %1. Either another program has it open, or you are not in the group that may use serial ports: run &quot;sudo usermod -aG dialout $USER&quot;, then log out and back in.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/link/transport.cpp" line="110"/>
        <source>Permission denied on %1: another program may have it open.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/link/transport.cpp" line="113"/>
        <source>%1 is already open.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/link/transport.cpp" line="115"/>
        <source>%1 is not open.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/link/transport.cpp" line="117"/>
        <source>Could not write to %1 (%2).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/link/transport.cpp" line="119"/>
        <source>Could not read from %1 (%2).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/link/transport.cpp" line="121"/>
        <source>%1 went away: the adapter was unplugged or the device closed.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/link/transport.cpp" line="124"/>
        <source>%1 does not support this setting (%2).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/link/transport.cpp" line="126"/>
        <source>%1 timed out.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/link/transport.cpp" line="130"/>
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
        <location filename="../../core/cli/arguments.cpp" line="81"/>
        <source>--ids: &quot;%1&quot; is not an ID</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/arguments.cpp" line="83"/>
        <source>--ids: ID %1 is over %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/arguments.cpp" line="92"/>
        <source>--ids: the range %1 runs backwards</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/arguments.cpp" line="100"/>
        <source>--ids needs at least one ID</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/ptkcommands.cpp" line="82"/>
        <source>ptk commands need --port PATH (see servoctl ports)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="55"/>
        <source>%1 bps</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="87"/>
        <source>unknown model, raw bytes only</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="88"/>
        <source>servo %1 at %2: %3 (%4), firmware %5</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="154"/>
        <source>feetech commands need --port PATH (see servoctl ports)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="164"/>
        <location filename="../../core/cli/ptkcommands.cpp" line="95"/>
        <source>--echo must be auto, on or off</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="180"/>
        <source>%1 could not be opened</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="192"/>
        <source>%1 (at %2; servoctl feetech scan --baud all looks at every rate)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="205"/>
        <source>servo %1 answers PING but its identity (addresses 0-8) could not be read: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="256"/>
        <location filename="../../core/cli/ptkcommands.cpp" line="181"/>
        <source>the servo did not finish in time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="330"/>
        <source>feetech needs a command (try servoctl --help)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="355"/>
        <source>unknown feetech command &quot;%1&quot;: use %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="388"/>
        <source>%1 takes no arguments</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="389"/>
        <source>%1 needs %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="406"/>
        <source>%1: &quot;%2&quot; is not a Feetech baud rate (%3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="413"/>
        <source>%1 needs --id N</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="465"/>
        <source>--ids: a scan covers one range of IDs, such as 0-20</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="479"/>
        <source>id</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="480"/>
        <source>baud</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="481"/>
        <source>model</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="482"/>
        <source>number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="483"/>
        <source>family</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="484"/>
        <source>firmware</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="514"/>
        <source>no servo answered (try --baud all, or check power and wiring)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="535"/>
        <source>%1; answered in %2 ms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="570"/>
        <source>no register table is known for this model: the bytes are shown as they are, and nothing can be written</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="574"/>
        <source>addr</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="575"/>
        <source>key</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="576"/>
        <source>value</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="577"/>
        <source>meaning</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="594"/>
        <source>%1 needs the register KEYs to read</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="597"/>
        <source>%1: &quot;%2&quot; is not a register key</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="611"/>
        <location filename="../../core/cli/feetechcommands.cpp" line="739"/>
        <source>%1 servos have no register &quot;%2&quot; (servoctl feetech read lists them)</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <location filename="../../core/cli/feetechcommands.cpp" line="688"/>
        <source>written to servo %1 and verified: %n register(s)</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="704"/>
        <source>%1 needs KEY=VALUE arguments</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="709"/>
        <source>&quot;%1&quot; is not KEY=VALUE</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="712"/>
        <source>the ID changes how the servo is reached: use servoctl feetech set-id --id N NEW</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="715"/>
        <source>the baud rate changes how the servo is reached: use servoctl feetech set-baud --id N BAUD</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="719"/>
        <source>%1 is given twice</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="731"/>
        <location filename="../../core/cli/feetechcommands.cpp" line="876"/>
        <source>servo %1 is of an unknown model (%2); nothing is written to it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="743"/>
        <source>%1 is read-only</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="779"/>
        <source>%1 = %2 is outside its range (%3 to %4) and is left out of the profile</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="805"/>
        <location filename="../../core/cli/feetechcommands.cpp" line="865"/>
        <source>one FILE</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="816"/>
        <source>servo %1 is of an unknown model (%2): no profile can be saved</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="830"/>
        <source>saved servo %1 (%2) to %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="885"/>
        <source>note: the profile was saved from a %1, this servo is a %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="911"/>
        <source>servo %1 already holds every value of %2; nothing written</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="971"/>
        <source>the NEW ID</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="974"/>
        <source>%1: &quot;%2&quot; is not an ID (0 to %3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="985"/>
        <source>servo %1 already has ID %1; nothing written</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="995"/>
        <source>the new BAUD rate in bits per second</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="1007"/>
        <source>servo %1 already runs at %2; nothing written</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="1010"/>
        <source>%1 servos do not support %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="1048"/>
        <source>--backup needs a FILE</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="1062"/>
        <source>servo %1 is of an unknown model (%2): no backup can be saved, so it is not reset</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="1071"/>
        <source>the backup could not be saved, so the servo was not reset: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="1073"/>
        <source>backup of servo %1 saved to %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/ptkcommands.cpp" line="218"/>
        <source>ptk needs a command: read, write, save, load or monitor</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/ptkcommands.cpp" line="223"/>
        <source>only ptk monitor takes --duration</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/ptkcommands.cpp" line="235"/>
        <source>unknown ptk command &quot;%1&quot;: use read, write, save, load or monitor</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/ptkcommands.cpp" line="270"/>
        <source>ptk read takes no arguments</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="674"/>
        <location filename="../../core/cli/ptkcommands.cpp" line="301"/>
        <source>%1: wrote %2, the servo holds %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="677"/>
        <location filename="../../core/cli/ptkcommands.cpp" line="303"/>
        <source>nothing</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/ptkcommands.cpp" line="312"/>
        <source>written and verified</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="696"/>
        <location filename="../../core/cli/ptkcommands.cpp" line="317"/>
        <source>verification failed: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/ptkcommands.cpp" line="325"/>
        <source>ptk write needs NAME=VALUE arguments (names: %1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/ptkcommands.cpp" line="333"/>
        <source>ptk save needs one FILE</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="421"/>
        <location filename="../../core/cli/ptkcommands.cpp" line="338"/>
        <source>the folder of %1 does not exist</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/ptkcommands.cpp" line="354"/>
        <source>saved %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/ptkcommands.cpp" line="362"/>
        <source>ptk load needs one FILE</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/ptkcommands.cpp" line="377"/>
        <source>ptk monitor takes no arguments</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/ptkcommands.cpp" line="383"/>
        <source>--duration must be a number of seconds above 0</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/ptkcommands.cpp" line="387"/>
        <source>choose --csv or --json, not both</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/ptkcommands.cpp" line="425"/>
        <source>the servo did not answer</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="98"/>
        <source>no command given (try servoctl --help)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="111"/>
        <source>unknown command &quot;%1&quot; (try servoctl --help)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/feetechcommands.cpp" line="374"/>
        <location filename="../../core/cli/feetechcommands.cpp" line="378"/>
        <location filename="../../core/cli/servoctl.cpp" line="127"/>
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
        <location filename="../../core/cli/servoctl.cpp" line="143"/>
        <source>ports takes no arguments</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="163"/>
        <source>no serial ports found</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="178"/>
        <source>decode needs the bytes to decode, as hex</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="191"/>
        <source>--family must be ptk or feetech</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="195"/>
        <source>no PTK (AF FA) or Feetech (FF FF) header found; name the protocol with --family</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="209"/>
        <source> [checksum ok]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="210"/>
        <source> [BAD CHECKSUM]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="237"/>
        <source>packet needs a protocol: ptk or feetech</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="242"/>
        <source>unknown protocol &quot;%1&quot;: use ptk or feetech</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="249"/>
        <source>packet ptk needs query CMD or write NAME=VALUE...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="252"/>
        <source>packet ptk query needs exactly one command</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="262"/>
        <source>&quot;%1&quot; is not a command byte (0-255) or N1..N8</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="270"/>
        <source>unknown PTK packet &quot;%1&quot;: use query or write</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="276"/>
        <source>packet ptk write needs NAME=VALUE arguments</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="292"/>
        <source>write %1 also carries %2; give it too</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="303"/>
        <source>packet feetech needs one instruction (try servoctl --help)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="310"/>
        <source>%1 needs --id</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="316"/>
        <source>%1 needs a unicast ID (0-253), not %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="322"/>
        <source>%1 needs --addr</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="327"/>
        <source>%1 needs --data</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="330"/>
        <source>--data is empty</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="335"/>
        <source>%1 needs --len</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="341"/>
        <source>the packet would be %1 bytes; the limit is %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="389"/>
        <source>calibrate --data is a 2-byte position in the family&apos;s byte order</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="397"/>
        <location filename="../../core/cli/servoctl.cpp" line="410"/>
        <source>%1 needs --ids</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="420"/>
        <source>--data must hold %1 or %2 bytes (--len %1 for %3 servos)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="430"/>
        <source>the SYNC WRITE would exceed %1 bytes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="434"/>
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
</context>
</TS>
