<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de_DE">
<context>
    <name>ConnectionBar</name>
    <message>
        <location filename="../../ui/connectionbar.cpp" line="22"/>
        <source>Connection</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/connectionbar.cpp" line="27"/>
        <source>Port </source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/connectionbar.cpp" line="34"/>
        <source>The serial port of the USB programmer, or a simulated servo</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/connectionbar.cpp" line="38"/>
        <source>Baud </source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/connectionbar.cpp" line="45"/>
        <source>PTK servos talk at 115200 baud</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/connectionbar.cpp" line="49"/>
        <source>Protocol </source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/connectionbar.cpp" line="52"/>
        <source>PTK RC servo</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/connectionbar.cpp" line="56"/>
        <source>Echo </source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/connectionbar.cpp" line="59"/>
        <source>Auto</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/connectionbar.cpp" line="60"/>
        <source>On</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/connectionbar.cpp" line="61"/>
        <source>Off</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/connectionbar.cpp" line="62"/>
        <source>Single-wire programmers send every byte back. Auto detects it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/connectionbar.cpp" line="66"/>
        <location filename="../../ui/connectionbar.cpp" line="114"/>
        <source>Connect</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/connectionbar.cpp" line="114"/>
        <source>Disconnect</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/connectionbar.cpp" line="141"/>
        <source>Simulated PTK servo</source>
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
        <location filename="../../core/sim/demoservos.cpp" line="24"/>
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
    <name>MainWindow</name>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="55"/>
        <source>ServoBench</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="87"/>
        <location filename="../../ui/mainwindow.cpp" line="224"/>
        <source>Not connected</source>
        <translation>Nicht verbunden</translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="106"/>
        <source>Read all parameters</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="108"/>
        <source>Read failed: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="129"/>
        <source>&amp;File</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="130"/>
        <source>&amp;Load profile…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="132"/>
        <source>&amp;Save profile…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="135"/>
        <source>&amp;Quit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="139"/>
        <source>&amp;Link</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="140"/>
        <source>&amp;Poll the servo</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="144"/>
        <source>Keep reading the eight queries so the values stay live</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="146"/>
        <source>&amp;Fast polling (queries back to back)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="153"/>
        <source>&amp;View</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="157"/>
        <source>&amp;Help</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="158"/>
        <source>&amp;About ServoBench</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="160"/>
        <source>About &amp;Qt</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="165"/>
        <source>About ServoBench</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="166"/>
        <source>&lt;p&gt;&lt;b&gt;ServoBench %1&lt;/b&gt;&lt;/p&gt;&lt;p&gt;Programs and monitors PTK RC servos and Feetech serial-bus servos on Linux, Windows and macOS.&lt;/p&gt;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="190"/>
        <source>Choose a serial port first.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="199"/>
        <source>The simulated servo could not start: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="202"/>
        <source>simulated PTK servo</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="206"/>
        <source>Enter a baud rate.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="227"/>
        <source>Connecting to %1…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="230"/>
        <source>Connected: %1 at %2 baud</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="233"/>
        <source>No reply on %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="236"/>
        <source>Disconnected: %1 went away, waiting for it to return</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="258"/>
        <source>sent %1 · ok %2 · checksum errors %3 · timeouts %4 · retries %5 · discarded %6 B</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="274"/>
        <source>%1 queries/s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="282"/>
        <source>Nothing was written: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="285"/>
        <source>Writing N1…N12, then reading back…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="297"/>
        <source>The servo did not take every value: the fields marked Mismatch hold something else than was written.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="300"/>
        <source>Written and verified</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="312"/>
        <source>Save profile</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="314"/>
        <location filename="../../ui/mainwindow.cpp" line="340"/>
        <source>ServoBench profiles (*.json)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="324"/>
        <source>Read the servo before saving a profile: not every value is known.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="332"/>
        <source>Saved %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="339"/>
        <source>Load profile</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="350"/>
        <source>The profile was not loaded: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="355"/>
        <source>The servo already holds every value of this profile</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="364"/>
        <source>Profile loaded as edits: review them, then Apply</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="372"/>
        <source>Unapplied changes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/mainwindow.cpp" line="373"/>
        <source>Some changes have not been written to the servo. Quit anyway?</source>
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
        <location filename="../../core/ptk/ptkclient.cpp" line="99"/>
        <source>The servo is not connected.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/ptk/ptkclient.cpp" line="101"/>
        <source>A read or write is already running.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/ptk/ptkclient.cpp" line="103"/>
        <source>There are no changes to apply.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/ptk/ptkclient.cpp" line="106"/>
        <source>%1 has not been read yet.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>PtkPage</name>
    <message>
        <location filename="../../ui/ptkpage.cpp" line="159"/>
        <source>Load profile…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/ptkpage.cpp" line="160"/>
        <source>Load parameter values from a profile file as edits</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/ptkpage.cpp" line="161"/>
        <source>Save profile…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/ptkpage.cpp" line="162"/>
        <source>Save the servo&apos;s parameter values to a profile file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/ptkpage.cpp" line="163"/>
        <source>Read</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/ptkpage.cpp" line="163"/>
        <source>Read every parameter from the servo</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/ptkpage.cpp" line="164"/>
        <source>Revert</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/ptkpage.cpp" line="165"/>
        <source>Drop every edit and show the servo&apos;s values again</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/ptkpage.cpp" line="166"/>
        <source>Apply</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/ptkpage.cpp" line="167"/>
        <source>Write the edited parameters to the servo, then read them back to verify</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/ptkpage.cpp" line="179"/>
        <source>%v of %m</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/ptkpage.cpp" line="212"/>
        <source>&lt;b&gt;Device&lt;/b&gt; is what the servo reports. Edits are written only when you press &lt;b&gt;Apply&lt;/b&gt;, then read back and verified.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/ptkpage.cpp" line="256"/>
        <location filename="../../ui/ptkpage.cpp" line="304"/>
        <source>Device</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/ptkpage.cpp" line="257"/>
        <source>New value</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/ptkpage.cpp" line="258"/>
        <source>State</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/ptkpage.cpp" line="358"/>
        <source>%1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/ptkpage.cpp" line="358"/>
        <source> or </source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/ptkpage.cpp" line="384"/>
        <source>%1: %2 to %3%4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/ptkpage.cpp" line="434"/>
        <source>Refused</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/ptkpage.cpp" line="472"/>
        <location filename="../../ui/ptkpage.cpp" line="529"/>
        <location filename="../../ui/ptkpage.cpp" line="532"/>
        <source>—</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/ptkpage.cpp" line="473"/>
        <source>Not read from the servo yet</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/ptkpage.cpp" line="481"/>
        <source>Changed here; written to the servo when you press Apply</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/ptkpage.cpp" line="485"/>
        <source>Being written to the servo</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/ptkpage.cpp" line="489"/>
        <source>Written and read back with the same value</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/ptkpage.cpp" line="493"/>
        <source>The value read back differs from the value written</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../ui/ptkpage.cpp" line="497"/>
        <source>The write did not go out; the edit is kept so you can try again</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>PtkSession</name>
    <message>
        <location filename="../../core/ptk/ptksession.cpp" line="192"/>
        <location filename="../../core/ptk/ptksession.cpp" line="254"/>
        <source>Not connected.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/ptk/ptksession.cpp" line="196"/>
        <location filename="../../core/ptk/ptksession.cpp" line="258"/>
        <source>Busy: a read or write is already running.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/ptk/ptksession.cpp" line="216"/>
        <source>No answer to the query for %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/ptk/ptksession.cpp" line="221"/>
        <source>Written, but not verified. %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/ptk/ptksession.cpp" line="237"/>
        <source>The link went down before the values could be read back.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/ptk/ptksession.cpp" line="240"/>
        <source>The link went down.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/ptk/ptksession.cpp" line="266"/>
        <source>%1 has not been read yet; nothing was written.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/ptk/ptksession.cpp" line="274"/>
        <source>%1; nothing was written.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/ptk/ptksession.cpp" line="304"/>
        <source>The link went down while writing %1; the servo may hold only part of the new values.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/ptk/ptksession.cpp" line="326"/>
        <source>The port is open but the servo does not answer. Check that it is powered and plugged into the programmer.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/ptk/ptksession.cpp" line="348"/>
        <source>The link went down during Apply: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/ptk/ptksession.cpp" line="353"/>
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
</context>
<context>
    <name>RequestEngine</name>
    <message>
        <location filename="../../core/link/requestengine.cpp" line="142"/>
        <source>stray input discarded before a request</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/link/requestengine.cpp" line="193"/>
        <source>late reply, discarded</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/link/requestengine.cpp" line="194"/>
        <source>received while no request was waiting</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/link/requestengine.cpp" line="221"/>
        <source>unexpected frame, ignored</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/link/requestengine.cpp" line="226"/>
        <source>bad checksum</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/link/requestengine.cpp" line="231"/>
        <source>bytes that form no frame</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/link/requestengine.cpp" line="249"/>
        <source>no reply (attempt %1 of %2)</source>
        <translation type="unfinished"></translation>
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
    <name>Tr</name>
    <message>
        <location filename="../../core/cli/ptkcommands.cpp" line="471"/>
        <source>&quot;%1&quot; is not NAME=VALUE</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/ptkcommands.cpp" line="476"/>
        <source>unknown parameter &quot;%1&quot; (known: %2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/ptkcommands.cpp" line="490"/>
        <source>%1: &quot;%2&quot; is not a number</source>
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
    <name>VirtualPtkServo</name>
    <message>
        <location filename="../../core/sim/virtualptkservo.cpp" line="47"/>
        <source>--values: &quot;%1&quot; is not KEY=NUMBER with a PTK parameter key</source>
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
        <source>Start simulated servos and connect to them.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../app/servobench.cpp" line="32"/>
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
        <location filename="../../core/ptk/ptkparameters.cpp" line="130"/>
        <source>Response</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/ptk/ptkparameters.cpp" line="132"/>
        <source>Travel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/ptk/ptkparameters.cpp" line="134"/>
        <source>Power</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/ptk/ptkparameters.cpp" line="197"/>
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
        <location filename="../../core/cli/ptkcommands.cpp" line="95"/>
        <source>--echo must be auto, on or off</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/ptkcommands.cpp" line="172"/>
        <source>the servo did not finish in time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/ptkcommands.cpp" line="209"/>
        <source>ptk needs a command: read, write, save, load or monitor</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/ptkcommands.cpp" line="214"/>
        <source>only ptk monitor takes --duration</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/ptkcommands.cpp" line="226"/>
        <source>unknown ptk command &quot;%1&quot;: use read, write, save, load or monitor</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/ptkcommands.cpp" line="261"/>
        <source>ptk read takes no arguments</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/ptkcommands.cpp" line="293"/>
        <source>%1: wrote %2, the servo holds %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/ptkcommands.cpp" line="295"/>
        <source>nothing</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/ptkcommands.cpp" line="304"/>
        <source>written and verified</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/ptkcommands.cpp" line="309"/>
        <source>verification failed: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/ptkcommands.cpp" line="317"/>
        <source>ptk write needs NAME=VALUE arguments (names: %1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/ptkcommands.cpp" line="328"/>
        <source>ptk save needs one FILE</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/ptkcommands.cpp" line="333"/>
        <source>the folder of %1 does not exist</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/ptkcommands.cpp" line="351"/>
        <source>saved %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/ptkcommands.cpp" line="359"/>
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
        <location filename="../../core/cli/servoctl.cpp" line="31"/>
        <source>usage: servoctl [--port PATH] [--baud N] [--json] [--trace] &lt;command&gt; [args]

commands:
  ports                                  list serial ports
  ptk read                               read the PTK servo&apos;s thirteen parameters
  ptk write NAME=VALUE...                change parameters (full sequence, verified)
  ptk save FILE | ptk load FILE          save the servo to a profile / program one
  ptk monitor [--duration S] [--csv]     poll continuously, one row per full refresh
  decode [--family ptk|feetech] HEX...   split bytes into frames and explain each
  packet ptk query CMD                   print a PTK query frame (CMD: 0x38, 56 or N1..N8)
  packet ptk write NAME=VALUE...         print the PTK write frames carrying these values
  packet feetech INSTRUCTION [--id N] [--addr A] [--data HEX] [--len N] [--ids LIST]
      INSTRUCTION: ping read write reg-write action sync-write sync-read
                   recovery reboot reset calibrate

options: --port PATH (device commands), --baud N (PTK: 115200),
         --echo auto|on|off (single-wire adapter echo; default auto)

exit status: 0 done, 1 device or link failure, 2 usage error (nothing sent)
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="82"/>
        <source>no command given (try servoctl --help)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="93"/>
        <source>unknown command &quot;%1&quot; (try servoctl --help)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="109"/>
        <source>%1 takes no --%2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="125"/>
        <source>ports takes no arguments</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="145"/>
        <source>no serial ports found</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="160"/>
        <source>decode needs the bytes to decode, as hex</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="173"/>
        <source>--family must be ptk or feetech</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="177"/>
        <source>no PTK (AF FA) or Feetech (FF FF) header found; name the protocol with --family</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="191"/>
        <source> [checksum ok]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="192"/>
        <source> [BAD CHECKSUM]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="219"/>
        <source>packet needs a protocol: ptk or feetech</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="224"/>
        <source>unknown protocol &quot;%1&quot;: use ptk or feetech</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="231"/>
        <source>packet ptk needs query CMD or write NAME=VALUE...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="234"/>
        <source>packet ptk query needs exactly one command</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="244"/>
        <source>&quot;%1&quot; is not a command byte (0-255) or N1..N8</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="252"/>
        <source>unknown PTK packet &quot;%1&quot;: use query or write</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="258"/>
        <source>packet ptk write needs NAME=VALUE arguments</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="274"/>
        <source>write %1 also carries %2; give it too</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="285"/>
        <source>packet feetech needs one instruction (try servoctl --help)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="292"/>
        <source>%1 needs --id</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="298"/>
        <source>%1 needs a unicast ID (0-253), not %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="304"/>
        <source>%1 needs --addr</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="309"/>
        <source>%1 needs --data</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="312"/>
        <source>--data is empty</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="317"/>
        <source>%1 needs --len</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="323"/>
        <source>the packet would be %1 bytes; the limit is %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="371"/>
        <source>calibrate --data is a 2-byte position in the family&apos;s byte order</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="379"/>
        <location filename="../../core/cli/servoctl.cpp" line="392"/>
        <source>%1 needs --ids</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="402"/>
        <source>--data must hold %1 or %2 bytes (--len %1 for %3 servos)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="412"/>
        <source>the SYNC WRITE would exceed %1 bytes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../core/cli/servoctl.cpp" line="416"/>
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
