<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de_DE">
<context>
    <name>ArmCalibration</name>
    <message>
        <source>no position was read from servo %1</source>
        <translation>von Servo %1 wurde keine Position gelesen</translation>
    </message>
    <message>
        <source>servo %1 stopped answering during the recording: record again</source>
        <translation>Servo %1 antwortete während der Aufzeichnung nicht mehr: erneut aufzeichnen</translation>
    </message>
    <message>
        <source>the joint never moved (%1 steps; move it through its whole range)</source>
        <translation>das Gelenk wurde nie bewegt (%1 Schritte; bewegen Sie es durch seinen ganzen Bereich)</translation>
    </message>
    <message>
        <source>the range of %1 steps is wider than the encoder allows (%2 steps: a turn less a safety margin of %3); is this a full-turn joint?</source>
        <translation>der Bereich von %1 Schritten ist breiter, als der Encoder erlaubt (%2 Schritte: eine Umdrehung abzüglich eines Sicherheitsabstands von %3); ist dies ein Gelenk mit voller Umdrehung?</translation>
    </message>
    <message>
        <source>the middle pose %1 is not a position of the encoder</source>
        <translation>die Mittelpose %1 ist keine Position des Encoders</translation>
    </message>
    <message>
        <source>from the middle pose, the range (%1 to %2) would cross the encoder&apos;s 0/4095 seam: take a middle pose nearer the middle of the joint&apos;s travel, or use ServoBench&apos;s order</source>
        <translation>von der Mittelpose aus würde der Bereich (%1 bis %2) die 0/4095-Naht des Encoders überschreiten: nehmen Sie eine Mittelpose näher an der Mitte des Gelenkwegs ein oder verwenden Sie die Reihenfolge von ServoBench</translation>
    </message>
    <message>
        <source>the limits %1 to %2 are outside what the servo holds (at most %3 and %4)</source>
        <translation>die Grenzen %1 bis %2 liegen außerhalb dessen, was das Servo speichern kann (höchstens %3 und %4)</translation>
    </message>
    <message>
        <source>no middle pose was taken for this joint</source>
        <translation>für dieses Gelenk wurde keine Mittelpose eingenommen</translation>
    </message>
    <message>
        <source>%1: wrote %2, the servo holds %3</source>
        <translation>%1: %2 geschrieben, das Servo enthält %3</translation>
    </message>
    <message>
        <source>nothing</source>
        <translation>nichts</translation>
    </message>
    <message>
        <source>%1: the file says %2, the servo holds %3</source>
        <translation>%1: Die Datei sagt %2, das Servo hält %3</translation>
    </message>
    <message>
        <source>nothing readable</source>
        <translation>nichts Lesbares</translation>
    </message>
</context>
<context>
    <name>BatchResultDialog</name>
    <message>
        <source>Programming results</source>
        <translation>Programmierergebnisse</translation>
    </message>
    <message numerus="yes">
        <source>%1 to %n servo(s): %2 written and verified, %3 unchanged, %4 failed.</source>
        <translation>
            <numerusform>%1 auf %n Servo: %2 geschrieben und verifiziert, %3 unverändert, %4 fehlgeschlagen.</numerusform>
            <numerusform>%1 auf %n Servos: %2 geschrieben und verifiziert, %3 unverändert, %4 fehlgeschlagen.</numerusform>
        </translation>
    </message>
    <message>
        <source>Servo</source>
        <translation>Servo</translation>
    </message>
    <message>
        <source>Status</source>
        <translation>Status</translation>
    </message>
    <message>
        <source>Registers written</source>
        <translation>Geschriebene Register</translation>
    </message>
    <message>
        <source>Error</source>
        <translation>Fehler</translation>
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
        <translation>Strom des ausgewählten Servos trennen</translation>
    </message>
    <message>
        <source>Power the selected servo again</source>
        <translation>Ausgewähltes Servo wieder mit Strom versorgen</translation>
    </message>
    <message>
        <source>Break the daisy chain after the selected servo</source>
        <translation>Daisy-Chain nach dem ausgewählten Servo unterbrechen</translation>
    </message>
    <message>
        <source>Mend the daisy chain</source>
        <translation>Daisy-Chain reparieren</translation>
    </message>
    <message>
        <source>Block the selected servo&apos;s horn</source>
        <translation>Servohorn des ausgewählten Servos blockieren</translation>
    </message>
    <message>
        <source>Free the selected servo&apos;s horn</source>
        <translation>Servohorn des ausgewählten Servos freigeben</translation>
    </message>
    <message>
        <source>Heat the selected servo (%1 °C/s)</source>
        <translation>Ausgewähltes Servo erhitzen (%1 °C/s)</translation>
    </message>
    <message>
        <source>Stop heating the selected servo</source>
        <translation>Erhitzen des ausgewählten Servos beenden</translation>
    </message>
    <message>
        <source>Latch an overload on the selected servo</source>
        <translation>Überlastabschaltung am ausgewählten Servo auslösen</translation>
    </message>
    <message>
        <source>Supply %1 V to the bus (too high for 7.4 V servos)</source>
        <translation>%1 V an den Bus legen (zu hoch für 7.4-V-Servos)</translation>
    </message>
    <message>
        <source>Supply %1 V to the bus (too low)</source>
        <translation>%1 V an den Bus legen (zu niedrig)</translation>
    </message>
    <message>
        <source>Supply each servo its usual voltage</source>
        <translation>Jedes Servo mit seiner üblichen Spannung versorgen</translation>
    </message>
    <message>
        <source>Servo #%1 has no power: it hears and answers nothing.</source>
        <translation>Servo #%1 hat keinen Strom: Es hört nichts und antwortet nicht.</translation>
    </message>
    <message>
        <source>Servo #%1 has power again.</source>
        <translation>Servo #%1 hat wieder Strom.</translation>
    </message>
    <message>
        <source>The daisy chain is broken after servo #%1: the servos after it have neither signal nor power.</source>
        <translation>Die Daisy-Chain ist nach Servo #%1 unterbrochen: Die Servos dahinter haben weder Signal noch Strom.</translation>
    </message>
    <message>
        <source>The daisy chain is whole again.</source>
        <translation>Die Daisy-Chain ist wieder intakt.</translation>
    </message>
    <message>
        <source>Servo #%1&apos;s horn is blocked: driven, its load rises and it stays put.</source>
        <translation>Das Servohorn von Servo #%1 ist blockiert: Angesteuert steigt seine Last, und es bleibt stehen.</translation>
    </message>
    <message>
        <source>Servo #%1&apos;s horn is free.</source>
        <translation>Das Servohorn von Servo #%1 ist frei.</translation>
    </message>
    <message>
        <source>Servo #%1 warms steadily until it trips at its maximum temperature.</source>
        <translation>Servo #%1 erwärmt sich stetig, bis es bei seiner Maximaltemperatur abschaltet.</translation>
    </message>
    <message>
        <source>Servo #%1 is no longer heated: it cools toward the room&apos;s temperature.</source>
        <translation>Servo #%1 wird nicht mehr erhitzt: Es kühlt auf Raumtemperatur ab.</translation>
    </message>
    <message>
        <source>Servo #%1&apos;s overload is latched: its torque is gone until the bus is power-cycled.</source>
        <translation>Die Überlastabschaltung von Servo #%1 ist eingerastet: Sein Drehmoment bleibt weg, bis der Bus aus- und eingeschaltet wird.</translation>
    </message>
    <message>
        <source>The bus has a %1 V supply.</source>
        <translation>Der Bus hat eine Versorgung von %1 V.</translation>
    </message>
    <message>
        <source>Every servo has its usual supply again.</source>
        <translation>Jedes Servo hat wieder seine übliche Versorgung.</translation>
    </message>
</context>
<context>
    <name>BusDoctor</name>
    <message>
        <source>You may not open %1. Add yourself to the dialout group (sudo usermod -aG dialout $USER, then log out and back in), or give the adapter a udev rule that lets your account use it.</source>
        <translation>Sie dürfen %1 nicht öffnen. Fügen Sie sich der Gruppe dialout hinzu (sudo usermod -aG dialout $USER, dann ab- und wieder anmelden) oder geben Sie dem Adapter eine udev-Regel, die Ihrem Konto den Zugriff erlaubt.</translation>
    </message>
    <message>
        <source>You may not open %1: ask for access to serial ports.</source>
        <translation>Sie dürfen %1 nicht öffnen: Fordern Sie Zugriff auf serielle Anschlüsse an.</translation>
    </message>
    <message>
        <source>%1 is in use by %2. Close that program (or its connection to the port) and try again.</source>
        <translation>%1 wird von %2 verwendet. Schließen Sie dieses Programm (oder seine Verbindung zum Anschluss) und versuchen Sie es erneut.</translation>
    </message>
    <message>
        <source>%1 is in use by another program (a terminal, another ServoBench, a modem manager). Close it and try again.</source>
        <translation>%1 wird von einem anderen Programm verwendet (einem Terminal, einem anderen ServoBench, einem Modem-Manager). Schließen Sie es und versuchen Sie es erneut.</translation>
    </message>
    <message>
        <source>%1 does not exist. Plug the adapter in, or choose another port.</source>
        <translation>%1 existiert nicht. Stecken Sie den Adapter ein oder wählen Sie einen anderen Anschluss.</translation>
    </message>
    <message>
        <source>%1 could not be used: %2.</source>
        <translation>%1 konnte nicht verwendet werden: %2.</translation>
    </message>
    <message>
        <source>Not a single byte came back at any rate. Check the servos&apos; power supply (the USB adapter does not power them), the wiring (signal and ground), the adapter&apos;s direction switch or jumper, and that a TTL servo (SCS, STS) is not on an RS485 adapter, or an RS485 servo on a TTL one.</source>
        <translation>Bei keiner Baudrate kam auch nur ein Byte zurück. Prüfen Sie die Stromversorgung der Servos (der USB-Adapter versorgt sie nicht), die Verkabelung (Signal und Masse), den Richtungsschalter oder Jumper des Adapters und dass kein TTL-Servo (SCS, STS) an einem RS485-Adapter hängt oder ein RS485-Servo an einem TTL-Adapter.</translation>
    </message>
    <message>
        <source>The adapter sends back what it sends, so it works: the servos do not answer.</source>
        <translation>Der Adapter sendet zurück, was er sendet, er funktioniert also: Die Servos antworten nicht.</translation>
    </message>
    <message>
        <source>At %1, bytes came back but never a valid answer. A servo may be at another rate, the adapter may send back what it sends (try Echo On), or two servos may share one ID (connect them one at a time).</source>
        <translation>Bei %1 kamen Bytes zurück, aber nie eine gültige Antwort. Ein Servo läuft vielleicht mit einer anderen Baudrate, der Adapter sendet vielleicht zurück, was er sendet (versuchen Sie Echo Ein), oder zwei Servos teilen sich eine ID (schließen Sie sie einzeln an).</translation>
    </message>
    <message>
        <source>Servo %1 answers at %2, not at %3. Move it to %3.</source>
        <translation>Servo %1 antwortet bei %2, nicht bei %3. Stellen Sie es auf %3 um.</translation>
    </message>
    <message>
        <source>A servo (%1) answers at ID %2, %3: no servo is expected at that ID.</source>
        <translation>Ein Servo (%1) antwortet unter ID %2, %3: Unter dieser ID wird kein Servo erwartet.</translation>
    </message>
    <message>
        <source>If it is the missing servo %1, move it to ID %1 at %2.</source>
        <translation>Falls es das fehlende Servo %1 ist, stellen Sie es auf ID %1 bei %2 um.</translation>
    </message>
    <message>
        <source>If it is the missing servo %1, move it to ID %1.</source>
        <translation>Falls es das fehlende Servo %1 ist, stellen Sie es auf ID %1 um.</translation>
    </message>
    <message>
        <source>Servo %1 does not answer</source>
        <translation>Servo %1 antwortet nicht</translation>
    </message>
    <message>
        <source>Servos %1 do not answer</source>
        <translation>Servos %1 antworten nicht</translation>
    </message>
    <message>
        <source>%1, while every servo up to ID %2 in the chain does: check the cable after ID %2 (and its connectors at both ends).</source>
        <translation>%1, während jedes Servo bis ID %2 in der Kette antwortet: Prüfen Sie das Kabel nach ID %2 (und seine Stecker an beiden Enden).</translation>
    </message>
    <message>
        <source>Expected servo %1 does not answer</source>
        <translation>Erwartetes Servo %1 antwortet nicht</translation>
    </message>
    <message>
        <source>Expected servos %1 do not answer</source>
        <translation>Erwartete Servos %1 antworten nicht</translation>
    </message>
    <message>
        <source>%1. Check power and cables; a new servo is at ID 1 until it is set up (Set up motors, or servoctl feetech setup-motor).</source>
        <translation>%1. Prüfen Sie Stromversorgung und Kabel; ein neues Servo hat ID 1, bis es eingerichtet ist (Motoren einrichten oder servoctl feetech setup-motor).</translation>
    </message>
    <message>
        <source>Servo %1 answers a PING but its registers come back garbled: two servos may share ID %1. Connect them one at a time and give each its own ID.</source>
        <translation>Servo %1 antwortet auf PING, aber seine Register kommen verstümmelt zurück: Möglicherweise teilen sich zwei Servos die ID %1. Schließen Sie sie einzeln an und geben Sie jedem eine eigene ID.</translation>
    </message>
    <message>
        <source>%1–%2 V</source>
        <translation>%1–%2 V</translation>
    </message>
    <message>
        <source>its limits</source>
        <translation>seine Grenzwerte</translation>
    </message>
    <message>
        <source>%1 V</source>
        <translation>%1 V</translation>
    </message>
    <message>
        <source>an unknown voltage</source>
        <translation>eine unbekannte Spannung</translation>
    </message>
    <message>
        <source>Servo %1 reports %2 and a voltage error; it accepts %3. Check the supply: a 12 V supply on a 7.4 V servo, or a supply too weak for the load.</source>
        <translation>Servo %1 meldet %2 und einen Spannungsfehler; es akzeptiert %3. Prüfen Sie die Versorgung: ein 12-V-Netzteil an einem 7,4-V-Servo oder ein für die Last zu schwaches Netzteil.</translation>
    </message>
    <message>
        <source>A PTK servo answers on %1, not a Feetech bus: connect the Feetech adapter, or use the PTK workspace.</source>
        <translation>An %1 antwortet ein PTK-Servo, kein Feetech-Bus: Schließen Sie den Feetech-Adapter an oder verwenden Sie den PTK-Arbeitsbereich.</translation>
    </message>
    <message>
        <source>No servo answered at %1. Re-scan with the port probed: it listens at every rate and tells silence from bytes that never make an answer.</source>
        <translation>Bei %1 hat kein Servo geantwortet. Scannen Sie erneut mit Anschlussprüfung: Diese lauscht bei jeder Baudrate und unterscheidet Stille von Bytes, die nie eine Antwort ergeben.</translation>
    </message>
    <message>
        <source>You may not open the port</source>
        <translation>Keine Berechtigung für den Anschluss</translation>
    </message>
    <message>
        <source>Another program has the port</source>
        <translation>Ein anderes Programm belegt den Anschluss</translation>
    </message>
    <message>
        <source>The port is not there</source>
        <translation>Der Anschluss ist nicht vorhanden</translation>
    </message>
    <message>
        <source>The port could not be opened</source>
        <translation>Der Anschluss konnte nicht geöffnet werden</translation>
    </message>
    <message>
        <source>Nothing answers</source>
        <translation>Nichts antwortet</translation>
    </message>
    <message>
        <source>Bytes come back, but no answer</source>
        <translation>Bytes kommen zurück, aber keine Antwort</translation>
    </message>
    <message>
        <source>A PTK servo, not a Feetech bus</source>
        <translation>Ein PTK-Servo, kein Feetech-Bus</translation>
    </message>
    <message>
        <source>No servo found</source>
        <translation>Kein Servo gefunden</translation>
    </message>
    <message>
        <source>A servo at an unexpected ID</source>
        <translation>Ein Servo unter einer unerwarteten ID</translation>
    </message>
    <message>
        <source>A servo at another rate</source>
        <translation>Ein Servo mit anderer Baudrate</translation>
    </message>
    <message>
        <source>The chain is broken</source>
        <translation>Die Kette ist unterbrochen</translation>
    </message>
    <message>
        <source>Servos are missing</source>
        <translation>Servos fehlen</translation>
    </message>
    <message>
        <source>Two servos may share an ID</source>
        <translation>Zwei Servos teilen sich vielleicht eine ID</translation>
    </message>
    <message>
        <source>The supply voltage is wrong</source>
        <translation>Die Versorgungsspannung stimmt nicht</translation>
    </message>
</context>
<context>
    <name>BusShare</name>
    <message>
        <source>The bus is shared already, at %1.</source>
        <translation>Der Bus wird bereits geteilt, unter %1.</translation>
    </message>
    <message>
        <source>The port is not open: connect to the bus first.</source>
        <translation>Der Port ist nicht geöffnet: zuerst mit dem Bus verbinden.</translation>
    </message>
    <message>
        <source>Name the path the other program opens.</source>
        <translation>Den Pfad angeben, den das andere Programm öffnet.</translation>
    </message>
    <message>
        <source>%1 is the bus&apos;s own port: give the other program another path.</source>
        <translation>%1 ist der eigene Port des Busses: dem anderen Programm einen anderen Pfad geben.</translation>
    </message>
    <message>
        <source>The program set %1 baud, which the port refuses; it stays at %2 baud.</source>
        <translation>Das Programm hat %1 Baud eingestellt, was der Port ablehnt; er bleibt bei %2 Baud.</translation>
    </message>
    <message>
        <source>The program set %1 baud; the port follows.</source>
        <translation>Das Programm hat %1 Baud eingestellt; der Port folgt.</translation>
    </message>
    <message>
        <source>The adapter went away (%1): what the program sends is lost until it is back; the share waits for it.</source>
        <translation>Der Adapter ist weg (%1): was das Programm sendet, geht verloren, bis er zurück ist; die Freigabe wartet auf ihn.</translation>
    </message>
    <message>
        <source>The adapter is back: the share goes on.</source>
        <translation>Der Adapter ist zurück: die Freigabe läuft weiter.</translation>
    </message>
    <message>
        <source>The recording stopped after %1 line(s): %2. The share goes on.</source>
        <translation>Die Aufzeichnung endete nach %1 Zeile(n): %2. Die Freigabe läuft weiter.</translation>
    </message>
    <message>
        <source>%1 frame(s) (%2 bytes) from the program, %3 frame(s) (%4 bytes) back to it; %5 request(s) unanswered, %6 garbled byte(s), %7 alert(s), %8 watch read(s), %9 request(s) not sent because the program had sent the next.</source>
        <translation>%1 Frame(s) (%2 Bytes) vom Programm, %3 Frame(s) (%4 Bytes) zurück; %5 Anfrage(n) unbeantwortet, %6 verstümmelte(s) Byte(s), %7 Warnung(en), %8 Beobachtungs-Lesevorgang/-vorgänge, %9 Anfrage(n) nicht gesendet, weil das Programm schon die nächste gesendet hatte.</translation>
    </message>
</context>
<context>
    <name>CalibrationActions</name>
    <message>
        <source>&amp;Calibrate arm…</source>
        <translation>Arm &amp;kalibrieren…</translation>
    </message>
    <message>
        <source>Record each joint&apos;s range by hand and centre it on the encoder</source>
        <translation>Den Bereich jedes Gelenks von Hand aufzeichnen und auf dem Encoder zentrieren</translation>
    </message>
    <message>
        <source>&amp;Save calibration…</source>
        <translation>Kalibrierung &amp;speichern…</translation>
    </message>
    <message>
        <source>Save the servos&apos; offsets and limits as a LeRobot calibration file</source>
        <translation>Offsets und Grenzen der Servos als LeRobot-Kalibrierdatei speichern</translation>
    </message>
    <message>
        <source>&amp;Load calibration…</source>
        <translation>Kalibrierung &amp;laden…</translation>
    </message>
    <message>
        <source>Write a LeRobot calibration file to the servos, after showing what changes</source>
        <translation>Eine LeRobot-Kalibrierdatei auf die Servos schreiben, nachdem die Änderungen angezeigt wurden</translation>
    </message>
    <message>
        <source>Save calibration</source>
        <translation>Kalibrierung speichern</translation>
    </message>
    <message>
        <source>LeRobot calibration (*.json)</source>
        <translation>LeRobot-Kalibrierung (*.json)</translation>
    </message>
    <message>
        <source>Load calibration</source>
        <translation>Kalibrierung laden</translation>
    </message>
    <message>
        <source>Close the motor set-up (%1) before calibrating: it changes the servos&apos; IDs and settings.</source>
        <translation>Schließen Sie die Motoreinrichtung (%1) vor dem Kalibrieren: Sie ändert die IDs und Einstellungen der Servos.</translation>
    </message>
</context>
<context>
    <name>CalibrationFiles</name>
    <message>
        <source>LeRobot calibration (*.json)</source>
        <translation>LeRobot-Kalibrierung (*.json)</translation>
    </message>
    <message>
        <source>The arm&apos;s name, as LeRobot&apos;s --robot.id (or --teleop.id) gives it; it names the file:</source>
        <translation>Der Name des Arms, wie LeRobots --robot.id (oder --teleop.id) ihn angibt; er benennt die Datei:</translation>
    </message>
</context>
<context>
    <name>CalibrationJointsPage</name>
    <message>
        <source>Choose the joints to calibrate. ServoBench records how far each joint turns, then sets its position offset so that the middle of that range reads 2048, and its angle limits to the range: no joint&apos;s range crosses the encoder&apos;s 0/4095 seam.</source>
        <translation>Wählen Sie die zu kalibrierenden Gelenke. ServoBench zeichnet auf, wie weit sich jedes Gelenk dreht, setzt dann seinen Positions-Offset so, dass die Mitte dieses Bereichs 2048 ergibt, und seine Winkelgrenzen auf den Bereich: Kein Gelenkbereich überschreitet die 0/4095-Naht des Encoders.</translation>
    </message>
    <message>
        <source>No template (joints named by ID)</source>
        <translation>Keine Vorlage (Gelenke nach ID benannt)</translation>
    </message>
    <message>
        <source>Names the joints whose IDs the arm&apos;s template has</source>
        <translation>Benennt die Gelenke, deren IDs die Vorlage des Arms enthält</translation>
    </message>
    <message>
        <source>Robot:</source>
        <translation>Roboter:</translation>
    </message>
    <message>
        <source>Calibrate</source>
        <translation>Kalibrieren</translation>
    </message>
    <message>
        <source>ID</source>
        <translation>ID</translation>
    </message>
    <message>
        <source>Model</source>
        <translation>Modell</translation>
    </message>
    <message>
        <source>Joint</source>
        <translation>Gelenk</translation>
    </message>
    <message>
        <source>Full turn</source>
        <translation>Volle Umdrehung</translation>
    </message>
    <message>
        <source>Order</source>
        <translation>Reihenfolge</translation>
    </message>
    <message>
        <source>ServoBench: record each joint&apos;s range, then centre it on the encoder (recommended)</source>
        <translation>ServoBench: Bereich jedes Gelenks aufzeichnen, dann auf dem Encoder zentrieren (empfohlen)</translation>
    </message>
    <message>
        <source>LeRobot: put the arm in its middle pose first (it reads 2047), then record the ranges</source>
        <translation>LeRobot: Arm zuerst in seine Mittelpose bringen (sie ergibt 2047), dann die Bereiche aufzeichnen</translation>
    </message>
    <message>
        <source>&amp;Next</source>
        <translation>&amp;Weiter</translation>
    </message>
    <message>
        <source>Check the choice, then switch torque off</source>
        <translation>Auswahl prüfen, dann Drehmoment abschalten</translation>
    </message>
    <message>
        <source>%1 (no position offset)</source>
        <translation>%1 (kein Positions-Offset)</translation>
    </message>
    <message>
        <source>This servo has no position offset register: it cannot be calibrated</source>
        <translation>Dieses Servo hat kein Positions-Offset-Register: Es kann nicht kalibriert werden</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a joint name: use letters, digits and _, a letter first (LeRobot&apos;s motor names, such as shoulder_pan).</source>
        <translation>„%1“ ist kein Gelenkname: Verwenden Sie Buchstaben, Ziffern und _, beginnend mit einem Buchstaben (die Motornamen von LeRobot, etwa shoulder_pan).</translation>
    </message>
    <message>
        <source>Two joints are named &quot;%1&quot;: give each its own name.</source>
        <translation>Zwei Gelenke heißen „%1“: Geben Sie jedem einen eigenen Namen.</translation>
    </message>
    <message>
        <source>Servo %1 (%2) has no position offset on a 4096-step encoder: it cannot be calibrated. Leave it out.</source>
        <translation>Servo %1 (%2) hat keinen Positions-Offset auf einem 4096-Schritt-Encoder: Es kann nicht kalibriert werden. Lassen Sie es weg.</translation>
    </message>
    <message>
        <source>%1 (ID %2)</source>
        <translation>%1 (ID %2)</translation>
    </message>
    <message>
        <source>Choose at least one joint to calibrate.</source>
        <translation>Wählen Sie mindestens ein Gelenk zum Kalibrieren.</translation>
    </message>
</context>
<context>
    <name>CalibrationResultsPage</name>
    <message>
        <source>Each joint&apos;s new position offset and angle limits (in steps, in the new coordinates), or why it is refused. Nothing has been written yet.</source>
        <translation>Neuer Positions-Offset und neue Winkelgrenzen jedes Gelenks (in Schritten, in den neuen Koordinaten) oder warum es abgelehnt wird. Noch wurde nichts geschrieben.</translation>
    </message>
    <message>
        <source>Joint</source>
        <translation>Gelenk</translation>
    </message>
    <message>
        <source>Offset</source>
        <translation>Offset</translation>
    </message>
    <message>
        <source>Min limit</source>
        <translation>Min.-Grenze</translation>
    </message>
    <message>
        <source>Max limit</source>
        <translation>Max.-Grenze</translation>
    </message>
    <message>
        <source>Status</source>
        <translation>Status</translation>
    </message>
    <message>
        <source>&amp;Write to the servos</source>
        <translation>&amp;Auf die Servos schreiben</translation>
    </message>
    <message>
        <source>Write the offsets and limits to EEPROM and verify them</source>
        <translation>Offsets und Grenzen ins EEPROM schreiben und verifizieren</translation>
    </message>
    <message>
        <source>&amp;Save LeRobot file…</source>
        <translation>LeRobot-Datei &amp;speichern…</translation>
    </message>
    <message>
        <source>Save the written calibration as LeRobot&apos;s JSON file</source>
        <translation>Die geschriebene Kalibrierung als JSON-Datei von LeRobot speichern</translation>
    </message>
    <message>
        <source>&amp;Record again</source>
        <translation>&amp;Erneut aufzeichnen</translation>
    </message>
    <message>
        <source>Forget this recording and record the ranges again</source>
        <translation>Diese Aufzeichnung verwerfen und die Bereiche erneut aufzeichnen</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>To write</source>
        <translation>Zu schreiben</translation>
    </message>
    <message>
        <source>Refused, nothing written: %1</source>
        <translation>Abgelehnt, nichts geschrieben: %1</translation>
    </message>
    <message>
        <source>Written and verified</source>
        <translation>Geschrieben und verifiziert</translation>
    </message>
    <message>
        <source>Writing each joint&apos;s offset and limits to its EEPROM and reading them back…</source>
        <translation>Offset und Grenzen jedes Gelenks werden in sein EEPROM geschrieben und zurückgelesen…</translation>
    </message>
    <message>
        <source>Every joint&apos;s offset and limits were written to its EEPROM and read back as written.</source>
        <translation>Offset und Grenzen jedes Gelenks wurden in sein EEPROM geschrieben und unverändert zurückgelesen.</translation>
    </message>
    <message>
        <source>No joint&apos;s calibration was written and verified: the status column says why.</source>
        <translation>Die Kalibrierung keines Gelenks wurde geschrieben und verifiziert: Die Statusspalte zeigt, warum.</translation>
    </message>
    <message numerus="yes">
        <source>%1 of %n joint(s) were written and verified; the status column says what became of the others.</source>
        <translation>
            <numerusform>Geschrieben und verifiziert: %1 von %n Gelenk; die Statusspalte zeigt, was aus den übrigen wurde.</numerusform>
            <numerusform>Geschrieben und verifiziert: %1 von %n Gelenken; die Statusspalte zeigt, was aus den übrigen wurde.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>CalibrationSaver</name>
    <message>
        <source>Servo %1 could not be read: %2; nothing was saved.</source>
        <translation>Servo %1 konnte nicht gelesen werden: %2; es wurde nichts gespeichert.</translation>
    </message>
    <message>
        <source>Servo %1 holds the limits %2 to %3, which are no calibrated range; nothing was saved.</source>
        <translation>Servo %1 hat die Grenzen %2 bis %3, die keinen kalibrierten Bereich darstellen; es wurde nichts gespeichert.</translation>
    </message>
    <message numerus="yes">
        <source>Saved the calibration of %n joint(s) to %1.</source>
        <translation>
            <numerusform>Kalibrierung von %n Gelenk in %1 gespeichert.</numerusform>
            <numerusform>Kalibrierung von %n Gelenken in %1 gespeichert.</numerusform>
        </translation>
    </message>
    <message>
        <source>No servo on the bus has a position offset to save.</source>
        <translation>Kein Servo am Bus hat einen Positions-Offset, der gespeichert werden könnte.</translation>
    </message>
</context>
<context>
    <name>CalibrationSteps</name>
    <message>
        <source>The bus was disconnected.</source>
        <translation>Die Verbindung zum Bus wurde getrennt.</translation>
    </message>
    <message>
        <source>The bus is not connected.</source>
        <translation>Der Bus ist nicht verbunden.</translation>
    </message>
    <message>
        <source>Written and verified.</source>
        <translation>Geschrieben und verifiziert.</translation>
    </message>
    <message>
        <source>Verification failed: %1</source>
        <translation>Verifizierung fehlgeschlagen: %1</translation>
    </message>
</context>
<context>
    <name>CalibrationWizard</name>
    <message>
        <source>Calibrate the arm</source>
        <translation>Arm kalibrieren</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <source>Torque is off, but the recording could not start: %1</source>
        <translation>Das Drehmoment ist aus, aber die Aufzeichnung konnte nicht starten: %1</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>Schließen</translation>
    </message>
    <message>
        <source>Support the arm: torque goes off on these joints, and the arm will fall under its own weight if nothing holds it.

%1</source>
        <translation>Stützen Sie den Arm: Das Drehmoment dieser Gelenke wird abgeschaltet, und der Arm fällt unter seinem eigenen Gewicht, wenn ihn nichts hält.

%1</translation>
    </message>
    <message>
        <source>Reading the joints and switching torque off…</source>
        <translation>Gelenke werden gelesen und Drehmoment abgeschaltet…</translation>
    </message>
    <message>
        <source>Servo %1: %2</source>
        <translation>Servo %1: %2</translation>
    </message>
    <message>
        <source>%1 (%2): %3</source>
        <translation>%1 (%2): %3</translation>
    </message>
    <message>
        <source>no reading yet</source>
        <translation>noch kein Messwert</translation>
    </message>
    <message>
        <source>stopped answering</source>
        <translation>antwortet nicht mehr</translation>
    </message>
    <message>
        <source>min %1 · present %2 · max %3</source>
        <translation>min %1 · aktuell %2 · max %3</translation>
    </message>
    <message>
        <source>No position has come from %1 (ID %2) yet: check that it answers.</source>
        <translation>Von %1 (ID %2) ist noch keine Position gekommen: Prüfen Sie, ob es antwortet.</translation>
    </message>
    <message>
        <source>Check the results, then write them to the servos.</source>
        <translation>Prüfen Sie die Ergebnisse und schreiben Sie sie dann auf die Servos.</translation>
    </message>
    <message>
        <source>No joint can be calibrated from this recording: press Record again and move every joint through its range.</source>
        <translation>Aus dieser Aufzeichnung kann kein Gelenk kalibriert werden: Drücken Sie „Erneut aufzeichnen“ und bewegen Sie jedes Gelenk durch seinen Bereich.</translation>
    </message>
    <message>
        <source>No joint was written: there is nothing to save.</source>
        <translation>Kein Gelenk wurde geschrieben: Es gibt nichts zu speichern.</translation>
    </message>
    <message>
        <source>Save LeRobot calibration</source>
        <translation>LeRobot-Kalibrierung speichern</translation>
    </message>
    <message>
        <source>Saved %1.</source>
        <translation>%1 gespeichert.</translation>
    </message>
    <message>
        <source>Nothing is written to the servos until you have seen the results and chosen to write them. Cancel at any point writes nothing (torque stays off).</source>
        <translation>Nichts wird auf die Servos geschrieben, bevor Sie die Ergebnisse gesehen und das Schreiben gewählt haben. Abbrechen schreibt zu jedem Zeitpunkt nichts (das Drehmoment bleibt aus).</translation>
    </message>
    <message>
        <source>I am supporting the arm: switch torque &amp;off</source>
        <translation>Ich stütze den Arm: Drehmoment &amp;abschalten</translation>
    </message>
    <message>
        <source>Switch torque off on the joints and start</source>
        <translation>Drehmoment der Gelenke abschalten und beginnen</translation>
    </message>
    <message>
        <source>&amp;Back</source>
        <translation>&amp;Zurück</translation>
    </message>
    <message>
        <source>Choose the joints again</source>
        <translation>Gelenke erneut auswählen</translation>
    </message>
    <message>
        <source>Move every joint to the middle of its travel (LeRobot&apos;s middle pose: the arm stretched out level, the gripper half open), then take the pose. Each joint&apos;s present position there will read 2047.</source>
        <translation>Bewegen Sie jedes Gelenk in die Mitte seines Wegs (die Mittelpose von LeRobot: Arm waagerecht ausgestreckt, Greifer halb offen) und nehmen Sie dann die Pose. Die aktuelle Position jedes Gelenks ergibt dort 2047.</translation>
    </message>
    <message>
        <source>&amp;Take the middle pose</source>
        <translation>&amp;Mittelpose übernehmen</translation>
    </message>
    <message>
        <source>Keep the present positions as the middle</source>
        <translation>Die aktuellen Positionen als Mitte behalten</translation>
    </message>
    <message>
        <source>Move every joint slowly through its whole range, to both end stops, and back to the middle. Turn a full-turn joint as far as you want it to go. The bars show one turn of the encoder: the filled part is the range recorded so far, the line the present position, the dashed line the middle the range will be centred on.</source>
        <translation>Bewegen Sie jedes Gelenk langsam durch seinen ganzen Bereich, bis zu beiden Endanschlägen, und zurück zur Mitte. Drehen Sie ein Gelenk mit voller Umdrehung so weit, wie es gehen soll. Die Balken zeigen eine Umdrehung des Encoders: Der gefüllte Teil ist der bisher aufgezeichnete Bereich, die Linie die aktuelle Position, die gestrichelte Linie die Mitte, auf die der Bereich zentriert wird.</translation>
    </message>
    <message>
        <source>&amp;Finish recording</source>
        <translation>Aufzeichnung &amp;beenden</translation>
    </message>
    <message>
        <source>Stop recording and compute the calibration</source>
        <translation>Aufzeichnung stoppen und Kalibrierung berechnen</translation>
    </message>
    <message>
        <source>%1 (%2)%3</source>
        <translation>%1 (%2)%3</translation>
    </message>
    <message>
        <source>, full turn</source>
        <translation>, volle Umdrehung</translation>
    </message>
    <message>
        <source>Calibrate the new %1 servo</source>
        <translation>Das neue Servo %1 kalibrieren</translation>
    </message>
    <message>
        <source>&amp;Save into %1</source>
        <translation>In %1 &amp;speichern</translation>
    </message>
    <message>
        <source>Update %1: this joint&apos;s offset and range replaced, the other joints kept</source>
        <translation>%1 aktualisieren: Offset und Bereich dieses Gelenks werden ersetzt, die anderen Gelenke bleiben erhalten</translation>
    </message>
    <message>
        <source>Save the joint into %1: the file&apos;s other joints stay as they are.</source>
        <translation>Speichern Sie das Gelenk in %1: Die anderen Gelenke der Datei bleiben unverändert.</translation>
    </message>
    <message>
        <source>Saving LeRobot&apos;s file keeps only the joints written and verified.</source>
        <translation>Beim Speichern der LeRobot-Datei werden nur die geschriebenen und verifizierten Gelenke übernommen.</translation>
    </message>
    <message>
        <source>Save LeRobot&apos;s file if you use LeRobot with this arm.</source>
        <translation>Speichern Sie die LeRobot-Datei, wenn Sie LeRobot mit diesem Arm verwenden.</translation>
    </message>
    <message>
        <source>Servo ID %1 is being calibrated: close the calibration wizard first.</source>
        <translation>Servo-ID %1 wird gerade kalibriert: Schließen Sie zuerst den Kalibrierassistenten.</translation>
    </message>
</context>
<context>
    <name>ConnectionBar</name>
    <message>
        <source>Connection</source>
        <translation>Verbindung</translation>
    </message>
    <message>
        <source>Port </source>
        <translation>Anschluss </translation>
    </message>
    <message>
        <source>The serial port of the USB programmer, or a simulated servo</source>
        <translation>Der serielle Anschluss des USB-Programmiergeräts oder ein simuliertes Servo</translation>
    </message>
    <message>
        <source>Baud </source>
        <translation>Baud </translation>
    </message>
    <message>
        <source>PTK servos talk at 115200 baud. On a Feetech bus this is the rate the port opens at; a scan visits the rates it is asked to.</source>
        <translation>PTK-Servos kommunizieren mit 115200 Baud. An einem Feetech-Bus ist dies die Baudrate, mit der der Anschluss geöffnet wird; ein Scan prüft die Baudraten, die ihm vorgegeben werden.</translation>
    </message>
    <message>
        <source>Protocol </source>
        <translation>Protokoll </translation>
    </message>
    <message>
        <source>PTK RC servo</source>
        <translation>PTK-RC-Servo</translation>
    </message>
    <message>
        <source>Feetech bus</source>
        <translation>Feetech-Bus</translation>
    </message>
    <message>
        <source>Echo </source>
        <translation>Echo </translation>
    </message>
    <message>
        <source>Auto</source>
        <translation>Auto</translation>
    </message>
    <message>
        <source>On</source>
        <translation>Ein</translation>
    </message>
    <message>
        <source>Off</source>
        <translation>Aus</translation>
    </message>
    <message>
        <source>Single-wire programmers send every byte back. Auto detects it.</source>
        <translation>Eindraht-Programmiergeräte senden jedes Byte zurück. Auto erkennt das.</translation>
    </message>
    <message>
        <source>Connect</source>
        <translation>Verbinden</translation>
    </message>
    <message>
        <source>Disconnect</source>
        <translation>Trennen</translation>
    </message>
    <message>
        <source>Simulated PTK servo</source>
        <translation>Simuliertes PTK-Servo</translation>
    </message>
    <message>
        <source>Simulated Feetech bus</source>
        <translation>Simulierter Feetech-Bus</translation>
    </message>
    <message>
        <source>Auto: ServoBench asks the port who is there (it only asks, it writes nothing) and opens the right workspace at the right rate. PTK: one RC servo on a USB programmer. Feetech: SCS, STS, SMS and HLS servos on a serial bus.</source>
        <translation>Auto: ServoBench fragt am Anschluss, wer da ist (es fragt nur und schreibt nichts), und öffnet den passenden Arbeitsbereich mit der passenden Baudrate. PTK: ein RC-Servo an einem USB-Programmiergerät. Feetech: SCS-, STS-, SMS- und HLS-Servos an einem seriellen Bus.</translation>
    </message>
    <message>
        <source>Simulated SO-101 arm</source>
        <translation>Simulierter SO-101-Arm</translation>
    </message>
    <message>
        <source>Choose a port</source>
        <translation>Anschluss wählen</translation>
    </message>
    <message>
        <source>Choose a serial port or a simulated servo first</source>
        <translation>Wählen Sie zuerst einen seriellen Anschluss oder ein simuliertes Servo</translation>
    </message>
</context>
<context>
    <name>ConnectionController</name>
    <message>
        <source>Choose a serial port first.</source>
        <translation>Wählen Sie zuerst einen seriellen Anschluss.</translation>
    </message>
    <message>
        <source>The simulated servos could not start: %1</source>
        <translation>Die simulierten Servos konnten nicht starten: %1</translation>
    </message>
    <message>
        <source>simulated SO-101 arm</source>
        <translation>simulierter SO-101-Arm</translation>
    </message>
    <message>
        <source>simulated Feetech bus</source>
        <translation>simulierter Feetech-Bus</translation>
    </message>
    <message>
        <source>simulated PTK servo</source>
        <translation>simuliertes PTK-Servo</translation>
    </message>
    <message>
        <source>Enter a baud rate.</source>
        <translation>Geben Sie eine Baudrate ein.</translation>
    </message>
    <message>
        <source>Auto-detection cancelled; nothing was connected.</source>
        <translation>Automatische Erkennung abgebrochen; es wurde nichts verbunden.</translation>
    </message>
    <message>
        <source>A PTK servo answers at 115,200 bps.</source>
        <translation>Ein PTK-Servo antwortet mit 115.200 bps.</translation>
    </message>
    <message>
        <source>Nothing answers on %1: the Doctor panel says what to check.</source>
        <translation>An %1 antwortet nichts: Das Diagnosefeld sagt, was zu prüfen ist.</translation>
    </message>
</context>
<context>
    <name>ControlPage</name>
    <message>
        <source>Damping: the horn can be turned by hand against a resistance (torque enable 2).</source>
        <translation>Dämpfung: Das Servohorn lässt sich von Hand gegen einen Widerstand drehen (torque enable 2).</translation>
    </message>
    <message>
        <source>Servo ID %1</source>
        <translation>Servo-ID %1</translation>
    </message>
    <message>
        <source>%1 servos have no damping mode.</source>
        <translation>%1-Servos haben keinen Dämpfungsmodus.</translation>
    </message>
    <message>
        <source>Stored in EEPROM: the servo keeps it when powered off.</source>
        <translation>Im EEPROM gespeichert: Das Servo behält es nach dem Ausschalten.</translation>
    </message>
    <message>
        <source>%1 servos have no operating mode register: they hold positions.</source>
        <translation>%1-Servos haben kein Betriebsart-Register: Sie halten Positionen.</translation>
    </message>
    <message>
        <source>Goals are limited to the servo&apos;s angle limits, %1 to %2 steps.</source>
        <translation>Ziele sind auf die Winkelgrenzen des Servos begrenzt, %1 bis %2 Schritte.</translation>
    </message>
    <message>
        <source>The servo has no angle limits (multi-turn) or they are not read yet: goals are limited to the register&apos;s range, %1 to %2.</source>
        <translation>Das Servo hat keine Winkelgrenzen (Multi-Turn) oder sie sind noch nicht gelesen: Ziele sind auf den Bereich des Registers begrenzt, %1 bis %2.</translation>
    </message>
    <message>
        <source>Torque state not read yet.</source>
        <translation>Drehmomentzustand noch nicht gelesen.</translation>
    </message>
    <message>
        <source>Off: the horn turns freely.</source>
        <translation>Aus: Das Servohorn dreht sich frei.</translation>
    </message>
    <message>
        <source>On: the servo holds its goal position.</source>
        <translation>Ein: Das Servo hält seine Zielposition.</translation>
    </message>
    <message>
        <source>Damping: the horn resists being turned.</source>
        <translation>Dämpfung: Das Servohorn widersetzt sich dem Drehen.</translation>
    </message>
    <message>
        <source>Torque enable is %1.</source>
        <translation>Torque enable ist %1.</translation>
    </message>
    <message>
        <source>Select a servo in the tree to control it.</source>
        <translation>Wählen Sie im Baum ein Servo aus, um es zu steuern.</translation>
    </message>
    <message>
        <source>The bus is not connected: connect and scan to control servos.</source>
        <translation>Der Bus ist nicht verbunden: Verbinden und scannen Sie, um Servos zu steuern.</translation>
    </message>
    <message>
        <source>This servo&apos;s model is unknown: ServoBench does not move it.</source>
        <translation>Das Modell dieses Servos ist unbekannt: ServoBench bewegt es nicht.</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>No servo is selected.</source>
        <translation>Kein Servo ausgewählt.</translation>
    </message>
    <message>
        <source>The servo cannot be moved now: the bus is not connected or its model is unknown.</source>
        <translation>Das Servo kann jetzt nicht bewegt werden: Der Bus ist nicht verbunden oder sein Modell ist unbekannt.</translation>
    </message>
    <message>
        <source>A test is moving %1: stop it first.</source>
        <translation>Ein Test bewegt %1: Stoppen Sie ihn zuerst.</translation>
    </message>
    <message>
        <source>%1 has no goal position register.</source>
        <translation>%1 hat kein Zielpositionsregister.</translation>
    </message>
    <message>
        <source>Goal %1 is outside %2, %3 to %4 steps: nothing was sent.</source>
        <translation>Ziel %1 liegt außerhalb %2, %3 bis %4 Schritte: Es wurde nichts gesendet.</translation>
    </message>
    <message>
        <source>the servo&apos;s angle limits</source>
        <translation>der Winkelgrenzen des Servos</translation>
    </message>
    <message>
        <source>the goal position range</source>
        <translation>des Zielpositionsbereichs</translation>
    </message>
    <message>
        <source>Torque is off: %1 keeps the goal but does not move until torque is on.</source>
        <translation>Das Drehmoment ist aus: %1 behält das Ziel, bewegt sich aber erst, wenn das Drehmoment eingeschaltet ist.</translation>
    </message>
    <message>
        <source>unknown</source>
        <translation>unbekannt</translation>
    </message>
    <message>
        <source>Change the operating mode?</source>
        <translation>Betriebsart ändern?</translation>
    </message>
    <message>
        <source>%1 will change from “%2” to “%3”.</source>
        <translation>%1 wechselt von „%2“ zu „%3“.</translation>
    </message>
    <message>
        <source>The servo will move differently from now on: in speed or PWM mode the goal registers make it turn continuously instead of holding a position. The mode is written to EEPROM and kept after power-off.</source>
        <translation>Das Servo bewegt sich ab jetzt anders: Im Geschwindigkeits- oder PWM-Modus lassen die Zielregister es dauerhaft drehen, statt eine Position zu halten. Die Betriebsart wird ins EEPROM geschrieben und bleibt nach dem Ausschalten erhalten.</translation>
    </message>
    <message>
        <source>Change mode</source>
        <translation>Betriebsart ändern</translation>
    </message>
    <message>
        <source>Writing to servo ID %1 failed: %2</source>
        <translation>Schreiben auf Servo-ID %1 fehlgeschlagen: %2</translation>
    </message>
    <message>
        <source>Off: All torque off was sent to every servo.</source>
        <translation>Aus: „Alle Drehmomente aus“ wurde an jedes Servo gesendet.</translation>
    </message>
    <message>
        <source>The bus is shared with another program: ServoBench neither reads nor moves this servo meanwhile. Stop sharing (Link › Share this bus…) to control it here.</source>
        <translation>Der Bus wird mit einem anderen Programm geteilt: ServoBench liest und bewegt dieses Servo währenddessen nicht. Beenden Sie die Freigabe (Verbindung › Diesen Bus teilen…), um es hier zu steuern.</translation>
    </message>
    <message>
        <source>All torque off was sent to every servo of the bus; each one&apos;s torque is read back to confirm it.</source>
        <translation>Alles Drehmoment aus wurde an jedes Servo des Busses gesendet; das Drehmoment jedes Servos wird zur Bestätigung zurückgelesen.</translation>
    </message>
</context>
<context>
    <name>Decoder</name>
    <message numerus="yes">
        <source>incomplete frame (%n byte(s))</source>
        <translation>
            <numerusform>unvollständiger Frame (%n Byte)</numerusform>
            <numerusform>unvollständiger Frame (%n Bytes)</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n byte(s) that are not part of any frame</source>
        <translation>
            <numerusform>%n Byte, das zu keinem Frame gehört</numerusform>
            <numerusform>%n Bytes, die zu keinem Frame gehören</numerusform>
        </translation>
    </message>
    <message>
        <source>query %1 (command %2) asks for %3</source>
        <translation>Abfrage %1 (Befehl %2) fragt nach %3</translation>
    </message>
    <message>
        <source>write %1 (command %2) %3</source>
        <translation>Schreiben %1 (Befehl %2) %3</translation>
    </message>
    <message>
        <source>with zero payload</source>
        <translation>ohne Nutzdaten</translation>
    </message>
    <message>
        <source>request with unknown command %1, payload %2 %3</source>
        <translation>Anfrage mit unbekanntem Befehl %1, Nutzdaten %2 %3</translation>
    </message>
    <message>
        <source>reply to %1: %2</source>
        <translation>Antwort auf %1: %2</translation>
    </message>
    <message>
        <source>reply (query unknown): words %1, %2</source>
        <translation>Antwort (Abfrage unbekannt): Wörter %1, %2</translation>
    </message>
    <message>
        <source>ID %1 (broadcast)</source>
        <translation>ID %1 (Broadcast)</translation>
    </message>
    <message>
        <source>ID %1</source>
        <translation>ID %1</translation>
    </message>
    <message>
        <source>status from %1: %2</source>
        <translation>Status von %1: %2</translation>
    </message>
    <message>
        <source>no error</source>
        <translation>kein Fehler</translation>
    </message>
    <message>
        <source>error %1 (%2)</source>
        <translation>Fehler %1 (%2)</translation>
    </message>
    <message>
        <source>, data %1</source>
        <translation>, Daten %1</translation>
    </message>
    <message>
        <source>address %1 (%2), length %3</source>
        <translation>Adresse %1 (%2), Länge %3</translation>
    </message>
    <message>
        <source>address %1 (%2), data %3</source>
        <translation>Adresse %1 (%2), Daten %3</translation>
    </message>
    <message>
        <source>address %1 (%2), length %3, IDs %4</source>
        <translation>Adresse %1 (%2), Länge %3, IDs %4</translation>
    </message>
    <message>
        <source>ID %1: %2</source>
        <translation>ID %1: %2</translation>
    </message>
    <message>
        <source>address %1 (%2), length %3; %4</source>
        <translation>Adresse %1 (%2), Länge %3; %4</translation>
    </message>
    <message>
        <source>current position becomes the middle</source>
        <translation>aktuelle Position wird zur Mitte</translation>
    </message>
    <message>
        <source>current position becomes %1</source>
        <translation>aktuelle Position wird zu %1</translation>
    </message>
    <message>
        <source>parameters %1</source>
        <translation>Parameter %1</translation>
    </message>
    <message>
        <source>PING</source>
        <comment>instruction</comment>
        <translation>PING</translation>
    </message>
    <message>
        <source>READ</source>
        <comment>instruction</comment>
        <translation>READ</translation>
    </message>
    <message>
        <source>WRITE</source>
        <comment>instruction</comment>
        <translation>WRITE</translation>
    </message>
    <message>
        <source>REG WRITE</source>
        <comment>instruction</comment>
        <translation>REG WRITE</translation>
    </message>
    <message>
        <source>ACTION</source>
        <comment>instruction</comment>
        <translation>ACTION</translation>
    </message>
    <message>
        <source>RECOVERY</source>
        <comment>instruction</comment>
        <translation>RECOVERY</translation>
    </message>
    <message>
        <source>REBOOT</source>
        <comment>instruction</comment>
        <translation>REBOOT</translation>
    </message>
    <message>
        <source>BACKUP</source>
        <comment>instruction</comment>
        <translation>BACKUP</translation>
    </message>
    <message>
        <source>RESET</source>
        <comment>instruction</comment>
        <translation>RESET</translation>
    </message>
    <message>
        <source>CALIBRATE</source>
        <comment>instruction</comment>
        <translation>CALIBRATE</translation>
    </message>
    <message>
        <source>SYNC READ</source>
        <comment>instruction</comment>
        <translation>SYNC READ</translation>
    </message>
    <message>
        <source>SYNC WRITE</source>
        <comment>instruction</comment>
        <translation>SYNC WRITE</translation>
    </message>
</context>
<context>
    <name>DemoServos</name>
    <message>
        <source>Cannot create a folder for the simulated servos: %1</source>
        <translation>Ordner für die simulierten Servos kann nicht angelegt werden: %1</translation>
    </message>
    <message>
        <source>Simulated PTK servo</source>
        <translation>Simuliertes PTK-Servo</translation>
    </message>
    <message>
        <source>Simulated Feetech bus</source>
        <translation>Simulierter Feetech-Bus</translation>
    </message>
    <message>
        <source>Simulated SO-101 arm</source>
        <translation>Simulierter SO-101-Arm</translation>
    </message>
    <message>
        <source>Simulated SO-101 leader arm</source>
        <translation>Simulierter SO-101-Führungsarm</translation>
    </message>
</context>
<context>
    <name>DoctorPanel</name>
    <message>
        <source>Move servo %1 (%2) to ID %3 at %4</source>
        <translation>Servo %1 (%2) auf ID %3 bei %4 umstellen</translation>
    </message>
    <message>
        <source>Move servo %1 to ID %2</source>
        <translation>Servo %1 auf ID %2 umstellen</translation>
    </message>
    <message>
        <source>Move servo %1 to %2</source>
        <translation>Servo %1 auf %2 umstellen</translation>
    </message>
    <message>
        <source>Doctor</source>
        <translation>Diagnose</translation>
    </message>
    <message>
        <source>Scan a bus: when it comes back short, the doctor says why.</source>
        <translation>Scannen Sie einen Bus: Wenn Servos fehlen, sagt die Diagnose, warum.</translation>
    </message>
    <message>
        <source>The bus should hold:</source>
        <translation>Der Bus sollte enthalten:</translation>
    </message>
    <message>
        <source>the servos found last time on this port</source>
        <translation>die zuletzt an diesem Anschluss gefundenen Servos</translation>
    </message>
    <message>
        <source>A robot template: its joints&apos; IDs in chain order, at its rate</source>
        <translation>Eine Robotervorlage: die IDs ihrer Gelenke in Kettenreihenfolge, mit ihrer Baudrate</translation>
    </message>
    <message>
        <source>Finding</source>
        <translation>Befund</translation>
    </message>
    <message>
        <source>IDs</source>
        <translation>IDs</translation>
    </message>
    <message>
        <source>What is wrong and what to do</source>
        <translation>Was falsch ist und was zu tun ist</translation>
    </message>
    <message>
        <source>Re-scan</source>
        <translation>Erneut scannen</translation>
    </message>
    <message>
        <source>Ask the port again and scan the rates that answer</source>
        <translation>Den Anschluss erneut abfragen und die antwortenden Baudraten scannen</translation>
    </message>
    <message>
        <source>Move the servo</source>
        <translation>Servo umstellen</translation>
    </message>
    <message>
        <source>Looking at the bus on %1…</source>
        <translation>Bus an %1 wird untersucht…</translation>
    </message>
    <message>
        <source>The bus on %1 holds what was expected.</source>
        <translation>Der Bus an %1 enthält, was erwartet wurde.</translation>
    </message>
    <message numerus="yes">
        <source>The bus on %1: %n finding(s).</source>
        <translation>
            <numerusform>Der Bus an %1: %n Befund.</numerusform>
            <numerusform>Der Bus an %1: %n Befunde.</numerusform>
        </translation>
    </message>
    <message>
        <source>Servo %1 is no longer on the bus; re-scan first.</source>
        <translation>Servo %1 ist nicht mehr am Bus; scannen Sie zuerst erneut.</translation>
    </message>
    <message>
        <source>%1? Its EEPROM is written and read back.</source>
        <translation>%1? Sein EEPROM wird geschrieben und zurückgelesen.</translation>
    </message>
    <message>
        <source>The servo moved to its new ID could not be found to change its rate; re-scan.</source>
        <translation>Das auf die neue ID umgestellte Servo wurde nicht gefunden, um seine Baudrate zu ändern; scannen Sie erneut.</translation>
    </message>
    <message>
        <source>Code</source>
        <translation>Code</translation>
    </message>
    <message>
        <source>%1 (code %2)</source>
        <translation>%1 (Code %2)</translation>
    </message>
    <message>
        <source>The finding&apos;s code, as servoctl doctor prints it</source>
        <translation>Der Code des Befunds, wie servoctl doctor ihn ausgibt</translation>
    </message>
</context>
<context>
    <name>Faults</name>
    <message>
        <source>--faults: &quot;%1&quot; is not NAME=VALUE</source>
        <translation>--faults: „%1“ ist nicht NAME=WERT</translation>
    </message>
    <message>
        <source>--faults: &quot;%1&quot; is not a number</source>
        <translation>--faults: „%1“ ist keine Zahl</translation>
    </message>
    <message>
        <source>--faults: delay is in milliseconds, 0 to 60000</source>
        <translation>--faults: delay ist in Millisekunden, 0 bis 60000</translation>
    </message>
    <message>
        <source>--faults: %1 is a probability from 0 to 1</source>
        <translation>--faults: %1 ist eine Wahrscheinlichkeit von 0 bis 1</translation>
    </message>
    <message>
        <source>--faults: unknown fault &quot;%1&quot; (drop, corrupt, truncate, noise, delay, lost)</source>
        <translation>--faults: unbekannter Fehler „%1“ (drop, corrupt, truncate, noise, delay, lost)</translation>
    </message>
</context>
<context>
    <name>FeetechBusClient</name>
    <message>
        <source>The bus is not connected.</source>
        <translation>Der Bus ist nicht verbunden.</translation>
    </message>
    <message>
        <source>No servo is selected.</source>
        <translation>Kein Servo ausgewählt.</translation>
    </message>
    <message>
        <source>Another operation is still running.</source>
        <translation>Ein anderer Vorgang läuft noch.</translation>
    </message>
    <message>
        <source>This servo&apos;s model is unknown; its memory is shown read-only.</source>
        <translation>Das Modell dieses Servos ist unbekannt; sein Speicher wird schreibgeschützt angezeigt.</translation>
    </message>
    <message>
        <source>ID %1 is already in use on this bus.</source>
        <translation>ID %1 wird an diesem Bus bereits verwendet.</translation>
    </message>
    <message>
        <source>Nothing to write.</source>
        <translation>Nichts zu schreiben.</translation>
    </message>
    <message>
        <source>This servo has no middle calibration (SCS servos have no offset register).</source>
        <translation>Dieses Servo hat keine Mittelstellungskalibrierung (SCS-Servos haben kein Offset-Register).</translation>
    </message>
    <message>
        <source>Choose at least one servo to monitor.</source>
        <translation>Wählen Sie mindestens ein Servo zum Überwachen.</translation>
    </message>
    <message>
        <source>The rate cannot be negative.</source>
        <translation>Die Rate darf nicht negativ sein.</translation>
    </message>
    <message>
        <source>Servo %1 is of an unknown model: its feedback cannot be decoded.</source>
        <translation>Servo %1 ist von unbekanntem Modell: Seine Rückmeldungen können nicht dekodiert werden.</translation>
    </message>
    <message>
        <source>Nothing to move.</source>
        <translation>Nichts zu bewegen.</translation>
    </message>
    <message>
        <source>Servo %1 is of an unknown model; nothing is written to it.</source>
        <translation>Servo %1 ist von unbekanntem Modell; es wird nichts darauf geschrieben.</translation>
    </message>
    <message>
        <source>Servo %1: %2</source>
        <translation>Servo %1: %2</translation>
    </message>
    <message>
        <source>This servo has no status register: there is nothing to recover.</source>
        <translation>Dieses Servo hat kein Statusregister: Es gibt nichts wiederherzustellen.</translation>
    </message>
    <message>
        <source>No servo to check: scan the bus first.</source>
        <translation>Kein Servo zu prüfen: Scannen Sie zuerst den Bus.</translation>
    </message>
    <message>
        <source>The move test moves servo %1: it runs only once that is confirmed.</source>
        <translation>Der Bewegungstest bewegt Servo %1: Er läuft erst, wenn das bestätigt ist.</translation>
    </message>
    <message>
        <source>This servo has no goal position register: it cannot be moved.</source>
        <translation>Dieses Servo hat kein Zielpositionsregister: Es kann nicht bewegt werden.</translation>
    </message>
    <message>
        <source>That is not a whole Feetech frame (header, length and checksum).</source>
        <translation>Das ist kein vollständiger Feetech-Frame (Kopf, Länge und Prüfsumme).</translation>
    </message>
    <message>
        <source>%1 bps is not a Feetech baud rate.</source>
        <translation>%1 bps ist keine Feetech-Baudrate.</translation>
    </message>
    <message>
        <source>The recording moves servo %1, which the scan did not find: nothing was moved.</source>
        <translation>Die Aufzeichnung bewegt Servo %1, das der Scan nicht gefunden hat: Nichts wurde bewegt.</translation>
    </message>
    <message>
        <source>The servos to record answer at different baud rates: choose servos at one rate.</source>
        <translation>Die aufzuzeichnenden Servos antworten mit unterschiedlichen Baudraten: Wählen Sie Servos mit derselben Rate.</translation>
    </message>
    <message>
        <source>The bus is shared with another program: this would change the port&apos;s rate under it. Stop sharing first.</source>
        <translation>Der Bus wird mit einem anderen Programm geteilt: Dies würde ihm die Baudrate des Ports unbemerkt ändern. Beenden Sie zuerst die Freigabe.</translation>
    </message>
    <message>
        <source>The bus is shared already.</source>
        <translation>Der Bus wird bereits geteilt.</translation>
    </message>
    <message>
        <source>Name the path the other program opens.</source>
        <translation>Den Pfad angeben, den das andere Programm öffnet.</translation>
    </message>
</context>
<context>
    <name>FeetechGuard</name>
    <message>
        <source>Servo %1 has no torque switch the guard could use.</source>
        <translation>Servo %1 hat keinen Drehmomentschalter, den der Schutz nutzen könnte.</translation>
    </message>
    <message>
        <source>Guard: torque off of servo %1</source>
        <translation>Schutz: Drehmoment von Servo %1 aus</translation>
    </message>
    <message>
        <source>Hold where it stands</source>
        <translation>An der Stelle halten</translation>
    </message>
    <message>
        <source>Torque off</source>
        <translation>Drehmoment aus</translation>
    </message>
    <message>
        <source>Servo ID %1</source>
        <translation>Servo-ID %1</translation>
    </message>
    <message>
        <source>its goal was set to where it stands (%1)</source>
        <translation>sein Ziel wurde auf die aktuelle Stelle gesetzt (%1)</translation>
    </message>
    <message>
        <source>its goal was set to where it stands</source>
        <translation>sein Ziel wurde auf die aktuelle Stelle gesetzt</translation>
    </message>
    <message>
        <source>its torque was switched off</source>
        <translation>sein Drehmoment wurde abgeschaltet</translation>
    </message>
    <message>
        <source>temperature %1 °C, its maximum is %2 °C</source>
        <translation>Temperatur %1 °C, das Maximum ist %2 °C</translation>
    </message>
    <message>
        <source>current %1 mA above the guard&apos;s %2 mA</source>
        <translation>Strom %1 mA über den %2 mA des Schutzes</translation>
    </message>
    <message>
        <source>load %1 % above the guard&apos;s %2 %</source>
        <translation>Last %1 % über den %2 % des Schutzes</translation>
    </message>
    <message>
        <source>%1: its own overload protection tripped (status bit Load is set); its torque is off. Use Recover to switch it off and on again.</source>
        <translation>%1: Sein eigener Überlastschutz hat ausgelöst (Statusbit Load ist gesetzt); sein Drehmoment ist aus. Verwenden Sie „Wiederherstellen“, um es aus- und wieder einzuschalten.</translation>
    </message>
    <message>
        <source>Guard warning: %1 is hot (%2); the guard acts at %3 °C.</source>
        <translation>Schutzwarnung: %1 ist heiß (%2); der Schutz greift bei %3 °C ein.</translation>
    </message>
    <message>
        <source>Guard warning: %1 is straining (%2); the guard acts if it lasts %3 s.</source>
        <translation>Schutzwarnung: %1 ist stark belastet (%2); der Schutz greift ein, wenn das %3 s anhält.</translation>
    </message>
    <message>
        <source>Guard: %1 (%2) could not be stopped: %3. Switch its torque off.</source>
        <translation>Schutz: %1 (%2) konnte nicht gestoppt werden: %3. Schalten Sie sein Drehmoment ab.</translation>
    </message>
    <message>
        <source>Guard: %1 was too hot (%2): %3.</source>
        <translation>Schutz: %1 war zu heiß (%2): %3.</translation>
    </message>
    <message>
        <source>Guard: %1 was overloaded for %2 s (%3): %4.</source>
        <translation>Schutz: %1 war %2 s lang überlastet (%3): %4.</translation>
    </message>
    <message>
        <source>Guard: %1 is held but still loaded (%2): free the horn or switch its torque off before its own protection trips.</source>
        <translation>Schutz: %1 wird gehalten, ist aber weiter belastet (%2): Befreien Sie das Servohorn oder schalten Sie sein Drehmoment ab, bevor sein eigener Schutz auslöst.</translation>
    </message>
    <message>
        <source>%1: the overload protection is no longer tripped.</source>
        <translation>%1: Der Überlastschutz ist nicht mehr ausgelöst.</translation>
    </message>
    <message>
        <source>%1 has no torque, goal or status register to recover with.</source>
        <translation>%1 hat kein Drehmoment-, Ziel- oder Statusregister für eine Wiederherstellung.</translation>
    </message>
    <message>
        <source>Recovery: torque off</source>
        <translation>Wiederherstellung: Drehmoment aus</translation>
    </message>
    <message>
        <source>Recovery: torque on again</source>
        <translation>Wiederherstellung: Drehmoment wieder ein</translation>
    </message>
    <message>
        <source>The status of %1 could not be read.</source>
        <translation>Der Status von %1 konnte nicht gelesen werden.</translation>
    </message>
    <message>
        <source>Recovery: torque off (still tripped)</source>
        <translation>Wiederherstellung: Drehmoment aus (weiterhin ausgelöst)</translation>
    </message>
    <message>
        <source>The overload bit of servo ID %1 stays set after torque off and on: only a power cycle clears it.</source>
        <translation>Das Überlastbit von Servo-ID %1 bleibt nach Drehmoment aus und ein gesetzt: Nur Aus- und Einschalten der Stromversorgung löscht es.</translation>
    </message>
    <message>
        <source>1. Free the horn: remove whatever blocks it or the load it holds.</source>
        <translation>1. Befreien Sie das Servohorn: Entfernen Sie, was es blockiert, oder die Last, die es hält.</translation>
    </message>
    <message>
        <source>2. Switch the servos&apos; power supply off (the USB adapter may stay connected).</source>
        <translation>2. Schalten Sie die Stromversorgung der Servos aus (der USB-Adapter darf verbunden bleiben).</translation>
    </message>
    <message>
        <source>3. Wait five seconds, then switch the power on again.</source>
        <translation>3. Warten Sie fünf Sekunden und schalten Sie die Stromversorgung dann wieder ein.</translation>
    </message>
    <message>
        <source>4. Check again: only the status is read; torque stays off until you switch it on.</source>
        <translation>4. Erneut prüfen: Nur der Status wird gelesen; das Drehmoment bleibt aus, bis Sie es einschalten.</translation>
    </message>
</context>
<context>
    <name>FeetechParameters</name>
    <message>
        <source>Other EEPROM</source>
        <translation>Weiteres EEPROM</translation>
    </message>
    <message>
        <source>Other RAM</source>
        <translation>Weiteres RAM</translation>
    </message>
    <message>
        <source>Identity and link</source>
        <translation>Identität und Verbindung</translation>
    </message>
    <message>
        <source>Travel and mode</source>
        <translation>Weg und Betriebsart</translation>
    </message>
    <message>
        <source>Control loop</source>
        <translation>Regelkreis</translation>
    </message>
    <message>
        <source>Limits and protection</source>
        <translation>Grenzen und Schutz</translation>
    </message>
    <message>
        <source>%1 is not a writable register of %2.</source>
        <translation>%1 ist kein beschreibbares Register von %2.</translation>
    </message>
    <message>
        <source>%1 = %2 is out of range (%3 to %4).</source>
        <translation>%1 = %2 liegt außerhalb des Bereichs (%3 bis %4).</translation>
    </message>
    <message>
        <source>%1 = %2 does not fit the register.</source>
        <translation>%1 = %2 passt nicht in das Register.</translation>
    </message>
    <message>
        <source>baud_rate: %1 bps is not a Feetech baud rate.</source>
        <translation>baud_rate: %1 bps ist keine Feetech-Baudrate.</translation>
    </message>
    <message>
        <source>%1: &quot;%2&quot; is not a whole number.</source>
        <translation>%1: „%2“ ist keine ganze Zahl.</translation>
    </message>
    <message>
        <source>bit %1</source>
        <translation>Bit %1</translation>
    </message>
    <message>
        <source>none</source>
        <translation>keine</translation>
    </message>
    <message>
        <source>%1: &quot;%2&quot; is not a number.</source>
        <translation>%1: „%2“ ist keine Zahl.</translation>
    </message>
    <message>
        <source>%1: %2 is not a whole number of steps of %3: set to %4.</source>
        <translation>%1: %2 ist kein ganzzahliges Vielfaches der Schrittweite %3: auf %4 gesetzt.</translation>
    </message>
</context>
<context>
    <name>FeetechRegister</name>
    <message>
        <source>HLS (HLSCL layer)</source>
        <translation>HLS (HLSCL-Schicht)</translation>
    </message>
    <message>
        <source>Firmware major</source>
        <translation>Firmware-Hauptversion</translation>
    </message>
    <message>
        <source>Firmware minor</source>
        <translation>Firmware-Nebenversion</translation>
    </message>
    <message>
        <source>HLS firmware reports minor 40-59.</source>
        <translation>HLS-Firmware meldet Nebenversion 40-59.</translation>
    </message>
    <message>
        <source>Byte order (END)</source>
        <translation>Bytereihenfolge (END)</translation>
    </message>
    <message>
        <source>Little-endian</source>
        <translation>Little-Endian</translation>
    </message>
    <message>
        <source>Big-endian</source>
        <translation>Big-Endian</translation>
    </message>
    <message>
        <source>Model major</source>
        <translation>Modell-Hauptnummer</translation>
    </message>
    <message>
        <source>Model minor</source>
        <translation>Modell-Nebennummer</translation>
    </message>
    <message>
        <source>ID</source>
        <translation>ID</translation>
    </message>
    <message>
        <source>Baud rate</source>
        <translation>Baudrate</translation>
    </message>
    <message>
        <source>Codes 8-11 (19200/14400/9600/4800) appear only in the WIKI protocol index. LeRobot maps 5-7 to 57600/38400/19200; Feetech sources say 76800/57600/38400.</source>
        <translation>Die Codes 8-11 (19200/14400/9600/4800) stehen nur im WIKI-Protokollindex. LeRobot ordnet 5-7 den Raten 57600/38400/19200 zu; Feetech-Quellen nennen 76800/57600/38400.</translation>
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
        <translation>Zweit-ID</translation>
    </message>
    <message>
        <source>Applies to WRITE, REG WRITE, ACTION, SYNC WRITE; writing the main ID also updates it.</source>
        <translation>Gilt für WRITE, REG WRITE, ACTION, SYNC WRITE; das Schreiben der Haupt-ID ändert sie ebenfalls.</translation>
    </message>
    <message>
        <source>Response level</source>
        <translation>Antwortstufe</translation>
    </message>
    <message>
        <source>READ and PING only</source>
        <translation>Nur READ und PING</translation>
    </message>
    <message>
        <source>All instructions</source>
        <translation>Alle Befehle</translation>
    </message>
    <message>
        <source>Min angle limit</source>
        <translation>Untere Winkelgrenze</translation>
    </message>
    <message>
        <source>Range per WIKI; the STS3215 sheet allows down to -32766. Min = max = 0 selects multi-turn / step mode.</source>
        <translation>Bereich laut WIKI; das STS3215-Datenblatt erlaubt bis -32766. Min = Max = 0 wählt den Multiturn-/Schrittmodus.</translation>
    </message>
    <message>
        <source>step</source>
        <translation>Schritt</translation>
    </message>
    <message>
        <source>Max angle limit</source>
        <translation>Obere Winkelgrenze</translation>
    </message>
    <message>
        <source>WIKI range 1-4095; 0 allowed here because min = max = 0 selects multi-turn / step mode. The STS3215 sheet allows up to 32767.</source>
        <translation>WIKI-Bereich 1-4095; 0 ist hier erlaubt, weil Min = Max = 0 den Multiturn-/Schrittmodus wählt. Das STS3215-Datenblatt erlaubt bis 32767.</translation>
    </message>
    <message>
        <source>Max temperature</source>
        <translation>Max. Temperatur</translation>
    </message>
    <message>
        <source>°C</source>
        <translation>°C</translation>
    </message>
    <message>
        <source>Max input voltage</source>
        <translation>Max. Eingangsspannung</translation>
    </message>
    <message>
        <source>V</source>
        <translation>V</translation>
    </message>
    <message>
        <source>Min input voltage</source>
        <translation>Min. Eingangsspannung</translation>
    </message>
    <message>
        <source>Max torque</source>
        <translation>Max. Drehmoment</translation>
    </message>
    <message>
        <source>Copied to torque limit (48) at power-on.</source>
        <translation>Wird beim Einschalten in die Drehmomentgrenze (48) kopiert.</translation>
    </message>
    <message>
        <source>%</source>
        <translation>%</translation>
    </message>
    <message>
        <source>Phase (special functions)</source>
        <translation>Phase (Sonderfunktionen)</translation>
    </message>
    <message>
        <source>Bit 0 encoder type from firmware 3.44.</source>
        <translation>Bit 0: Encodertyp ab Firmware 3.44.</translation>
    </message>
    <message>
        <source>Encoder type AS5600/MT6701</source>
        <translation>Encodertyp AS5600/MT6701</translation>
    </message>
    <message>
        <source>Current feedback direction</source>
        <translation>Richtung der Stromrückmeldung</translation>
    </message>
    <message>
        <source>Bridge direction</source>
        <translation>Brückenrichtung</translation>
    </message>
    <message>
        <source>Full-angle (multi-turn) feedback</source>
        <translation>Vollwinkel-Rückmeldung (Multiturn)</translation>
    </message>
    <message>
        <source>Bridge configuration</source>
        <translation>Brückenkonfiguration</translation>
    </message>
    <message>
        <source>PWM frequency</source>
        <translation>PWM-Frequenz</translation>
    </message>
    <message>
        <source>Position direction</source>
        <translation>Positionsrichtung</translation>
    </message>
    <message>
        <source>Unload conditions</source>
        <translation>Abschaltbedingungen</translation>
    </message>
    <message>
        <source>Voltage</source>
        <translation>Spannung</translation>
    </message>
    <message>
        <source>Encoder</source>
        <translation>Encoder</translation>
    </message>
    <message>
        <source>Temperature</source>
        <translation>Temperatur</translation>
    </message>
    <message>
        <source>Current</source>
        <translation>Strom</translation>
    </message>
    <message>
        <source>LED alarm conditions</source>
        <translation>LED-Alarmbedingungen</translation>
    </message>
    <message>
        <source>Position P gain</source>
        <translation>P-Verstärkung Position</translation>
    </message>
    <message>
        <source>Copied to RAM 50 at power-on.</source>
        <translation>Wird beim Einschalten nach RAM 50 kopiert.</translation>
    </message>
    <message>
        <source>Position D gain</source>
        <translation>D-Verstärkung Position</translation>
    </message>
    <message>
        <source>Copied to RAM 51 at power-on.</source>
        <translation>Wird beim Einschalten nach RAM 51 kopiert.</translation>
    </message>
    <message>
        <source>Position I gain</source>
        <translation>I-Verstärkung Position</translation>
    </message>
    <message>
        <source>Copied to RAM 52 at power-on.</source>
        <translation>Wird beim Einschalten nach RAM 52 kopiert.</translation>
    </message>
    <message>
        <source>Min startup force</source>
        <translation>Min. Anlaufkraft</translation>
    </message>
    <message>
        <source>Firmware dependent: newer WIKI-STS has 24 as 1 byte and 25 as integral limit (x4, 0 = off).</source>
        <translation>Firmwareabhängig: Neuere WIKI-STS führt 24 als 1 Byte und 25 als Integralgrenze (x4, 0 = aus).</translation>
    </message>
    <message>
        <source>CW dead zone</source>
        <translation>Totzone CW</translation>
    </message>
    <message>
        <source>Range per WIKI; the STS3215 sheet allows 0-32.</source>
        <translation>Bereich laut WIKI; das STS3215-Datenblatt erlaubt 0-32.</translation>
    </message>
    <message>
        <source>CCW dead zone</source>
        <translation>Totzone CCW</translation>
    </message>
    <message>
        <source>Protection current</source>
        <translation>Schutzstrom</translation>
    </message>
    <message>
        <source>Copied to goal current (44) at power-on. Range per WIKI-STS.</source>
        <translation>Wird beim Einschalten in den Zielstrom (44) kopiert. Bereich laut WIKI-STS.</translation>
    </message>
    <message>
        <source>mA</source>
        <translation>mA</translation>
    </message>
    <message>
        <source>Angular resolution</source>
        <translation>Winkelauflösung</translation>
    </message>
    <message>
        <source>Range per WIKI; the STS3215 sheet allows 1-3. Multiplies the step size in multi-turn use.</source>
        <translation>Bereich laut WIKI; das STS3215-Datenblatt erlaubt 1-3. Vervielfacht die Schrittweite im Multiturn-Betrieb.</translation>
    </message>
    <message>
        <source>Position offset</source>
        <translation>Positionsoffset</translation>
    </message>
    <message>
        <source>Sign-magnitude, sign bit 15 on HLS.</source>
        <translation>Vorzeichen und Betrag, Vorzeichenbit 15 bei HLS.</translation>
    </message>
    <message>
        <source>Operating mode</source>
        <translation>Betriebsmodus</translation>
    </message>
    <message>
        <source>Position + current limit</source>
        <translation>Position + Strombegrenzung</translation>
    </message>
    <message>
        <source>Constant speed + current limit</source>
        <translation>Konstante Geschwindigkeit + Strombegrenzung</translation>
    </message>
    <message>
        <source>Constant current (torque)</source>
        <translation>Konstanter Strom (Drehmoment)</translation>
    </message>
    <message>
        <source>PWM open loop</source>
        <translation>PWM, ungeregelt</translation>
    </message>
    <message>
        <source>Current loop P gain</source>
        <translation>P-Verstärkung Stromregler</translation>
    </message>
    <message>
        <source>Current loop I gain</source>
        <translation>I-Verstärkung Stromregler</translation>
    </message>
    <message>
        <source>Speed P gain</source>
        <translation>P-Verstärkung Geschwindigkeit</translation>
    </message>
    <message>
        <source>Over-current protection time</source>
        <translation>Überstrom-Schutzzeit</translation>
    </message>
    <message>
        <source>ms</source>
        <translation>ms</translation>
    </message>
    <message>
        <source>Speed I gain</source>
        <translation>I-Verstärkung Geschwindigkeit</translation>
    </message>
    <message>
        <source>Torque enable</source>
        <translation>Drehmoment-Freigabe</translation>
    </message>
    <message>
        <source>128-calibration not supported per WIKI-PROTO (LINUX-FORK writes 128 anyway); prefer instruction 0x0B.</source>
        <translation>128-Kalibrierung laut WIKI-PROTO nicht unterstützt (LINUX-FORK schreibt trotzdem 128); besser Befehl 0x0B verwenden.</translation>
    </message>
    <message>
        <source>Off</source>
        <translation>Aus</translation>
    </message>
    <message>
        <source>On</source>
        <translation>Ein</translation>
    </message>
    <message>
        <source>Damping</source>
        <translation>Dämpfung</translation>
    </message>
    <message>
        <source>Acceleration</source>
        <translation>Beschleunigung</translation>
    </message>
    <message>
        <source>0 = maximum acceleration.</source>
        <translation>0 = maximale Beschleunigung.</translation>
    </message>
    <message>
        <source>step/s²</source>
        <translation>Schritt/s²</translation>
    </message>
    <message>
        <source>Goal position</source>
        <translation>Zielposition</translation>
    </message>
    <message>
        <source>Goal current</source>
        <translation>Zielstrom</translation>
    </message>
    <message>
        <source>SDK name GOAL_TORQUE. Loaded from protection current (28) at power-on. In PWM mode (3): duty +/-1000 with direction bit 10.</source>
        <translation>SDK-Name GOAL_TORQUE. Wird beim Einschalten aus dem Schutzstrom (28) geladen. Im PWM-Modus (3): Tastverhältnis +/-1000 mit Richtungsbit 10.</translation>
    </message>
    <message>
        <source>Goal speed</source>
        <translation>Zielgeschwindigkeit</translation>
    </message>
    <message>
        <source>Unit 0.732 rpm per WIKI-HLS; range undocumented. 0 = stop.</source>
        <translation>Einheit 0.732 U/min laut WIKI-HLS; Bereich undokumentiert. 0 = Stopp.</translation>
    </message>
    <message>
        <source>rpm</source>
        <translation>U/min</translation>
    </message>
    <message>
        <source>Torque limit</source>
        <translation>Drehmomentgrenze</translation>
    </message>
    <message>
        <source>Loaded from max torque (16) at power-on.</source>
        <translation>Wird beim Einschalten aus dem max. Drehmoment (16) geladen.</translation>
    </message>
    <message>
        <source>Live position P gain</source>
        <translation>P-Verstärkung Position (aktiv)</translation>
    </message>
    <message>
        <source>Loaded from 21 at power-on.</source>
        <translation>Wird beim Einschalten aus 21 geladen.</translation>
    </message>
    <message>
        <source>Live position D gain</source>
        <translation>D-Verstärkung Position (aktiv)</translation>
    </message>
    <message>
        <source>Loaded from 22 at power-on.</source>
        <translation>Wird beim Einschalten aus 22 geladen.</translation>
    </message>
    <message>
        <source>Live position I gain</source>
        <translation>I-Verstärkung Position (aktiv)</translation>
    </message>
    <message>
        <source>Loaded at power-on from 23 (per the EEPROM row) or 39 (per the RAM row); sources disagree.</source>
        <translation>Wird beim Einschalten aus 23 (laut EEPROM-Zeile) oder 39 (laut RAM-Zeile) geladen; die Quellen widersprechen sich.</translation>
    </message>
    <message>
        <source>EEPROM lock</source>
        <translation>EEPROM-Sperre</translation>
    </message>
    <message>
        <source>Power-on value 1 per WIKI/FDQT, 0 per the STS3215 sheet: write 0 before EEPROM writes and 1 afterwards.</source>
        <translation>Einschaltwert 1 laut WIKI/FDQT, 0 laut STS3215-Datenblatt: vor EEPROM-Schreibzugriffen 0 schreiben, danach 1.</translation>
    </message>
    <message>
        <source>Unlocked</source>
        <translation>Entsperrt</translation>
    </message>
    <message>
        <source>Locked</source>
        <translation>Gesperrt</translation>
    </message>
    <message>
        <source>Present position</source>
        <translation>Aktuelle Position</translation>
    </message>
    <message>
        <source>In step mode (3): remaining steps.</source>
        <translation>Im Schrittmodus (3): verbleibende Schritte.</translation>
    </message>
    <message>
        <source>Present speed</source>
        <translation>Aktuelle Geschwindigkeit</translation>
    </message>
    <message>
        <source>step/s</source>
        <translation>Schritt/s</translation>
    </message>
    <message>
        <source>Present load</source>
        <translation>Aktuelle Last</translation>
    </message>
    <message>
        <source>Present voltage</source>
        <translation>Aktuelle Spannung</translation>
    </message>
    <message>
        <source>Present temperature</source>
        <translation>Aktuelle Temperatur</translation>
    </message>
    <message>
        <source>Async write flag</source>
        <translation>Flag für asynchrones Schreiben</translation>
    </message>
    <message>
        <source>Servo status</source>
        <translation>Servostatus</translation>
    </message>
    <message>
        <source>Moving</source>
        <translation>In Bewegung</translation>
    </message>
    <message>
        <source>Above speed threshold</source>
        <translation>Über der Geschwindigkeitsschwelle</translation>
    </message>
    <message>
        <source>Target not reached</source>
        <translation>Ziel nicht erreicht</translation>
    </message>
    <message>
        <source>Current goal position</source>
        <translation>Aktuelle Zielposition</translation>
    </message>
    <message>
        <source>WIKI; LeRobot instead names 71-72 &quot;Goal_Position_2&quot;. Sign encoding undocumented.</source>
        <translation>WIKI; LeRobot nennt 71-72 stattdessen &quot;Goal_Position_2&quot;. Vorzeichenkodierung undokumentiert.</translation>
    </message>
    <message>
        <source>Present current</source>
        <translation>Aktueller Strom</translation>
    </message>
    <message>
        <source>Current zero offset</source>
        <translation>Strom-Nullpunktoffset</translation>
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
        <translation>Geschwindigkeitsschwelle für Bewegung</translation>
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
        <translation>Geschwindigkeitsobergrenze</translation>
    </message>
    <message>
        <source>Max acceleration</source>
        <translation>Max. Beschleunigung</translation>
    </message>
    <message>
        <source>Acceleration multiplier</source>
        <translation>Beschleunigungsfaktor</translation>
    </message>
    <message>
        <source>SCS (SCSCL layer)</source>
        <translation>SCS (SCSCL-Schicht)</translation>
    </message>
    <message>
        <source>May be absent on old SCS firmware.</source>
        <translation>Fehlt möglicherweise bei alter SCS-Firmware.</translation>
    </message>
    <message>
        <source>Factory 1 Mbps or 500 kbps depending on model. Codes 8-11 (19200/14400/9600/4800) appear only in the WIKI protocol index. LeRobot maps 5-7 to 57600/38400/19200; Feetech sources say 76800/57600/38400.</source>
        <translation>Ab Werk 1 Mbps oder 500 kbps, je nach Modell. Die Codes 8-11 (19200/14400/9600/4800) stehen nur im WIKI-Protokollindex. LeRobot ordnet 5-7 den Raten 57600/38400/19200 zu; Feetech-Quellen nennen 76800/57600/38400.</translation>
    </message>
    <message>
        <source>Return delay</source>
        <translation>Antwortverzögerung</translation>
    </message>
    <message>
        <source>May be unsupported: WIKI-SCS lists this address as undefined; LeRobot and FDQT (default 250) use it as return delay.</source>
        <translation>Möglicherweise nicht unterstützt: WIKI-SCS führt diese Adresse als undefiniert; LeRobot und FDQT (Standard 250) verwenden sie als Antwortverzögerung.</translation>
    </message>
    <message>
        <source>µs</source>
        <translation>µs</translation>
    </message>
    <message>
        <source>Min = max = 0 selects motor (PWM) mode.</source>
        <translation>Min = Max = 0 wählt den Motormodus (PWM).</translation>
    </message>
    <message>
        <source>Documented range 1-1023; 0 allowed here because min = max = 0 selects motor (PWM) mode.</source>
        <translation>Dokumentierter Bereich 1-1023; 0 ist hier erlaubt, weil Min = Max = 0 den Motormodus (PWM) wählt.</translation>
    </message>
    <message>
        <source>Max = min = 0 disables the voltage check.</source>
        <translation>Max = Min = 0 schaltet die Spannungsprüfung ab.</translation>
    </message>
    <message>
        <source>Copied to the torque limit at power-on.</source>
        <translation>Wird beim Einschalten in die Drehmomentgrenze kopiert.</translation>
    </message>
    <message>
        <source>Direction</source>
        <translation>Richtung</translation>
    </message>
    <message>
        <source>Speed 0 = stop/max</source>
        <translation>Geschwindigkeit 0 = Stopp/Max.</translation>
    </message>
    <message>
        <source>PWM phase</source>
        <translation>PWM-Phase</translation>
    </message>
    <message>
        <source>Voltage sampling</source>
        <translation>Spannungsmessung</translation>
    </message>
    <message>
        <source>Load</source>
        <translation>Last</translation>
    </message>
    <message>
        <source>May be unsupported: WIKI-SCS lists this address as undefined; LeRobot names it I coefficient.</source>
        <translation>Möglicherweise nicht unterstützt: WIKI-SCS führt diese Adresse als undefiniert; LeRobot nennt sie I-Koeffizient.</translation>
    </message>
    <message>
        <source>FDQT default 2.</source>
        <translation>FDQT-Standard 2.</translation>
    </message>
    <message>
        <source>Holding torque</source>
        <translation>Haltemoment</translation>
    </message>
    <message>
        <source>Protection time</source>
        <translation>Schutzzeit</translation>
    </message>
    <message>
        <source>Overload torque</source>
        <translation>Überlastmoment</translation>
    </message>
    <message>
        <source>No 128 calibration on SCS.</source>
        <translation>Keine 128-Kalibrierung bei SCS.</translation>
    </message>
    <message>
        <source>Off (free)</source>
        <translation>Aus (frei)</translation>
    </message>
    <message>
        <source>May be unsupported: WIKI-SCS lists this address as undefined; LeRobot and LINUX-FORK name it Acceleration.</source>
        <translation>Möglicherweise nicht unterstützt: WIKI-SCS führt diese Adresse als undefiniert; LeRobot und LINUX-FORK nennen sie Acceleration (Beschleunigung).</translation>
    </message>
    <message>
        <source>Goal time / PWM</source>
        <translation>Zielzeit / PWM</translation>
    </message>
    <message>
        <source>Time is used when goal speed = 0. In motor mode (min = max angle = 0) this is PWM duty, 0.1 % units, +/-1000 with direction bit 10.</source>
        <translation>Die Zeit gilt, wenn die Zielgeschwindigkeit = 0 ist. Im Motormodus (Min = Max Winkel = 0) ist dies das PWM-Tastverhältnis in Einheiten von 0.1 %, +/-1000 mit Richtungsbit 10.</translation>
    </message>
    <message>
        <source>Factory value = the model&apos;s max speed.</source>
        <translation>Werkswert = Maximalgeschwindigkeit des Modells.</translation>
    </message>
    <message>
        <source>Unsigned on SCS (no sign decoding in the SDKs).</source>
        <translation>Vorzeichenlos bei SCS (keine Vorzeichendekodierung in den SDKs).</translation>
    </message>
    <message>
        <source>Read by the C++ SDK feedback block (56-70); absent from WIKI-SCS and FDQT tables. Units undocumented.</source>
        <translation>Wird vom Rückmeldeblock des C++-SDK (56-70) gelesen; fehlt in den Tabellen von WIKI-SCS und FDQT. Einheiten undokumentiert.</translation>
    </message>
    <message>
        <source>PWM mode max step</source>
        <translation>Max. Schritt im PWM-Modus</translation>
    </message>
    <message>
        <source>Factory area at LeRobot&apos;s decimal addresses 78-83; the WIKI hex column is off by one.</source>
        <translation>Werksbereich an LeRobots dezimalen Adressen 78-83; die Hex-Spalte des WIKI ist um eins verschoben.</translation>
    </message>
    <message>
        <source>Min speed limit</source>
        <translation>Geschwindigkeitsuntergrenze</translation>
    </message>
    <message>
        <source>Factory acceleration</source>
        <translation>Werksbeschleunigung</translation>
    </message>
    <message>
        <source>SMS (SMS_STS layer, RS485)</source>
        <translation>SMS (SMS_STS-Schicht, RS485)</translation>
    </message>
    <message>
        <source>Valid values 0 or 50-253 (WIKI-SMS); values below 50 act as 50 (100 µs). Factory value 0 per WIKI-SMS, 250 per LeRobot/FDQT: read it, don&apos;t assume.</source>
        <translation>Gültige Werte 0 oder 50-253 (WIKI-SMS); Werte unter 50 wirken wie 50 (100 µs). Werkswert 0 laut WIKI-SMS, 250 laut LeRobot/FDQT: auslesen, nicht voraussetzen.</translation>
    </message>
    <message>
        <source>Driver direction</source>
        <translation>Treiberrichtung</translation>
    </message>
    <message>
        <source>Bridge brushed/none</source>
        <translation>Brücke bürstenbehaftet/keine</translation>
    </message>
    <message>
        <source>Speed unit 0.732/0.0146 rpm</source>
        <translation>Geschwindigkeitseinheit 0.732/0.0146 U/min</translation>
    </message>
    <message>
        <source>Voltage sampling 1.5k/1k</source>
        <translation>Spannungsmessung 1.5k/1k</translation>
    </message>
    <message>
        <source>PWM 24/16 kHz</source>
        <translation>PWM 24/16 kHz</translation>
    </message>
    <message>
        <source>Position feedback direction</source>
        <translation>Richtung der Positionsrückmeldung</translation>
    </message>
    <message>
        <source>Range per WIKI (STS3215 sheet: 0-511).</source>
        <translation>Bereich laut WIKI (STS3215-Datenblatt: 0-511).</translation>
    </message>
    <message>
        <source>LeRobot: present = actual - offset. WIKI describes a 0-8191 encoding.</source>
        <translation>LeRobot: aktuell = tatsächlich - Offset. Das WIKI beschreibt eine 0-8191-Kodierung.</translation>
    </message>
    <message>
        <source>WIKI-SMS table range 0-2; its text still lists 3 = step mode.</source>
        <translation>Tabelle in WIKI-SMS: Bereich 0-2; ihr Text nennt noch 3 = Schrittmodus.</translation>
    </message>
    <message>
        <source>Position</source>
        <translation>Position</translation>
    </message>
    <message>
        <source>Constant speed (wheel)</source>
        <translation>Konstante Geschwindigkeit (Rad)</translation>
    </message>
    <message>
        <source>Torque after an overload trip.</source>
        <translation>Drehmoment nach einer Überlastabschaltung.</translation>
    </message>
    <message>
        <source>No damping value on SMS. Calibration by 128 for SMS fw &lt;= 2.54; instruction 0x0B unsupported.</source>
        <translation>Kein Dämpfungswert bei SMS. Kalibrierung per 128 bei SMS-Firmware &lt;= 2.54; Befehl 0x0B nicht unterstützt.</translation>
    </message>
    <message>
        <source>Calibrate middle (2048)</source>
        <translation>Mittelstellung kalibrieren (2048)</translation>
    </message>
    <message>
        <source>In step mode (3): relative steps.</source>
        <translation>Im Schrittmodus (3): relative Schritte.</translation>
    </message>
    <message>
        <source>In PWM mode (2): duty +/-1000 with direction bit 10. SMS_STS position writes put 0 here.</source>
        <translation>Im PWM-Modus (2): Tastverhältnis +/-1000 mit Richtungsbit 10. Positionsbefehle von SMS_STS schreiben hier 0.</translation>
    </message>
    <message>
        <source>50 step/s = 0.732 rpm. 0 = maximum speed unless Phase bit 3. Sign used in wheel mode.</source>
        <translation>50 Schritte/s = 0.732 U/min. 0 = Maximalgeschwindigkeit, außer bei Phase-Bit 3. Das Vorzeichen gilt im Radmodus.</translation>
    </message>
    <message>
        <source>Documented maximum 500 (3250 mA).</source>
        <translation>Dokumentiertes Maximum 500 (3250 mA).</translation>
    </message>
    <message>
        <source>Speed unit factor</source>
        <translation>Faktor der Geschwindigkeitseinheit</translation>
    </message>
    <message>
        <source>Hts</source>
        <translation>Hts</translation>
    </message>
    <message>
        <source>Valid for SMS firmware &gt;= 2.54.</source>
        <translation>Gültig für SMS-Firmware &gt;= 2.54.</translation>
    </message>
    <message>
        <source>ns</source>
        <translation>ns</translation>
    </message>
    <message>
        <source>Read-only per WIKI; LeRobot nevertheless writes 254 here on STS.</source>
        <translation>Laut WIKI schreibgeschützt; LeRobot schreibt hier bei STS trotzdem 254.</translation>
    </message>
    <message>
        <source>Used when acceleration = 0.</source>
        <translation>Wird verwendet, wenn Beschleunigung = 0.</translation>
    </message>
    <message>
        <source>STS (SMS_STS layer)</source>
        <translation>STS (SMS_STS-Schicht)</translation>
    </message>
    <message>
        <source>WIKI-STS marks address 7 &quot;Reserved&quot;; ST3215, LeRobot and FDQT use it as return delay. Factory value 0 (ST3215 sheet) or 250 = 500 µs (LeRobot, FDQT): read it, don&apos;t assume.</source>
        <translation>WIKI-STS kennzeichnet Adresse 7 als &quot;Reserved&quot;; ST3215, LeRobot und FDQT verwenden sie als Antwortverzögerung. Werkswert 0 (ST3215-Datenblatt) oder 250 = 500 µs (LeRobot, FDQT): auslesen, nicht voraussetzen.</translation>
    </message>
    <message>
        <source>80 = 8.0 V on the 7.4 V STS3215; FDQT default 140.</source>
        <translation>80 = 8.0 V beim 7.4-V-STS3215; FDQT-Standard 140.</translation>
    </message>
    <message>
        <source>LeRobot clears bit 4 on STS3215.</source>
        <translation>LeRobot löscht Bit 4 beim STS3215.</translation>
    </message>
    <message>
        <source>Bridge brushless/brushed</source>
        <translation>Brücke bürstenlos/bürstenbehaftet</translation>
    </message>
    <message>
        <source>FDQT default 37.</source>
        <translation>FDQT-Standard 37.</translation>
    </message>
    <message>
        <source>Default 500 and range 0-511 per STS3215 sheet; WIKI: default 511, range 0-2047.</source>
        <translation>Standard 500 und Bereich 0-511 laut STS3215-Datenblatt; WIKI: Standard 511, Bereich 0-2047.</translation>
    </message>
    <message>
        <source>Step</source>
        <translation>Schritt</translation>
    </message>
    <message>
        <source>In PWM mode (2): duty +/-1000 with direction bit 10. Default 0 per STS3215 sheet, 1000 per WIKI. SMS_STS position writes put 0 here.</source>
        <translation>Im PWM-Modus (2): Tastverhältnis +/-1000 mit Richtungsbit 10. Standard 0 laut STS3215-Datenblatt, 1000 laut WIKI. Positionsbefehle von SMS_STS schreiben hier 0.</translation>
    </message>
    <message>
        <source>WIKI-STS; LeRobot names 83 &quot;Hts&quot;.</source>
        <translation>WIKI-STS; LeRobot nennt 83 &quot;Hts&quot;.</translation>
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
        <translation>Rate</translation>
    </message>
    <message>
        <source>Model</source>
        <translation>Modell</translation>
    </message>
    <message>
        <source>Family</source>
        <translation>Familie</translation>
    </message>
    <message>
        <source>Firmware</source>
        <translation>Firmware</translation>
    </message>
</context>
<context>
    <name>FeetechSession</name>
    <message numerus="yes">
        <source>no reply after %n attempt(s)</source>
        <translation>
            <numerusform>keine Antwort nach %n Versuch</numerusform>
            <numerusform>keine Antwort nach %n Versuchen</numerusform>
        </translation>
    </message>
    <message>
        <source>the port is closed</source>
        <translation>der Anschluss ist geschlossen</translation>
    </message>
    <message>
        <source>cancelled</source>
        <translation>abgebrochen</translation>
    </message>
    <message>
        <source>%1 is back. Scan again if servos were changed while it was away.</source>
        <translation>%1 ist wieder da. Scannen Sie erneut, falls Servos geändert wurden, während es weg war.</translation>
    </message>
    <message>
        <source>Not connected.</source>
        <translation>Nicht verbunden.</translation>
    </message>
    <message>
        <source>The port cannot be set to %1.</source>
        <translation>Der Anschluss kann nicht auf %1 eingestellt werden.</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>The servo&apos;s model has no known EEPROM lock register.</source>
        <translation>Für das Modell des Servos ist kein EEPROM-Sperrregister bekannt.</translation>
    </message>
    <message>
        <source>Locking the EEPROM</source>
        <translation>EEPROM wird gesperrt</translation>
    </message>
    <message>
        <source>Unlocking the EEPROM</source>
        <translation>EEPROM wird entsperrt</translation>
    </message>
    <message>
        <source>Reading %1 bytes at address %2: %3</source>
        <translation>Lesen von %1 Bytes an Adresse %2: %3</translation>
    </message>
    <message>
        <source>Reading the identity of servo %1: %2</source>
        <translation>Lesen der Identität von Servo %1: %2</translation>
    </message>
    <message>
        <source>Servo %1 does not answer.</source>
        <translation>Servo %1 antwortet nicht.</translation>
    </message>
    <message>
        <source>ID %1 is already in use on this bus.</source>
        <translation>ID %1 wird an diesem Bus bereits verwendet.</translation>
    </message>
    <message>
        <source>servo %1 at %2</source>
        <translation>Servo %1 bei %2</translation>
    </message>
    <message numerus="yes">
        <source>Scan cancelled; %n servo(s) found before.</source>
        <translation>
            <numerusform>Scan abgebrochen; zuvor %n Servo gefunden.</numerusform>
            <numerusform>Scan abgebrochen; zuvor %n Servos gefunden.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Scan complete: %n servo(s) found.</source>
        <translation>
            <numerusform>Scan abgeschlossen: %n Servo gefunden.</numerusform>
            <numerusform>Scan abgeschlossen: %n Servos gefunden.</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 is not a Feetech baud rate.</source>
        <translation>%1 ist keine Feetech-Baudrate.</translation>
    </message>
    <message>
        <source>unknown (identity unreadable)</source>
        <translation>unbekannt (Identität nicht lesbar)</translation>
    </message>
    <message>
        <source>Servo %1 answers.</source>
        <translation>Servo %1 antwortet.</translation>
    </message>
    <message>
        <source>Servo %1 does not answer: %2</source>
        <translation>Servo %1 antwortet nicht: %2</translation>
    </message>
    <message>
        <source>Read %1.</source>
        <translation>%1 gelesen.</translation>
    </message>
    <message>
        <source>Servo %1 is of an unknown model; its memory is shown read-only and nothing is written to it.</source>
        <translation>Servo %1 ist von unbekanntem Modell; sein Speicher wird schreibgeschützt angezeigt, und es wird nichts darauf geschrieben.</translation>
    </message>
    <message>
        <source>The ID and the baud rate change how the servo is reached; use Change ID or Change baud rate.</source>
        <translation>ID und Baudrate ändern, wie das Servo erreicht wird; verwenden Sie „ID ändern“ oder „Baudrate ändern“.</translation>
    </message>
    <message>
        <source>The EEPROM lock is opened and closed by ServoBench around each EEPROM write; it is not written by hand.</source>
        <translation>Die EEPROM-Sperre wird von ServoBench um jeden EEPROM-Schreibvorgang herum geöffnet und geschlossen; sie wird nicht von Hand geschrieben.</translation>
    </message>
    <message>
        <source>Torque enable 128 recalibrates the middle; use Calibrate middle.</source>
        <translation>Torque enable 128 kalibriert die Mitte neu; verwenden Sie „Mittelstellung kalibrieren“.</translation>
    </message>
    <message>
        <source>Writing address %1</source>
        <translation>Schreiben an Adresse %1</translation>
    </message>
    <message>
        <source>Written and read back.</source>
        <translation>Geschrieben und zurückgelesen.</translation>
    </message>
    <message>
        <source>Servo %1 is of an unknown model; its ID is not changed.</source>
        <translation>Servo %1 ist von unbekanntem Modell; seine ID wird nicht geändert.</translation>
    </message>
    <message>
        <source>ID %1 is out of range (0 to %2).</source>
        <translation>ID %1 liegt außerhalb des Bereichs (0 bis %2).</translation>
    </message>
    <message>
        <source>The servo already has ID %1.</source>
        <translation>Das Servo hat bereits ID %1.</translation>
    </message>
    <message>
        <source>ID %1 is already in use on this bus; nothing was written.</source>
        <translation>ID %1 wird an diesem Bus bereits verwendet; es wurde nichts geschrieben.</translation>
    </message>
    <message>
        <source>Servo %1 now answers as ID %2.</source>
        <translation>Servo %1 antwortet jetzt als ID %2.</translation>
    </message>
    <message>
        <source>The servo still has its old ID.</source>
        <translation>Das Servo hat noch seine alte ID.</translation>
    </message>
    <message>
        <source>Servo %1 is of an unknown model; its baud rate is not changed.</source>
        <translation>Servo %1 ist von unbekanntem Modell; seine Baudrate wird nicht geändert.</translation>
    </message>
    <message>
        <source>%1 is not a baud rate this servo supports.</source>
        <translation>%1 ist keine Baudrate, die dieses Servo unterstützt.</translation>
    </message>
    <message>
        <source>The servo already runs at %1.</source>
        <translation>Das Servo läuft bereits mit %1.</translation>
    </message>
    <message>
        <source>The servo reports baud code %1 instead of %2.</source>
        <translation>Das Servo meldet Baudcode %1 statt %2.</translation>
    </message>
    <message>
        <source>Servo %1 now runs at %2 and answers there.</source>
        <translation>Servo %1 läuft jetzt mit %2 und antwortet dort.</translation>
    </message>
    <message>
        <source>It still answers at %1.</source>
        <translation>Es antwortet noch bei %1.</translation>
    </message>
    <message>
        <source>It answers at neither rate; scan all baud rates to find it.</source>
        <translation>Es antwortet bei keiner der beiden Baudraten; scannen Sie alle Baudraten, um es zu finden.</translation>
    </message>
    <message>
        <source>Middle calibration is not available on this servo (SCS servos have no offset register).</source>
        <translation>Mittelstellung kalibrieren ist bei diesem Servo nicht verfügbar (SCS-Servos haben kein Offset-Register).</translation>
    </message>
    <message>
        <source>Middle calibration</source>
        <translation>Mittelstellung kalibrieren</translation>
    </message>
    <message>
        <source>The present position is now the middle.</source>
        <translation>Die aktuelle Position ist jetzt die Mitte.</translation>
    </message>
    <message>
        <source>Servo %1 is of an unknown model; it is not reset.</source>
        <translation>Servo %1 ist von unbekanntem Modell; es wird nicht zurückgesetzt.</translation>
    </message>
    <message>
        <source>Factory reset</source>
        <translation>Werksreset</translation>
    </message>
    <message>
        <source>Factory values restored; servo %1 answers at %2.</source>
        <translation>Werkswerte wiederhergestellt; Servo %1 antwortet bei %2.</translation>
    </message>
    <message>
        <source>Servo %1 answers at no baud rate; scan the bus to find it.</source>
        <translation>Servo %1 antwortet bei keiner Baudrate; scannen Sie den Bus, um es zu finden.</translation>
    </message>
    <message>
        <source>Torque off</source>
        <translation>Drehmoment aus</translation>
    </message>
    <message>
        <source>Reboot</source>
        <translation>Neustart</translation>
    </message>
    <message>
        <source>Servo %1 restarted and answers again after %2 ms.</source>
        <translation>Servo %1 wurde neu gestartet und antwortet nach %2 ms wieder.</translation>
    </message>
    <message>
        <source>Servo %1 has not answered within %2 ms of the restart.</source>
        <translation>Servo %1 hat nicht innerhalb von %2 ms nach dem Neustart geantwortet.</translation>
    </message>
    <message>
        <source>Clearing the status</source>
        <translation>Status wird gelöscht</translation>
    </message>
    <message>
        <source>Status of servo %1 cleared.</source>
        <translation>Status von Servo %1 gelöscht.</translation>
    </message>
    <message>
        <source>%1 answers again; it is back in the cycle.</source>
        <translation>%1 antwortet wieder; es ist zurück im Zyklus.</translation>
    </message>
    <message>
        <source>%1 stopped answering; it is left out of the cycle and asked alone every %2 ms until it answers.</source>
        <translation>%1 antwortet nicht mehr; es wird aus dem Zyklus genommen und alle %2 ms einzeln abgefragt, bis es antwortet.</translation>
    </message>
    <message>
        <source>Torque off at %1</source>
        <translation>Drehmoment aus bei %1</translation>
    </message>
    <message>
        <source>%1 did not confirm (no reply).</source>
        <translation>%1 hat nicht bestätigt (keine Antwort).</translation>
    </message>
    <message>
        <source>%1 still has torque on.</source>
        <translation>%1 hat noch Drehmoment eingeschaltet.</translation>
    </message>
    <message numerus="yes">
        <source>Torque off: sent to the whole bus; %n servo(s) confirmed it.</source>
        <translation>
            <numerusform>Drehmoment aus: an den ganzen Bus gesendet; %n Servo hat es bestätigt.</numerusform>
            <numerusform>Drehmoment aus: an den ganzen Bus gesendet; %n Servos haben es bestätigt.</numerusform>
        </translation>
    </message>
    <message>
        <source>Torque off was sent to the whole bus, but: %1</source>
        <translation>„Drehmoment aus“ wurde an den ganzen Bus gesendet, aber: %1</translation>
    </message>
    <message>
        <source>The SYNC WRITE does not fit in one packet.</source>
        <translation>Das SYNC WRITE passt nicht in ein Paket.</translation>
    </message>
    <message>
        <source>SYNC WRITE at %1</source>
        <translation>SYNC WRITE bei %1</translation>
    </message>
    <message numerus="yes">
        <source>Sent to %n servo(s) in one SYNC WRITE.</source>
        <translation>
            <numerusform>An %n Servo in einem SYNC WRITE gesendet.</numerusform>
            <numerusform>An %n Servos in einem SYNC WRITE gesendet.</numerusform>
        </translation>
    </message>
    <message>
        <source>The EEPROM lock could not be closed again: the servo&apos;s EEPROM may be left open. Read the servo again and lock it when it answers.</source>
        <translation>Die EEPROM-Sperre konnte nicht wieder geschlossen werden: Das EEPROM des Servos ist möglicherweise offen geblieben. Lesen Sie das Servo erneut und sperren Sie es, sobald es antwortet.</translation>
    </message>
    <message>
        <source>Nothing to write.</source>
        <translation>Nichts zu schreiben.</translation>
    </message>
    <message>
        <source>Writing %1</source>
        <translation>Schreiben von %1</translation>
    </message>
    <message>
        <source>Not sent: all torque off was asked for after this write.</source>
        <translation>Nicht gesendet: „Alle Drehmomente aus“ wurde nach diesem Schreibvorgang angefordert.</translation>
    </message>
    <message>
        <source>%1 is of an unknown model; its torque was not read back.</source>
        <translation>%1 ist von unbekanntem Modell; sein Drehmoment wurde nicht zurückgelesen.</translation>
    </message>
    <message>
        <source>Servo ID %1: the overload bit is clear; switch its torque on when you are ready.</source>
        <translation>Servo-ID %1: Das Überlastbit ist gelöscht; schalten Sie sein Drehmoment ein, wenn Sie bereit sind.</translation>
    </message>
    <message>
        <source>Servo ID %1 recovered: the overload bit is clear and it holds where it stands with torque on.</source>
        <translation>Servo-ID %1 wiederhergestellt: Das Überlastbit ist gelöscht, und es hält mit eingeschaltetem Drehmoment an der aktuellen Stelle.</translation>
    </message>
    <message numerus="yes">
        <source>The health check was stopped after %1 of %n servo(s).</source>
        <translation>
            <numerusform>Die Zustandsprüfung wurde nach %1 von %n Servo gestoppt.</numerusform>
            <numerusform>Die Zustandsprüfung wurde nach %1 von %n Servos gestoppt.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n servo(s) checked.</source>
        <translation>
            <numerusform>%n Servo geprüft.</numerusform>
            <numerusform>%n Servos geprüft.</numerusform>
        </translation>
    </message>
    <message>
        <source>Servo %1&apos;s EEPROM is locked (read back).</source>
        <translation>Das EEPROM von Servo %1 ist gesperrt (zurückgelesen).</translation>
    </message>
    <message>
        <source>Servo %1 still reads back unlocked after the lock was written.</source>
        <translation>Servo %1 liest sich nach dem Schreiben der Sperre noch immer als entsperrt zurück.</translation>
    </message>
    <message numerus="yes">
        <source>%1 of %n joint(s) already set up.</source>
        <translation>
            <numerusform>%1 von %n Gelenk bereits eingerichtet.</numerusform>
            <numerusform>%1 von %n Gelenken bereits eingerichtet.</numerusform>
        </translation>
    </message>
    <message>
        <source>The link closed.</source>
        <translation>Die Verbindung wurde geschlossen.</translation>
    </message>
    <message>
        <source>%1 is of a model ServoBench does not move (%2): no move test.</source>
        <translation>%1 ist von einem Modell, das ServoBench nicht bewegt (%2): kein Bewegungstest.</translation>
    </message>
    <message>
        <source>%1 does not answer: %2</source>
        <translation>%1 antwortet nicht: %2</translation>
    </message>
    <message>
        <source>%1 is not in position mode (mode %2): it is not moved.</source>
        <translation>%1 ist nicht im Positionsmodus (Modus %2): Es wird nicht bewegt.</translation>
    </message>
    <message>
        <source>%1 holds torque enable %2, neither on nor off: it is not moved.</source>
        <translation>%1 hat torque enable %2, weder ein noch aus: Es wird nicht bewegt.</translation>
    </message>
    <message>
        <source>%1 stands at %2: its angle limits leave no room for a move of %3 steps.</source>
        <translation>%1 steht bei %2: Seine Winkelgrenzen lassen keinen Platz für eine Bewegung um %3 Schritte.</translation>
    </message>
    <message>
        <source>%1 stopped answering: %2</source>
        <translation>%1 antwortet nicht mehr: %2</translation>
    </message>
    <message>
        <source>The overload guard stopped the move test of %1; its goal stays where the guard held it.</source>
        <translation>Der Überlastschutz hat den Bewegungstest von %1 gestoppt; sein Ziel bleibt dort, wo der Schutz es gehalten hat.</translation>
    </message>
    <message>
        <source>All torque off: the move test of %1 was stopped.</source>
        <translation>Alle Drehmomente aus: Der Bewegungstest von %1 wurde gestoppt.</translation>
    </message>
    <message>
        <source>%1 did not get back to %2 (it stands at %3).</source>
        <translation>%1 ist nicht zu %2 zurückgekehrt (es steht bei %3).</translation>
    </message>
    <message>
        <source>%1 reads %2, not %3</source>
        <translation>%1 ist %2, nicht %3</translation>
    </message>
    <message>
        <source>it could not be restored (%1); check its torque.</source>
        <translation>es konnte nicht wiederhergestellt werden (%1); prüfen Sie sein Drehmoment.</translation>
    </message>
    <message>
        <source>it was not restored as it was: %1.</source>
        <translation>es wurde nicht wie zuvor wiederhergestellt: %1.</translation>
    </message>
    <message>
        <source>%1 moved from %2 to %3 and back; its torque is on, as it was.</source>
        <translation>%1 hat sich von %2 zu %3 und zurück bewegt; sein Drehmoment ist ein, wie zuvor.</translation>
    </message>
    <message>
        <source>%1 moved from %2 to %3 and back; its torque is off, as it was.</source>
        <translation>%1 hat sich von %2 zu %3 und zurück bewegt; sein Drehmoment ist aus, wie zuvor.</translation>
    </message>
    <message>
        <source>%1 is of a model ServoBench does not move (%2); it cannot be identified.</source>
        <translation>%1 ist von einem Modell, das ServoBench nicht bewegt (%2); es kann nicht identifiziert werden.</translation>
    </message>
    <message>
        <source>Identifying %1 was stopped; nothing was written.</source>
        <translation>Identifizieren von %1 wurde gestoppt; es wurde nichts geschrieben.</translation>
    </message>
    <message>
        <source>%1 stands at %2, outside the goal positions it accepts: it is not moved.</source>
        <translation>%1 steht bei %2, außerhalb der Zielpositionen, die es akzeptiert: Es wird nicht bewegt.</translation>
    </message>
    <message>
        <source>%1&apos;s angle limits leave no room to move it around %2.</source>
        <translation>Die Winkelgrenzen von %1 lassen keinen Platz, um es um %2 herum zu bewegen.</translation>
    </message>
    <message>
        <source>Identifying %1 was stopped.</source>
        <translation>Identifizieren von %1 wurde gestoppt.</translation>
    </message>
    <message>
        <source>All torque off: identifying %1 was stopped.</source>
        <translation>Alle Drehmomente aus: Identifizieren von %1 wurde gestoppt.</translation>
    </message>
    <message>
        <source>its registers could not be restored (%1); check its torque.</source>
        <translation>seine Register konnten nicht wiederhergestellt werden (%1); prüfen Sie sein Drehmoment.</translation>
    </message>
    <message>
        <source>%1 was moved, but %2</source>
        <translation>%1 wurde bewegt, aber %2</translation>
    </message>
    <message>
        <source>%1 (%2) wiggled around %3 and is back; its torque is on, as it was.</source>
        <translation>%1 (%2) hat um %3 herum gewackelt und ist zurück; sein Drehmoment ist ein, wie zuvor.</translation>
    </message>
    <message>
        <source>%1 (%2) wiggled around %3 and is back; its torque is off, as it was.</source>
        <translation>%1 (%2) hat um %3 herum gewackelt und ist zurück; sein Drehmoment ist aus, wie zuvor.</translation>
    </message>
    <message>
        <source>SYNC READ at %1: no answer in time from ID %2</source>
        <translation>SYNC READ bei %1: keine rechtzeitige Antwort von ID %2</translation>
    </message>
    <message>
        <source>%1 Torque stays off.</source>
        <translation>%1 Das Drehmoment bleibt aus.</translation>
    </message>
    <message>
        <source>The operating mode could not be read.</source>
        <translation>Die Betriebsart konnte nicht gelesen werden.</translation>
    </message>
    <message>
        <source>Servo %1 is not in position mode (mode %2): its goal is not a position, so it cannot be held there.</source>
        <translation>Servo %1 ist nicht im Positionsmodus (Modus %2): Sein Ziel ist keine Position, daher kann es dort nicht gehalten werden.</translation>
    </message>
    <message>
        <source>The present position could not be read.</source>
        <translation>Die aktuelle Position konnte nicht gelesen werden.</translation>
    </message>
    <message>
        <source>The goal cannot be set to the present position (%1).</source>
        <translation>Das Ziel kann nicht auf die aktuelle Position (%1) gesetzt werden.</translation>
    </message>
    <message>
        <source>Setting the goal to the present position</source>
        <translation>Ziel wird auf die aktuelle Position gesetzt</translation>
    </message>
    <message>
        <source>Sent; its answers, if any, are in the packet log.</source>
        <translation>Gesendet; etwaige Antworten stehen im Paketprotokoll.</translation>
    </message>
    <message>
        <source>Servo %1 answered.</source>
        <translation>Servo %1 hat geantwortet.</translation>
    </message>
    <message>
        <source>Sent; servo %1 did not answer: %2</source>
        <translation>Gesendet; Servo %1 hat nicht geantwortet: %2</translation>
    </message>
    <message>
        <source>%1 stopped answering: check the power and the cable, then look again.</source>
        <translation>%1 antwortet nicht mehr: Prüfen Sie Stromversorgung und Kabel und suchen Sie dann erneut.</translation>
    </message>
    <message>
        <source>There is nothing to replay.</source>
        <translation>Es gibt nichts wiederzugeben.</translation>
    </message>
    <message>
        <source>%1 is of a model ServoBench does not move (%2): nothing was replayed.</source>
        <translation>%1 ist von einem Modell, das ServoBench nicht bewegt (%2): Es wurde nichts wiedergegeben.</translation>
    </message>
    <message>
        <source>A servo does not answer: %1 Nothing was replayed.</source>
        <translation>Ein Servo antwortet nicht: %1 Es wurde nichts wiedergegeben.</translation>
    </message>
    <message>
        <source>Frame %1 (at %2 s) asks %3 for %4, outside the positions it accepts (%5 to %6): nothing was moved.</source>
        <translation>Frame %1 (bei %2 s) verlangt von %3 die Position %4, außerhalb der Positionen, die es annimmt (%5 bis %6): Nichts wurde bewegt.</translation>
    </message>
    <message>
        <source>The replay was stopped; nothing was moved.</source>
        <translation>Die Wiedergabe wurde gestoppt; nichts wurde bewegt.</translation>
    </message>
    <message>
        <source>The servos could not be held where they stand: %1</source>
        <translation>Die Servos konnten nicht an ihrer Stelle gehalten werden: %1</translation>
    </message>
    <message numerus="yes">
        <source>Played %n frame(s)</source>
        <translation>
            <numerusform>%n Frame abgespielt</numerusform>
            <numerusform>%n Frames abgespielt</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n time(s)</source>
        <translation>
            <numerusform>(%n Durchlauf)</numerusform>
            <numerusform>(%n Durchläufe)</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 %2; the arm holds the last frame.</source>
        <translation>%1 %2; der Arm hält den letzten Frame.</translation>
    </message>
    <message>
        <source>%1 %2, but torque could not be switched off: %3</source>
        <translation>%1 %2, aber das Drehmoment konnte nicht abgeschaltet werden: %3</translation>
    </message>
    <message>
        <source>%1 %2; torque is off.</source>
        <translation>%1 %2; das Drehmoment ist aus.</translation>
    </message>
    <message>
        <source>%1 cannot take goal %2 with the others in one SYNC WRITE.</source>
        <translation>%1 kann Ziel %2 nicht zusammen mit den anderen in einem SYNC WRITE annehmen.</translation>
    </message>
    <message>
        <source>The replay stopped: %1</source>
        <translation>Die Wiedergabe wurde abgebrochen: %1</translation>
    </message>
    <message>
        <source>All torque off: the replay was stopped.</source>
        <translation>Alle Drehmomente aus: Die Wiedergabe wurde gestoppt.</translation>
    </message>
    <message>
        <source>Loop %1 of %2: easing to the first frame</source>
        <translation>Durchlauf %1 von %2: sanfte Fahrt zum ersten Frame</translation>
    </message>
    <message>
        <source>Loop %1 of %2: playing %3 frames over %4 s</source>
        <translation>Durchlauf %1 von %2: %3 Frames über %4 s werden abgespielt</translation>
    </message>
    <message>
        <source>Loop %1 of %2: frame %3 of %4</source>
        <translation>Durchlauf %1 von %2: Frame %3 von %4</translation>
    </message>
    <message>
        <source>while easing to the first frame (loop %1 of %2)</source>
        <translation>während der sanften Fahrt zum ersten Frame (Durchlauf %1 von %2)</translation>
    </message>
    <message>
        <source>at %1 s of %2 s (loop %3 of %4)</source>
        <translation>bei %1 s von %2 s (Durchlauf %3 von %4)</translation>
    </message>
    <message>
        <source>The replay was stopped %1; the arm holds where it stood.</source>
        <translation>Die Wiedergabe wurde %1 gestoppt; der Arm hält, wo er stand.</translation>
    </message>
    <message>
        <source>The replay was stopped %1, but the arm could not be held: %2</source>
        <translation>Die Wiedergabe wurde %1 gestoppt, aber der Arm konnte nicht gehalten werden: %2</translation>
    </message>
    <message numerus="yes">
        <source>The settings of %n servo(s) read.</source>
        <translation>
            <numerusform>Einstellungen von %n Servo gelesen.</numerusform>
            <numerusform>Einstellungen von %n Servos gelesen.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%1 of %n setting(s) fixed and verified.</source>
        <translation>
            <numerusform>%1 von %n Einstellung behoben und überprüft.</numerusform>
            <numerusform>%1 von %n Einstellungen behoben und überprüft.</numerusform>
        </translation>
    </message>
    <message>
        <source>Shared bus alert at ID %1: %2</source>
        <translation>Warnung am geteilten Bus bei ID %1: %2</translation>
    </message>
    <message>
        <source>Shared bus: %1</source>
        <translation>Geteilter Bus: %1</translation>
    </message>
    <message>
        <source>Not while the bus is shared with another program: this would change the port&apos;s rate under it. Stop sharing first.</source>
        <translation>Nicht, solange der Bus mit einem anderen Programm geteilt wird: Dies würde ihm die Baudrate des Ports unbemerkt ändern. Beenden Sie zuerst die Freigabe.</translation>
    </message>
    <message numerus="yes">
        <source> (%n position(s) a little past a joint&apos;s limit played at the limit)</source>
        <translation>
            <numerusform> (%n Position knapp hinter der Grenze eines Gelenks an der Grenze gespielt)</numerusform>
            <numerusform> (%n Positionen knapp hinter der Grenze eines Gelenks an der Grenze gespielt)</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>FeetechTelemetry</name>
    <message>
        <source>Position</source>
        <translation>Position</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>Geschwindigkeit</translation>
    </message>
    <message>
        <source>Load</source>
        <translation>Last</translation>
    </message>
    <message>
        <source>Voltage</source>
        <translation>Spannung</translation>
    </message>
    <message>
        <source>Temperature</source>
        <translation>Temperatur</translation>
    </message>
    <message>
        <source>Current</source>
        <translation>Strom</translation>
    </message>
    <message>
        <source>none</source>
        <translation>keine</translation>
    </message>
    <message>
        <source>Line %1: %2</source>
        <translation>Zeile %1: %2</translation>
    </message>
    <message>
        <source>not a ServoBench telemetry recording (unexpected header)</source>
        <translation>keine ServoBench-Telemetrieaufzeichnung (unerwarteter Kopf)</translation>
    </message>
    <message>
        <source>%1 cells instead of %2</source>
        <translation>%1 Zellen statt %2</translation>
    </message>
    <message>
        <source>the time is not a number</source>
        <translation>die Zeit ist keine Zahl</translation>
    </message>
    <message>
        <source>the ID is not a servo ID</source>
        <translation>die ID ist keine Servo-ID</translation>
    </message>
    <message>
        <source>%1 is not a number</source>
        <translation>%1 ist keine Zahl</translation>
    </message>
    <message>
        <source>the status is not a byte</source>
        <translation>der Status ist kein Byte</translation>
    </message>
    <message>
        <source>moving is neither 0 nor 1</source>
        <translation>moving ist weder 0 noch 1</translation>
    </message>
</context>
<context>
    <name>FeetechWorkspace</name>
    <message>
        <source>Scan…</source>
        <translation>Scannen…</translation>
    </message>
    <message>
        <source>Look for servos on the bus: choose IDs and baud rates</source>
        <translation>Servos am Bus suchen: IDs und Baudraten wählen</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <source>Stop the scan</source>
        <translation>Scan stoppen</translation>
    </message>
    <message>
        <source>%v of %m IDs</source>
        <translation>%v von %m IDs</translation>
    </message>
    <message>
        <source>Connect, then scan to find the servos.</source>
        <translation>Verbinden Sie und scannen Sie dann, um die Servos zu finden.</translation>
    </message>
    <message>
        <source>All torque off  (Esc)</source>
        <translation>Alle Drehmomente aus  (Esc)</translation>
    </message>
    <message>
        <source>Switch the torque of every servo on the bus off at once, ahead of anything else (also: Esc, from any page)</source>
        <translation>Das Drehmoment jedes Servos am Bus auf einmal abschalten, vor allem anderen (auch: Esc, von jeder Seite aus)</translation>
    </message>
    <message>
        <source>Change ID…</source>
        <translation>ID ändern…</translation>
    </message>
    <message>
        <source>Give the servo another ID; an ID in use is refused</source>
        <translation>Dem Servo eine andere ID geben; eine belegte ID wird abgelehnt</translation>
    </message>
    <message>
        <source>Change baud rate…</source>
        <translation>Baudrate ändern…</translation>
    </message>
    <message>
        <source>Move the servo to another baud rate and follow it there</source>
        <translation>Das Servo auf eine andere Baudrate umstellen und ihm dorthin folgen</translation>
    </message>
    <message>
        <source>Calibrate middle…</source>
        <translation>Mittelstellung kalibrieren…</translation>
    </message>
    <message>
        <source>Make the horn&apos;s present position the middle (2048)</source>
        <translation>Die aktuelle Position des Servohorns zur Mitte (2048) machen</translation>
    </message>
    <message>
        <source>Factory reset…</source>
        <translation>Werksreset…</translation>
    </message>
    <message>
        <source>Restore factory values (the ID is kept), after saving a backup profile</source>
        <translation>Werkswerte wiederherstellen (die ID bleibt erhalten), nachdem ein Sicherungsprofil gespeichert wurde</translation>
    </message>
    <message>
        <source>Reboot</source>
        <translation>Neustart</translation>
    </message>
    <message>
        <source>Torque off, restart the servo and wait until it answers again</source>
        <translation>Drehmoment aus, Servo neu starten und warten, bis es wieder antwortet</translation>
    </message>
    <message>
        <source>Clear status</source>
        <translation>Status löschen</translation>
    </message>
    <message>
        <source>Reset the servo&apos;s error status (instruction 0x0A)</source>
        <translation>Fehlerstatus des Servos zurücksetzen (Instruktion 0x0A)</translation>
    </message>
    <message>
        <source>The settings changed most, in real units. &lt;b&gt;EEPROM&lt;/b&gt; values are written with the lock opened and closed again and survive power-off. Changing the ID or the baud rate asks first, then follows the servo.</source>
        <translation>Die am häufigsten geänderten Einstellungen, in realen Einheiten. &lt;b&gt;EEPROM&lt;/b&gt;-Werte werden bei geöffneter und danach wieder geschlossener Sperre geschrieben und bleiben nach dem Ausschalten erhalten. Beim Ändern von ID oder Baudrate wird zuerst nachgefragt, dann folgt ServoBench dem Servo.</translation>
    </message>
    <message>
        <source>Settings</source>
        <translation>Einstellungen</translation>
    </message>
    <message>
        <source>Memory table</source>
        <translation>Speichertabelle</translation>
    </message>
    <message>
        <source>Control</source>
        <translation>Steuerung</translation>
    </message>
    <message>
        <source>Monitor</source>
        <translation>Monitor</translation>
    </message>
    <message>
        <source>Joints</source>
        <translation>Gelenke</translation>
    </message>
    <message>
        <source>Restarting the servo…</source>
        <translation>Servo wird neu gestartet…</translation>
    </message>
    <message>
        <source>Clearing the status…</source>
        <translation>Status wird gelöscht…</translation>
    </message>
    <message>
        <source>Working…</source>
        <translation>Wird bearbeitet…</translation>
    </message>
    <message>
        <source>Scanning at %1…</source>
        <translation>Scan bei %1…</translation>
    </message>
    <message>
        <source>Connect to the bus before scanning.</source>
        <translation>Verbinden Sie sich vor dem Scan mit dem Bus.</translation>
    </message>
    <message>
        <source>servo %1 (%2)</source>
        <translation>Servo %1 (%2)</translation>
    </message>
    <message>
        <source>Choose a servo in the tree.</source>
        <translation>Wählen Sie im Baum ein Servo aus.</translation>
    </message>
    <message>
        <source>No servo yet: connect to the bus and scan.</source>
        <translation>Noch kein Servo: Verbinden Sie sich mit dem Bus und scannen Sie.</translation>
    </message>
    <message>
        <source>unknown family</source>
        <translation>unbekannte Familie</translation>
    </message>
    <message>
        <source>status not read yet</source>
        <translation>Status noch nicht gelesen</translation>
    </message>
    <message>
        <source>status OK</source>
        <translation>Status OK</translation>
    </message>
    <message>
        <source>&lt;span style=&apos;color:#b3261e&apos;&gt;status: %1&lt;/span&gt;</source>
        <translation>&lt;span style=&apos;color:#b3261e&apos;&gt;Status: %1&lt;/span&gt;</translation>
    </message>
    <message>
        <source>&lt;b&gt;ID %1 · %2&lt;/b&gt; &amp;nbsp; model %3 · %4 family · firmware %5 · %6 · %7</source>
        <translation>&lt;b&gt;ID %1 · %2&lt;/b&gt; &amp;nbsp; Modell %3 · Familie %4 · Firmware %5 · %6 · %7</translation>
    </message>
    <message>
        <source>No register table is known for this model, so nothing is guessed: the Memory table shows its raw bytes, read-only.</source>
        <translation>Für dieses Modell ist keine Registertabelle bekannt, daher wird nichts geraten: Die Speichertabelle zeigt seine Rohbytes, schreibgeschützt.</translation>
    </message>
    <message>
        <source>SCS servos have no offset register: not available</source>
        <translation>SCS-Servos haben kein Offset-Register: nicht verfügbar</translation>
    </message>
    <message>
        <source>its ID from %1 to %2</source>
        <translation>seine ID von %1 auf %2</translation>
    </message>
    <message>
        <source>its baud rate from %1 to %2</source>
        <translation>seine Baudrate von %1 auf %2</translation>
    </message>
    <message>
        <source>Change how the servo is reached?</source>
        <translation>Ändern, wie das Servo erreicht wird?</translation>
    </message>
    <message>
        <source>This changes %1.&lt;br&gt;&lt;br&gt;ServoBench writes it to EEPROM with the lock opened and closed again, then finds the servo at its new address and confirms it there. Other programs and robot code must use the new address afterwards.</source>
        <translation>Dies ändert %1.&lt;br&gt;&lt;br&gt;ServoBench schreibt es bei geöffneter und danach wieder geschlossener Sperre ins EEPROM, findet das Servo dann unter seiner neuen Adresse und bestätigt es dort. Andere Programme und Robotercode müssen danach die neue Adresse verwenden.</translation>
    </message>
    <message>
        <source> and </source>
        <translation> und </translation>
    </message>
    <message>
        <source>Nothing was written: %1</source>
        <translation>Es wurde nichts geschrieben: %1</translation>
    </message>
    <message>
        <source>Change ID</source>
        <translation>ID ändern</translation>
    </message>
    <message>
        <source>New ID for %1 (IDs found on this bus: %2).
An ID in use is refused.</source>
        <translation>Neue ID für %1 (an diesem Bus gefundene IDs: %2).
Eine belegte ID wird abgelehnt.</translation>
    </message>
    <message>
        <source>ID %1 is already in use on this bus; nothing was written.</source>
        <translation>ID %1 wird an diesem Bus bereits verwendet; es wurde nichts geschrieben.</translation>
    </message>
    <message>
        <source>Change baud rate</source>
        <translation>Baudrate ändern</translation>
    </message>
    <message>
        <source>New baud rate for %1 (now %2). ServoBench follows the servo to the new rate and confirms it there.</source>
        <translation>Neue Baudrate für %1 (derzeit %2). ServoBench folgt dem Servo zur neuen Baudrate und bestätigt es dort.</translation>
    </message>
    <message>
        <source>Calibrate middle</source>
        <translation>Mittelstellung kalibrieren</translation>
    </message>
    <message>
        <source>The horn&apos;s present position becomes the middle (2048) of %1. Turn the horn to where the middle should be first; the new offset is stored in EEPROM.</source>
        <translation>Die aktuelle Position des Servohorns wird zur Mitte (2048) von %1. Drehen Sie das Servohorn zuerst dorthin, wo die Mitte sein soll; der neue Offset wird im EEPROM gespeichert.</translation>
    </message>
    <message>
        <source>Calibrating the middle…</source>
        <translation>Mittelstellung wird kalibriert…</translation>
    </message>
    <message>
        <source>Factory reset</source>
        <translation>Werksreset</translation>
    </message>
    <message>
        <source>First save a backup profile of %1; the reset only starts once it is saved.</source>
        <translation>Speichern Sie zuerst ein Sicherungsprofil von %1; der Reset beginnt erst, wenn es gespeichert ist.</translation>
    </message>
    <message>
        <source>Backup saved to %1.&lt;br&gt;&lt;br&gt;Restore the factory values of %2? Everything but the ID returns to what the servo left the factory with, possibly including its baud rate; ServoBench looks for it at every rate afterwards.</source>
        <translation>Sicherung in %1 gespeichert.&lt;br&gt;&lt;br&gt;Werkswerte von %2 wiederherstellen? Alles außer der ID kehrt zu dem zurück, womit das Servo das Werk verlassen hat, möglicherweise auch seine Baudrate; ServoBench sucht es danach bei jeder Baudrate.</translation>
    </message>
    <message>
        <source>Restoring factory values…</source>
        <translation>Werkswerte werden wiederhergestellt…</translation>
    </message>
    <message>
        <source>Choose a servo first.</source>
        <translation>Wählen Sie zuerst ein Servo.</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>%1 gespeichert</translation>
    </message>
    <message>
        <source>Only a servo of a known model can be saved as a profile.</source>
        <translation>Nur ein Servo eines bekannten Modells kann als Profil gespeichert werden.</translation>
    </message>
    <message>
        <source>Choose a servo of a known model first.</source>
        <translation>Wählen Sie zuerst ein Servo eines bekannten Modells.</translation>
    </message>
    <message>
        <source>Wait for the running operation to finish before loading a profile.</source>
        <translation>Warten Sie, bis der laufende Vorgang beendet ist, bevor Sie ein Profil laden.</translation>
    </message>
    <message>
        <source>Health</source>
        <translation>Zustand</translation>
    </message>
    <message>
        <source>No servo chosen. Scan the bus (Scan… at the top left), then choose a servo in the tree: its settings show here.</source>
        <translation>Kein Servo gewählt. Scannen Sie den Bus („Scannen…“ oben links) und wählen Sie dann ein Servo im Baum: Seine Einstellungen erscheinen hier.</translation>
    </message>
    <message>
        <source>Press Scan… to find the servos on the bus.</source>
        <translation>Drücken Sie „Scannen…“, um die Servos am Bus zu finden.</translation>
    </message>
    <message>
        <source>No servo yet: scan the bus.</source>
        <translation>Noch kein Servo: Scannen Sie den Bus.</translation>
    </message>
    <message>
        <source>Not connected: the servos listed are those of the last scan. Connect, then scan again.</source>
        <translation>Nicht verbunden: Die aufgeführten Servos stammen aus dem letzten Scan. Verbinden Sie sich und scannen Sie dann erneut.</translation>
    </message>
    <message>
        <source>✓ Verified: %1</source>
        <translation>✓ Verifiziert: %1</translation>
    </message>
</context>
<context>
    <name>GuardBanner</name>
    <message>
        <source>Recover…</source>
        <translation>Wiederherstellen…</translation>
    </message>
    <message>
        <source>Walks you through clearing the servo&apos;s overload trip: torque off and on, then a power cycle if needed.</source>
        <translation>Führt Sie durch das Zurücksetzen der Überlastauslösung des Servos: Drehmoment aus und ein, bei Bedarf dann Aus- und Einschalten der Stromversorgung.</translation>
    </message>
    <message>
        <source>Guard…</source>
        <translation>Schutz…</translation>
    </message>
    <message>
        <source>The overload and thermal guard&apos;s limits, hold time and action for each servo.</source>
        <translation>Grenzen, Haltezeit und Aktion des Überlast- und Temperaturschutzes für jedes Servo.</translation>
    </message>
    <message>
        <source>Guard on: an overloaded servo is stopped (held where it stands, or its torque switched off, as set under Guard…); a hot one has its torque switched off.</source>
        <translation>Schutz ein: Ein überlastetes Servo wird gestoppt (an der Stelle gehalten oder sein Drehmoment abgeschaltet, wie unter „Schutz…“ eingestellt); bei einem heißen wird das Drehmoment abgeschaltet.</translation>
    </message>
    <message>
        <source>Guard off: nothing stops an overloaded servo but its own protection.</source>
        <translation>Schutz aus: Nichts stoppt ein überlastetes Servo außer seinem eigenen Schutz.</translation>
    </message>
</context>
<context>
    <name>GuardSettingsDialog</name>
    <message>
        <source>Overload and thermal guard</source>
        <translation>Überlast- und Temperaturschutz</translation>
    </message>
    <message>
        <source>While a servo is driven (torque on, a goal, a test, an identify), the guard watches its load and temperature. When the load stays above its limit for the hold time, or the temperature comes within the margin of its maximum, it warns and then holds the servo where it stands (or switches its torque off). It never moves a servo. The defaults come from each servo&apos;s overload torque, protection time and maximum temperature registers.</source>
        <translation>Solange ein Servo angesteuert wird (Drehmoment ein, ein Ziel, ein Test, ein Identifizieren), überwacht der Schutz seine Last und Temperatur. Bleibt die Last länger als die Haltezeit über ihrer Grenze oder kommt die Temperatur bis auf den Abstand an ihr Maximum heran, warnt er und hält das Servo dann an seiner Stelle (oder schaltet sein Drehmoment ab). Er bewegt nie ein Servo. Die Standardwerte stammen aus den Registern für Überlastdrehmoment, Schutzzeit und Maximaltemperatur jedes Servos.</translation>
    </message>
    <message>
        <source>Guard the servos of this bus (recommended)</source>
        <translation>Die Servos dieses Busses schützen (empfohlen)</translation>
    </message>
    <message>
        <source>Servo</source>
        <translation>Servo</translation>
    </message>
    <message>
        <source>Guarded</source>
        <translation>Geschützt</translation>
    </message>
    <message>
        <source>Load limit</source>
        <translation>Lastgrenze</translation>
    </message>
    <message>
        <source>Hold time</source>
        <translation>Haltezeit</translation>
    </message>
    <message>
        <source>Max temperature</source>
        <translation>Max. Temperatur</translation>
    </message>
    <message>
        <source>Acts within</source>
        <translation>Eingriffsabstand</translation>
    </message>
    <message>
        <source>Action</source>
        <translation>Aktion</translation>
    </message>
    <message>
        <source>ID %1 (%2)</source>
        <translation>ID %1 (%2)</translation>
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
        <translation>Standardwerte wiederherstellen</translation>
    </message>
</context>
<context>
    <name>Hand</name>
    <message>
        <source>servo #%1 (ID %2)</source>
        <translation>Servo #%1 (ID %2)</translation>
    </message>
    <message>
        <source>position %1 is out of range: %2 turns from 0 to %3</source>
        <translation>Position %1 liegt außerhalb des Bereichs: %2 dreht von 0 bis %3</translation>
    </message>
    <message>
        <source>%1 has its torque on: it holds its position and the hand cannot turn it</source>
        <translation>%1 hat sein Drehmoment eingeschaltet: Es hält seine Position, und die Hand kann es nicht drehen</translation>
    </message>
    <message>
        <source>a sweep takes more than 0 and at most %1 seconds</source>
        <translation>ein Schwenk dauert mehr als 0 und höchstens %1 Sekunden</translation>
    </message>
    <message>
        <source>a sweep runs 0 (until released) to %1 times</source>
        <translation>ein Schwenk läuft 0 (bis zum Loslassen) bis %1 Mal</translation>
    </message>
    <message>
        <source>%1 is an SCS servo: it stops at 0 and %2, there is no seam to sweep across</source>
        <translation>%1 ist ein SCS-Servo: Es stoppt bei 0 und %2, es gibt keine Naht, über die geschwenkt werden könnte</translation>
    </message>
    <message>
        <source>the hand lets go: %1</source>
        <translation>die Hand lässt los: %1</translation>
    </message>
    <message numerus="yes">
        <source>the hand finished sweeping %1 (%n time(s))</source>
        <translation>
            <numerusform>die Hand hat das Schwenken von %1 beendet (%n Mal)</numerusform>
            <numerusform>die Hand hat das Schwenken von %1 beendet (%n Mal)</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>HealthPage</name>
    <message>
        <source>Move test</source>
        <translation>Bewegungstest</translation>
    </message>
    <message>
        <source>Checks each servo: firmware, voltage and temperature against its own limits, status bits, load, %1 reads for communication quality, position against its angle limits. It only reads; the move test moves a servo 100 steps and back, once you confirm.</source>
        <translation>Prüft jedes Servo: Firmware, Spannung und Temperatur gegen seine eigenen Grenzen, Statusbits, Last, %1 Lesevorgänge für die Kommunikationsqualität, Position gegen seine Winkelgrenzen. Es wird nur gelesen; der Bewegungstest bewegt ein Servo nach Ihrer Bestätigung um 100 Schritte und zurück.</translation>
    </message>
    <message>
        <source>Check</source>
        <translation>Prüfen</translation>
    </message>
    <message>
        <source>Read every servo found and give each a verdict</source>
        <translation>Jedes gefundene Servo lesen und jedem eine Bewertung geben</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <source>Stop the check before the next servo</source>
        <translation>Die Prüfung vor dem nächsten Servo stoppen</translation>
    </message>
    <message>
        <source>Move test…</source>
        <translation>Bewegungstest…</translation>
    </message>
    <message>
        <source>Move the selected servo a little and back, and measure how it follows</source>
        <translation>Das ausgewählte Servo ein wenig hin und zurück bewegen und messen, wie es folgt</translation>
    </message>
    <message>
        <source>Save report…</source>
        <translation>Bericht speichern…</translation>
    </message>
    <message>
        <source>Save the verdicts as an HTML page or as JSON</source>
        <translation>Die Bewertungen als HTML-Seite oder als JSON speichern</translation>
    </message>
    <message>
        <source>No servos scanned yet: scan the bus, then check their health here.</source>
        <translation>Noch keine Servos gescannt: Scannen Sie den Bus und prüfen Sie dann hier ihren Zustand.</translation>
    </message>
    <message>
        <source>ID</source>
        <translation>ID</translation>
    </message>
    <message>
        <source>Model</source>
        <translation>Modell</translation>
    </message>
    <message>
        <source>Firmware</source>
        <translation>Firmware</translation>
    </message>
    <message>
        <source>Verdict</source>
        <translation>Bewertung</translation>
    </message>
    <message>
        <source>Reasons</source>
        <translation>Gründe</translation>
    </message>
    <message>
        <source>Voltage</source>
        <translation>Spannung</translation>
    </message>
    <message>
        <source>Temperature</source>
        <translation>Temperatur</translation>
    </message>
    <message>
        <source>Load</source>
        <translation>Last</translation>
    </message>
    <message>
        <source>Communication</source>
        <translation>Kommunikation</translation>
    </message>
    <message numerus="yes">
        <source>Checking %n servo(s)…</source>
        <translation>
            <numerusform>%n Servo wird geprüft…</numerusform>
            <numerusform>%n Servos werden geprüft…</numerusform>
        </translation>
    </message>
    <message>
        <source>Select the servo to move in the table first.</source>
        <translation>Wählen Sie zuerst in der Tabelle das zu bewegende Servo aus.</translation>
    </message>
    <message>
        <source>The move test was not confirmed: nothing moved.</source>
        <translation>Der Bewegungstest wurde nicht bestätigt: Nichts wurde bewegt.</translation>
    </message>
    <message>
        <source>Servo %1 is no longer on the bus: nothing moved.</source>
        <translation>Servo %1 ist nicht mehr am Bus: Nichts wurde bewegt.</translation>
    </message>
    <message>
        <source>Moving servo %1…</source>
        <translation>Servo %1 wird bewegt…</translation>
    </message>
    <message>
        <source>Save the report as .html or .json: %1 is neither.</source>
        <translation>Speichern Sie den Bericht als .html oder .json: %1 ist keins von beiden.</translation>
    </message>
    <message>
        <source>Report saved to %1.</source>
        <translation>Bericht in %1 gespeichert.</translation>
    </message>
    <message>
        <source>Save health report</source>
        <translation>Zustandsbericht speichern</translation>
    </message>
    <message>
        <source>HTML page (*.html);;JSON (*.json)</source>
        <translation>HTML-Seite (*.html);;JSON (*.json)</translation>
    </message>
    <message>
        <source>not checked</source>
        <translation>nicht geprüft</translation>
    </message>
    <message>
        <source>Settings</source>
        <translation>Einstellungen</translation>
    </message>
    <message>
        <source>%1 (ID %2)</source>
        <translation>%1 (ID %2)</translation>
    </message>
    <message numerus="yes">
        <source>Of the %1, %n joint(s) did not answer the scan: %2. Check their cables and scan again.</source>
        <translation>
            <numerusform>Vom %1 antwortete %n Gelenk nicht beim Scan: %2. Prüfen Sie seine Kabel und scannen Sie erneut.</numerusform>
            <numerusform>Vom %1 antworteten %n Gelenke nicht beim Scan: %2. Prüfen Sie ihre Kabel und scannen Sie erneut.</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 (%2) will move %3 steps from where it stands and back, with its torque on meanwhile. Make sure nothing is in the way. Move it?</source>
        <translation>%1 (%2) bewegt sich %3 Schritte von seiner Stellung weg und zurück, währenddessen mit eingeschaltetem Drehmoment. Achten Sie darauf, dass nichts im Weg ist. Bewegen?</translation>
    </message>
</context>
<context>
    <name>HealthReport</name>
    <message>
        <source>not read</source>
        <translation>nicht gelesen</translation>
    </message>
    <message>
        <source>Servo health report</source>
        <translation>Servo-Zustandsbericht</translation>
    </message>
    <message>
        <source>Port %1, checked %2</source>
        <translation>Anschluss %1, geprüft am %2</translation>
    </message>
    <message>
        <source>No servo was checked.</source>
        <translation>Es wurde kein Servo geprüft.</translation>
    </message>
    <message>
        <source>ID</source>
        <translation>ID</translation>
    </message>
    <message>
        <source>Model</source>
        <translation>Modell</translation>
    </message>
    <message>
        <source>Firmware</source>
        <translation>Firmware</translation>
    </message>
    <message>
        <source>Verdict</source>
        <translation>Bewertung</translation>
    </message>
    <message>
        <source>Voltage</source>
        <translation>Spannung</translation>
    </message>
    <message>
        <source>Temperature</source>
        <translation>Temperatur</translation>
    </message>
    <message>
        <source>Load</source>
        <translation>Last</translation>
    </message>
    <message>
        <source>Status</source>
        <translation>Status</translation>
    </message>
    <message>
        <source>Communication</source>
        <translation>Kommunikation</translation>
    </message>
    <message>
        <source>Move test</source>
        <translation>Bewegungstest</translation>
    </message>
    <message>
        <source>Reasons</source>
        <translation>Gründe</translation>
    </message>
    <message>
        <source>not run</source>
        <translation>nicht ausgeführt</translation>
    </message>
    <message>
        <source>none</source>
        <translation>keine</translation>
    </message>
    <message>
        <source>The report could not be saved to %1: %2</source>
        <translation>Der Bericht konnte nicht in %1 gespeichert werden: %2</translation>
    </message>
</context>
<context>
    <name>IdentifyQuestion</name>
    <message>
        <source>Identify a servo</source>
        <translation>Servo identifizieren</translation>
    </message>
    <message>
        <source>Move it</source>
        <translation>Bewegen</translation>
    </message>
    <message>
        <source>Identify moves %1: its torque comes on and it turns %2 steps each way, slowly and with little torque, then goes back where it was, its settings as before.

Keep hands and objects clear of the arm. Move it now?</source>
        <translation>Identifizieren bewegt %1: Das Drehmoment wird eingeschaltet, das Servo dreht sich langsam und mit wenig Drehmoment um %2 Schritte in jede Richtung und kehrt dann an seine Ausgangsstellung zurück, mit denselben Einstellungen wie zuvor.

Halten Sie Hände und Gegenstände vom Arm fern. Jetzt bewegen?</translation>
    </message>
</context>
<context>
    <name>InProcessPort</name>
    <message>
        <source>A simulated port needs a name.</source>
        <translation>Ein simulierter Anschluss braucht einen Namen.</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
</context>
<context>
    <name>InProcessTransport</name>
    <message>
        <source>%1 is not running: its simulated servos have stopped.</source>
        <translation>%1 läuft nicht: Die zugehörigen simulierten Servos wurden beendet.</translation>
    </message>
    <message>
        <source>%1 is already open.</source>
        <translation>%1 ist bereits geöffnet.</translation>
    </message>
    <message>
        <source>%1 went away: its simulated servos have stopped.</source>
        <translation>%1 ist verschwunden: Die zugehörigen simulierten Servos wurden beendet.</translation>
    </message>
</context>
<context>
    <name>Joint</name>
    <message>
        <source>shoulder_pan</source>
        <translation>Schulterdrehung</translation>
    </message>
    <message>
        <source>shoulder_lift</source>
        <translation>Schulterhub</translation>
    </message>
    <message>
        <source>elbow_flex</source>
        <translation>Ellbogen</translation>
    </message>
    <message>
        <source>wrist_flex</source>
        <translation>Handgelenk beugen</translation>
    </message>
    <message>
        <source>wrist_roll</source>
        <translation>Handgelenk drehen</translation>
    </message>
    <message>
        <source>gripper</source>
        <translation>Greifer</translation>
    </message>
</context>
<context>
    <name>JointNameDelegate</name>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
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
        <translation>Positionen lesen</translation>
    </message>
    <message>
        <source>Read every servo&apos;s registers now: positions, limits and torque</source>
        <translation>Register jedes Servos jetzt lesen: Positionen, Grenzen und Drehmoment</translation>
    </message>
    <message>
        <source>Targets from present positions</source>
        <translation>Ziele aus aktuellen Positionen</translation>
    </message>
    <message>
        <source>Copy every servo&apos;s present position into its target</source>
        <translation>Die aktuelle Position jedes Servos in sein Ziel kopieren</translation>
    </message>
    <message>
        <source>Move all</source>
        <translation>Alle bewegen</translation>
    </message>
    <message>
        <source>Send every target at once: one SYNC WRITE per baud rate</source>
        <translation>Alle Ziele auf einmal senden: ein SYNC WRITE pro Baudrate</translation>
    </message>
    <message>
        <source>Targets only move servos when you press Move all.</source>
        <translation>Ziele bewegen Servos erst, wenn Sie „Alle bewegen“ drücken.</translation>
    </message>
    <message>
        <source>ID %1</source>
        <translation>ID %1</translation>
    </message>
    <message>
        <source>ID %1 (%2)</source>
        <translation>ID %1 (%2)</translation>
    </message>
    <message>
        <source>Scan the bus to list its servos here.</source>
        <translation>Scannen Sie den Bus, um seine Servos hier aufzulisten.</translation>
    </message>
    <message>
        <source>&lt;b&gt;Live positions:&lt;/b&gt; the monitor is not running, so positions are the last values read (grey) and may be stale. Start the monitor to see live positions, or read them now.</source>
        <translation>&lt;b&gt;Live-Positionen:&lt;/b&gt; Der Monitor läuft nicht, daher sind die Positionen die zuletzt gelesenen Werte (grau) und möglicherweise veraltet. Starten Sie den Monitor, um Live-Positionen zu sehen, oder lesen Sie sie jetzt.</translation>
    </message>
    <message>
        <source>&lt;b&gt;Live positions&lt;/b&gt; from the monitor; servos it does not watch show the last value read, in grey.</source>
        <translation>&lt;b&gt;Live-Positionen&lt;/b&gt; vom Monitor; Servos, die er nicht beobachtet, zeigen den zuletzt gelesenen Wert in Grau.</translation>
    </message>
    <message>
        <source>&lt;b&gt;Live positions&lt;/b&gt; from the monitor.</source>
        <translation>&lt;b&gt;Live-Positionen&lt;/b&gt; vom Monitor.</translation>
    </message>
    <message>
        <source>Move all failed: %1</source>
        <translation>„Alle bewegen“ fehlgeschlagen: %1</translation>
    </message>
    <message>
        <source>%1: torque was not switched %2: %3</source>
        <translation>%1: Drehmoment wurde nicht %2: %3</translation>
    </message>
    <message>
        <source>on</source>
        <translation>eingeschaltet</translation>
    </message>
    <message>
        <source>off</source>
        <translation>ausgeschaltet</translation>
    </message>
    <message>
        <source>That servo is no longer on the bus.</source>
        <translation>Dieses Servo ist nicht mehr am Bus.</translation>
    </message>
    <message>
        <source>%1: torque not switched %2: %3</source>
        <translation>%1: Drehmoment nicht %2: %3</translation>
    </message>
    <message>
        <source>Targets set to the present positions of %1 servos.</source>
        <translation>Ziele auf die aktuellen Positionen von %1 Servos gesetzt.</translation>
    </message>
    <message>
        <source>Targets set for %1 servos. No position is known yet for %2: read the positions first.</source>
        <translation>Ziele für %1 Servos gesetzt. Für %2 ist noch keine Position bekannt: Lesen Sie zuerst die Positionen.</translation>
    </message>
    <message>
        <source>, </source>
        <translation>, </translation>
    </message>
    <message>
        <source>The bus is not connected: nothing was sent.</source>
        <translation>Der Bus ist nicht verbunden: Es wurde nichts gesendet.</translation>
    </message>
    <message>
        <source>No servos: scan the bus first.</source>
        <translation>Keine Servos: Scannen Sie zuerst den Bus.</translation>
    </message>
    <message>
        <source>%1 has no target: type one, load a pose or use “Targets from present positions”. Nothing was sent.</source>
        <translation>%1 hat kein Ziel: Tippen Sie eins ein, laden Sie eine Pose oder verwenden Sie „Ziele aus aktuellen Positionen“. Es wurde nichts gesendet.</translation>
    </message>
    <message>
        <source>%1: the target %2 is outside its range %3 to %4. Nothing was sent.</source>
        <translation>%1: Das Ziel %2 liegt außerhalb seines Bereichs %3 bis %4. Es wurde nichts gesendet.</translation>
    </message>
    <message>
        <source>%1 is in %2 mode; a goal position only moves a servo in position mode. Nothing was sent.</source>
        <translation>%1 ist im Modus %2; eine Zielposition bewegt ein Servo nur im Positionsmodus. Es wurde nichts gesendet.</translation>
    </message>
    <message>
        <source>No servo here can be moved: their models are unknown.</source>
        <translation>Kein Servo hier kann bewegt werden: Ihre Modelle sind unbekannt.</translation>
    </message>
    <message>
        <source>Nothing was sent: %1</source>
        <translation>Es wurde nichts gesendet: %1</translation>
    </message>
    <message>
        <source>Targets sent to IDs %1 in one SYNC WRITE.</source>
        <translation>Ziele an IDs %1 in einem SYNC WRITE gesendet.</translation>
    </message>
    <message>
        <source>Targets sent to IDs %1 in %2 SYNC WRITEs, one per baud rate.</source>
        <translation>Ziele an IDs %1 in %2 SYNC WRITEs gesendet, einem pro Baudrate.</translation>
    </message>
    <message>
        <source>Torque is off on %1: it will not move until torque is on.</source>
        <translation>Drehmoment ist aus bei %1: Es bewegt sich erst, wenn das Drehmoment eingeschaltet ist.</translation>
    </message>
    <message>
        <source>Not moved (unknown model): %1.</source>
        <translation>Nicht bewegt (unbekanntes Modell): %1.</translation>
    </message>
    <message>
        <source>The bus is not connected.</source>
        <translation>Der Bus ist nicht verbunden.</translation>
    </message>
    <message>
        <source>Reading %1 servos…</source>
        <translation>%1 Servos werden gelesen…</translation>
    </message>
    <message>
        <source>Identify</source>
        <translation>Identifizieren</translation>
    </message>
    <message>
        <source>its model has no torque enable</source>
        <translation>sein Modell hat kein torque enable</translation>
    </message>
    <message>
        <source>%1 cannot be identified now: %2</source>
        <translation>%1 kann jetzt nicht identifiziert werden: %2</translation>
    </message>
    <message>
        <source>Identifying %1: watch which horn moves…</source>
        <translation>%1 wird identifiziert: Achten Sie darauf, welches Servohorn sich bewegt…</translation>
    </message>
    <message>
        <source>Wiggle %1 slowly with little torque, then put it back as it was</source>
        <translation>%1 langsam mit wenig Drehmoment wackeln lassen und dann wie zuvor zurückstellen</translation>
    </message>
    <message numerus="yes">
        <source>Reading %n servo(s)…</source>
        <translation>
            <numerusform>%n Servo wird gelesen…</numerusform>
            <numerusform>%n Servos werden gelesen…</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>JointTablePoses</name>
    <message>
        <source>Load pose…</source>
        <translation>Pose laden…</translation>
    </message>
    <message>
        <source>Fill the targets from a pose file; nothing moves until Move all</source>
        <translation>Die Ziele aus einer Posendatei füllen; nichts bewegt sich vor „Alle bewegen“</translation>
    </message>
    <message>
        <source>Save pose…</source>
        <translation>Pose speichern…</translation>
    </message>
    <message>
        <source>Save the targets as a pose file</source>
        <translation>Die Ziele als Posendatei speichern</translation>
    </message>
    <message>
        <source>No targets to save: set some first.</source>
        <translation>Keine Ziele zu speichern: Setzen Sie zuerst welche.</translation>
    </message>
    <message>
        <source>Saved the pose “%1” with %2 targets to %3.</source>
        <translation>Pose „%1“ mit %2 Zielen in %3 gespeichert.</translation>
    </message>
    <message>
        <source>Pose: %1</source>
        <translation>Pose: %1</translation>
    </message>
    <message>
        <source>Loaded the pose “%1”: %2 targets filled. Nothing moves until you press Move all.</source>
        <translation>Pose „%1“ geladen: %2 Ziele gefüllt. Nichts bewegt sich, bis Sie „Alle bewegen“ drücken.</translation>
    </message>
    <message>
        <source>ID %1 at %2</source>
        <translation>ID %1 bei %2</translation>
    </message>
    <message>
        <source>Not on the bus: %1.</source>
        <translation>Nicht am Bus: %1.</translation>
    </message>
    <message>
        <source>, </source>
        <translation>, </translation>
    </message>
    <message>
        <source>Not in the pose (targets unchanged): %1.</source>
        <translation>Nicht in der Pose (Ziele unverändert): %1.</translation>
    </message>
    <message>
        <source>Outside their range (shown in red): %1.</source>
        <translation>Außerhalb ihres Bereichs (rot dargestellt): %1.</translation>
    </message>
    <message>
        <source>pose.json</source>
        <translation>pose.json</translation>
    </message>
    <message>
        <source>Save pose</source>
        <translation>Pose speichern</translation>
    </message>
    <message>
        <source>ServoBench poses (*.json);;All files (*)</source>
        <translation>ServoBench-Posen (*.json);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Load pose</source>
        <translation>Pose laden</translation>
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
        <translation>Modell</translation>
    </message>
    <message>
        <source>Baud rate</source>
        <translation>Baudrate</translation>
    </message>
    <message>
        <source>Target range</source>
        <translation>Zielbereich</translation>
    </message>
    <message>
        <source>Torque</source>
        <translation>Drehmoment</translation>
    </message>
    <message>
        <source>Motion</source>
        <translation>Bewegung</translation>
    </message>
    <message>
        <source>Identify</source>
        <translation>Identifizieren</translation>
    </message>
    <message>
        <source>Present position: live while the monitor watches the servo, otherwise the last value read (grey)</source>
        <translation>Aktuelle Position: live, solange der Monitor das Servo beobachtet, sonst der zuletzt gelesene Wert (grau)</translation>
    </message>
    <message>
        <source>Where Move all sends the servo: double-click or type to change it</source>
        <translation>Wohin „Alle bewegen“ das Servo schickt: Doppelklicken oder eintippen, um es zu ändern</translation>
    </message>
    <message>
        <source>The servo&apos;s angle limits, or the goal register&apos;s range when the limits are unknown or both 0</source>
        <translation>Die Winkelgrenzen des Servos oder der Bereich des Zielregisters, wenn die Grenzen unbekannt oder beide 0 sind</translation>
    </message>
    <message>
        <source>Tick to switch torque on, untick to switch it off</source>
        <translation>Anhaken, um das Drehmoment einzuschalten, abhaken, um es abzuschalten</translation>
    </message>
    <message>
        <source>Whether the servo reports that it is moving</source>
        <translation>Ob das Servo meldet, dass es sich bewegt</translation>
    </message>
    <message>
        <source>Wiggle the servo slowly with little torque, then put it back as it was: see which servo of the arm it is</source>
        <translation>Das Servo langsam mit wenig Drehmoment wackeln lassen und dann wie zuvor zurückstellen: sehen, welches Servo des Arms es ist</translation>
    </message>
    <message>
        <source>%1 family, firmware %2</source>
        <translation>Familie %1, Firmware %2</translation>
    </message>
    <message>
        <source>Unknown model: it cannot be moved from here</source>
        <translation>Unbekanntes Modell: Es kann von hier aus nicht bewegt werden</translation>
    </message>
    <message>
        <source>Switching on…</source>
        <translation>Wird eingeschaltet…</translation>
    </message>
    <message>
        <source>Switching off…</source>
        <translation>Wird ausgeschaltet…</translation>
    </message>
    <message>
        <source>Unknown</source>
        <translation>Unbekannt</translation>
    </message>
    <message>
        <source>Off</source>
        <translation>Aus</translation>
    </message>
    <message>
        <source>On</source>
        <translation>Ein</translation>
    </message>
    <message>
        <source>Damping</source>
        <translation>Dämpfung</translation>
    </message>
    <message>
        <source>Live, from the monitor</source>
        <translation>Live, vom Monitor</translation>
    </message>
    <message>
        <source>Last value read: it may be stale</source>
        <translation>Zuletzt gelesener Wert: möglicherweise veraltet</translation>
    </message>
    <message>
        <source>Not read yet</source>
        <translation>Noch nicht gelesen</translation>
    </message>
    <message>
        <source>Moving</source>
        <translation>In Bewegung</translation>
    </message>
    <message>
        <source>Still</source>
        <translation>Steht</translation>
    </message>
    <message>
        <source>Unknown model: no goal register</source>
        <translation>Unbekanntes Modell: kein Zielregister</translation>
    </message>
    <message>
        <source>%1 to %2</source>
        <translation>%1 bis %2</translation>
    </message>
    <message>
        <source>From the servo&apos;s angle limits</source>
        <translation>Aus den Winkelgrenzen des Servos</translation>
    </message>
    <message>
        <source>The goal register&apos;s range: the angle limits are not read yet or both 0</source>
        <translation>Der Bereich des Zielregisters: Die Winkelgrenzen sind noch nicht gelesen oder beide 0</translation>
    </message>
    <message>
        <source>Outside the range %1 to %2: Move all will refuse it</source>
        <translation>Außerhalb des Bereichs %1 bis %2: „Alle bewegen“ wird es ablehnen</translation>
    </message>
    <message>
        <source>No target yet: type one, load a pose or take the present position</source>
        <translation>Noch kein Ziel: Tippen Sie eins ein, laden Sie eine Pose oder übernehmen Sie die aktuelle Position</translation>
    </message>
    <message>
        <source>Position (%1)</source>
        <translation>Position (%1)</translation>
    </message>
    <message>
        <source>Target (%1)</source>
        <translation>Ziel (%1)</translation>
    </message>
</context>
<context>
    <name>LanguageMenu</name>
    <message>
        <source>&amp;Language</source>
        <translation>&amp;Sprache</translation>
    </message>
    <message>
        <source>The system&apos;s language</source>
        <translation>Sprache des Systems</translation>
    </message>
    <message>
        <source>Language</source>
        <translation>Sprache</translation>
    </message>
    <message>
        <source>ServoBench shows the new language after it starts again.</source>
        <translation>ServoBench zeigt die neue Sprache nach einem Neustart.</translation>
    </message>
    <message>
        <source>Restart now</source>
        <translation>Jetzt neu starten</translation>
    </message>
    <message>
        <source>Later</source>
        <translation>Später</translation>
    </message>
</context>
<context>
    <name>LeRobotCalibration</name>
    <message>
        <source>not a LeRobot calibration (the document is not a JSON object of motors by joint name)</source>
        <translation>keine LeRobot-Kalibrierung (das Dokument ist kein JSON-Objekt aus Motoren nach Gelenknamen)</translation>
    </message>
    <message>
        <source>the calibration names no motor</source>
        <translation>die Kalibrierung nennt keinen Motor</translation>
    </message>
    <message>
        <source>a motor has an empty name</source>
        <translation>ein Motor hat einen leeren Namen</translation>
    </message>
    <message>
        <source>motor &quot;%1&quot;: not a motor name (ASCII letters, digits and _, a letter first)</source>
        <translation>Motor „%1“: kein Motorname (ASCII-Buchstaben, Ziffern und _, beginnend mit einem Buchstaben)</translation>
    </message>
    <message>
        <source>motor &quot;%1&quot;: not an object of id, drive_mode, homing_offset, range_min and range_max</source>
        <translation>Motor „%1“: kein Objekt aus id, drive_mode, homing_offset, range_min und range_max</translation>
    </message>
    <message>
        <source>motor &quot;%1&quot;: unknown field &quot;%2&quot;</source>
        <translation>Motor „%1“: unbekanntes Feld „%2“</translation>
    </message>
    <message>
        <source>motor &quot;%1&quot;: &quot;%2&quot; is missing</source>
        <translation>Motor „%1“: „%2“ fehlt</translation>
    </message>
    <message>
        <source>motor &quot;%1&quot;: &quot;%2&quot; must be a whole number</source>
        <translation>Motor „%1“: „%2“ muss eine ganze Zahl sein</translation>
    </message>
    <message>
        <source>motor &quot;%1&quot;: &quot;%2&quot; is %3, outside %4 to %5</source>
        <translation>Motor „%1“: „%2“ ist %3, außerhalb von %4 bis %5</translation>
    </message>
    <message>
        <source>motor &quot;%1&quot;: &quot;%2&quot; (%3) must be below &quot;%4&quot; (%5)</source>
        <translation>Motor „%1“: „%2“ (%3) muss kleiner sein als „%4“ (%5)</translation>
    </message>
    <message>
        <source>motor &quot;%1&quot;: ID %2 is used by another motor too</source>
        <translation>Motor „%1“: ID %2 wird auch von einem anderen Motor verwendet</translation>
    </message>
    <message>
        <source>the file is too large for a calibration</source>
        <translation>die Datei ist zu groß für eine Kalibrierung</translation>
    </message>
    <message>
        <source>no joint has ID %1 (%2): it is not this arm&apos;s file</source>
        <translation>kein Gelenk hat ID %1 (%2): es ist nicht die Datei dieses Arms</translation>
    </message>
</context>
<context>
    <name>LinkSession</name>
    <message>
        <source>Disconnected.</source>
        <translation>Getrennt.</translation>
    </message>
    <message>
        <source>%1 Reconnecting when it comes back.</source>
        <translation>%1 Verbindung wird wiederhergestellt, sobald er zurück ist.</translation>
    </message>
</context>
<context>
    <name>LoadCalibrationDialog</name>
    <message>
        <source>Load calibration</source>
        <translation>Kalibrierung laden</translation>
    </message>
    <message>
        <source>What %1 would change on each joint (now → file). Nothing is written until you press Write.</source>
        <translation>Was %1 an jedem Gelenk ändern würde (jetzt → Datei). Nichts wird geschrieben, bevor Sie „Schreiben“ drücken.</translation>
    </message>
    <message>
        <source>Joint</source>
        <translation>Gelenk</translation>
    </message>
    <message>
        <source>Offset</source>
        <translation>Offset</translation>
    </message>
    <message>
        <source>Min limit</source>
        <translation>Min.-Grenze</translation>
    </message>
    <message>
        <source>Max limit</source>
        <translation>Max.-Grenze</translation>
    </message>
    <message>
        <source>Status</source>
        <translation>Status</translation>
    </message>
    <message>
        <source>Reading the servos…</source>
        <translation>Servos werden gelesen…</translation>
    </message>
    <message>
        <source>&amp;Write</source>
        <translation>&amp;Schreiben</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>no answer</source>
        <translation>keine Antwort</translation>
    </message>
    <message>
        <source>Written and verified</source>
        <translation>Geschrieben und verifiziert</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>Schließen</translation>
    </message>
    <message>
        <source>Every change was written and verified.</source>
        <translation>Jede Änderung wurde geschrieben und verifiziert.</translation>
    </message>
    <message>
        <source>Not every change was written: see the status column.</source>
        <translation>Nicht jede Änderung wurde geschrieben: siehe Statusspalte.</translation>
    </message>
    <message>
        <source>Servo %1 is not on the bus: nothing written</source>
        <translation>Servo %1 ist nicht am Bus: nichts geschrieben</translation>
    </message>
    <message>
        <source>Servo %1 could not be read (%2): nothing written</source>
        <translation>Servo %1 konnte nicht gelesen werden (%2): nichts geschrieben</translation>
    </message>
    <message>
        <source>%1 → %2</source>
        <translation>%1 → %2</translation>
    </message>
    <message>
        <source>Unchanged</source>
        <translation>Unverändert</translation>
    </message>
    <message>
        <source>Torque is on: the new offset would move the horn. Switch torque off (support the arm) and load again.</source>
        <translation>Das Drehmoment ist ein: Der neue Offset würde das Servohorn bewegen. Schalten Sie das Drehmoment ab (stützen Sie den Arm) und laden Sie erneut.</translation>
    </message>
    <message>
        <source>To write</source>
        <translation>Zu schreiben</translation>
    </message>
    <message>
        <source>Not every servo could be read: those joints are not written.</source>
        <translation>Nicht jedes Servo konnte gelesen werden: Diese Gelenke werden nicht geschrieben.</translation>
    </message>
    <message>
        <source>Nothing to write.</source>
        <translation>Nichts zu schreiben.</translation>
    </message>
    <message numerus="yes">
        <source>Write %n joint(s) to EEPROM (locked writes, verified)?</source>
        <translation>
            <numerusform>%n Gelenk ins EEPROM schreiben (mit EEPROM-Sperre, verifiziert)?</numerusform>
            <numerusform>%n Gelenke ins EEPROM schreiben (mit EEPROM-Sperre, verifiziert)?</numerusform>
        </translation>
    </message>
    <message>
        <source>Writing to EEPROM and verifying…</source>
        <translation>Schreiben ins EEPROM und Verifizieren…</translation>
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
        <translation>Nicht verbunden</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <source>&amp;Load profile…</source>
        <translation>Profil &amp;laden…</translation>
    </message>
    <message>
        <source>&amp;Save profile…</source>
        <translation>Profil &amp;speichern…</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <source>&amp;Link</source>
        <translation>&amp;Verbindung</translation>
    </message>
    <message>
        <source>&amp;Poll the servo</source>
        <translation>Servo &amp;abfragen</translation>
    </message>
    <message>
        <source>Keep reading the eight queries so the values stay live</source>
        <translation>Die acht Abfragen fortlaufend lesen, damit die Werte live bleiben</translation>
    </message>
    <message>
        <source>&amp;Fast polling (queries back to back)</source>
        <translation>&amp;Schnelles Abfragen (Abfragen direkt hintereinander)</translation>
    </message>
    <message>
        <source>&amp;Scan the Feetech bus…</source>
        <translation>&amp;Feetech-Bus scannen…</translation>
    </message>
    <message>
        <source>Disconnect from the PTK servo before scanning a Feetech bus.</source>
        <translation>Trennen Sie die Verbindung zum PTK-Servo, bevor Sie einen Feetech-Bus scannen.</translation>
    </message>
    <message>
        <source>All &amp;torque off</source>
        <translation>Alle &amp;Drehmomente aus</translation>
    </message>
    <message>
        <source>Switch the torque of every servo on the Feetech bus off</source>
        <translation>Das Drehmoment jedes Servos am Feetech-Bus abschalten</translation>
    </message>
    <message>
        <source>Torque off: sent to every servo…</source>
        <translation>Drehmoment aus: an jedes Servo gesendet…</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Ansicht</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>&amp;Hilfe</translation>
    </message>
    <message>
        <source>&amp;About ServoBench</source>
        <translation>&amp;Über ServoBench</translation>
    </message>
    <message>
        <source>About &amp;Qt</source>
        <translation>Über &amp;Qt</translation>
    </message>
    <message>
        <source>About ServoBench</source>
        <translation>Über ServoBench</translation>
    </message>
    <message>
        <source>Some changes have not been written to the servos. Quit anyway?</source>
        <translation>Einige Änderungen wurden nicht auf die Servos geschrieben. Trotzdem beenden?</translation>
    </message>
    <message>
        <source>Connecting to %1…</source>
        <translation>Verbindung zu %1 wird hergestellt…</translation>
    </message>
    <message>
        <source>Open: %1</source>
        <translation>Geöffnet: %1</translation>
    </message>
    <message>
        <source>Connected: %1 at %2 baud</source>
        <translation>Verbunden: %1 mit %2 Baud</translation>
    </message>
    <message>
        <source>No reply on %1</source>
        <translation>Keine Antwort an %1</translation>
    </message>
    <message>
        <source>Disconnected: %1 went away, waiting for it to return</source>
        <translation>Getrennt: %1 ist verschwunden, es wird auf seine Rückkehr gewartet</translation>
    </message>
    <message>
        <source>sent %1 · ok %2 · checksum errors %3 · timeouts %4 · retries %5 · discarded %6 B</source>
        <translation>gesendet %1 · ok %2 · Prüfsummenfehler %3 · Zeitüberschreitungen %4 · Wiederholungen %5 · verworfen %6 B</translation>
    </message>
    <message>
        <source>%1 queries/s</source>
        <translation>%1 Abfragen/s</translation>
    </message>
    <message>
        <source>Unapplied changes</source>
        <translation>Nicht übernommene Änderungen</translation>
    </message>
    <message>
        <source>&amp;Robot</source>
        <translation>&amp;Roboter</translation>
    </message>
    <message>
        <source>Set up &amp;motors…</source>
        <translation>&amp;Motoren einrichten…</translation>
    </message>
    <message>
        <source>&lt;p&gt;&lt;b&gt;ServoBench %1&lt;/b&gt;&lt;/p&gt;&lt;p&gt;Programs and monitors PTK RC servos and Feetech serial-bus servos on Linux, Windows and macOS.&lt;/p&gt;&lt;p&gt;Built with Qt %2, running on Qt %3.&lt;/p&gt;&lt;p&gt;Free software under the GNU General Public License, version 3 or (at your option) any later version; it comes with no warranty.&lt;/p&gt;</source>
        <translation>&lt;p&gt;&lt;b&gt;ServoBench %1&lt;/b&gt;&lt;/p&gt;&lt;p&gt;Programmiert und überwacht PTK-RC-Servos und Feetech-Servos am seriellen Bus unter Linux, Windows und macOS.&lt;/p&gt;&lt;p&gt;Erstellt mit Qt %2, läuft unter Qt %3.&lt;/p&gt;&lt;p&gt;Freie Software unter der GNU General Public License, Version 3 oder (nach Ihrer Wahl) jeder späteren Version; sie wird ohne jede Gewährleistung bereitgestellt.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>Looking for servos on %1…</source>
        <translation>Suche nach Servos an %1…</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <source>Auto-detection</source>
        <translation>Automatische Erkennung</translation>
    </message>
    <message>
        <source>&amp;Reset layout</source>
        <translation>Layout &amp;zurücksetzen</translation>
    </message>
    <message>
        <source>&amp;Keyboard shortcuts</source>
        <translation>&amp;Tastenkürzel</translation>
    </message>
    <message>
        <source>&amp;Recent profiles</source>
        <translation>&amp;Zuletzt verwendete Profile</translation>
    </message>
    <message>
        <source>No profile opened or saved yet</source>
        <translation>Noch kein Profil geöffnet oder gespeichert</translation>
    </message>
    <message>
        <source>Pac&amp;ket window…</source>
        <translation>Pa&amp;ketfenster…</translation>
    </message>
    <message>
        <source>Wait until the port being probed answers, or Disconnect.</source>
        <translation>Warten Sie, bis der geprüfte Anschluss antwortet, oder trennen Sie die Verbindung.</translation>
    </message>
    <message>
        <source>&lt;p&gt;Home: &lt;a href=&quot;%1&quot;&gt;%1&lt;/a&gt;&lt;/p&gt;</source>
        <translation>&lt;p&gt;Website: &lt;a href=&quot;%1&quot;&gt;%1&lt;/a&gt;&lt;/p&gt;</translation>
    </message>
    <message>
        <source>Record and &amp;replay…</source>
        <translation>Aufzeichnen und &amp;wiedergeben…</translation>
    </message>
    <message>
        <source>Record joints moved by hand and play the motion back</source>
        <translation>Von Hand bewegte Gelenke aufzeichnen und die Bewegung wiedergeben</translation>
    </message>
    <message>
        <source>Shared bus, servo %1: %2</source>
        <translation>Geteilter Bus, Servo %1: %2</translation>
    </message>
    <message>
        <source>Sharing the bus: the other program opens %1.</source>
        <translation>Bus wird geteilt: Das andere Programm öffnet %1.</translation>
    </message>
    <message>
        <source>The bus is not shared.</source>
        <translation>Der Bus wird nicht geteilt.</translation>
    </message>
    <message>
        <source>Share this &amp;bus…</source>
        <translation>Diesen &amp;Bus teilen…</translation>
    </message>
    <message>
        <source>Give another program a port of its own on this Feetech bus and watch its traffic</source>
        <translation>Einem anderen Programm einen eigenen Port an diesem Feetech-Bus geben und seinen Datenverkehr beobachten</translation>
    </message>
    <message>
        <source>Re&amp;place a motor…</source>
        <translation>Motor &amp;ersetzen…</translation>
    </message>
    <message>
        <source>Set up a new servo as one joint of an arm and calibrate that joint alone into the arm&apos;s LeRobot file</source>
        <translation>Ein neues Servo als Gelenk eines Arms einrichten, nur dieses Gelenk kalibrieren und es in die LeRobot-Datei des Arms übernehmen</translation>
    </message>
    <message>
        <source>&amp;Teleoperate…</source>
        <translation>&amp;Teleoperation…</translation>
    </message>
    <message>
        <source>Move this arm with a leader arm on another port</source>
        <translation>Diesen Arm mit einem Führungsarm an einem anderen Anschluss bewegen</translation>
    </message>
    <message>
        <source>Close the calibration wizard before setting up motors: a set-up changes the servos&apos; IDs and settings.</source>
        <translation>Schließen Sie den Kalibrierassistenten, bevor Sie Motoren einrichten: Eine Einrichtung ändert die IDs und Einstellungen der Servos.</translation>
    </message>
    <message>
        <source>Ask skipped &amp;questions again</source>
        <translation>Übersprungene &amp;Fragen wieder stellen</translation>
    </message>
    <message>
        <source>ServoBench asks again before anything moves.</source>
        <translation>ServoBench fragt wieder nach, bevor sich etwas bewegt.</translation>
    </message>
    <message>
        <source>The questions you ticked &quot;Don&apos;t ask again&quot; on are asked again</source>
        <translation>Fragen, bei denen Sie „Nicht mehr fragen“ angehakt haben, werden wieder gestellt</translation>
    </message>
    <message>
        <source> · stream missed %1</source>
        <translation> · Datenstrom verpasst %1</translation>
    </message>
    <message>
        <source>the simulated leader arm is not running</source>
        <translation>der simulierte Führungsarm läuft nicht</translation>
    </message>
    <message>
        <source>the simulated leader arm has no joints</source>
        <translation>der simulierte Führungsarm hat keine Gelenke</translation>
    </message>
</context>
<context>
    <name>MemoryTablePage</name>
    <message>
        <source>Filter registers</source>
        <translation>Register filtern</translation>
    </message>
    <message>
        <source>Refresh RAM live</source>
        <translation>RAM live aktualisieren</translation>
    </message>
    <message>
        <source>Read the RAM registers (present position, load, voltage…) several times a second while this table is shown</source>
        <translation>Die RAM-Register (aktuelle Position, Last, Spannung…) mehrmals pro Sekunde lesen, solange diese Tabelle angezeigt wird</translation>
    </message>
    <message>
        <source>No servo chosen: scan the bus, then choose a servo in the tree; every register of its memory table shows here.</source>
        <translation>Kein Servo gewählt: Scannen Sie den Bus und wählen Sie dann ein Servo im Baum; jedes Register seiner Speichertabelle erscheint hier.</translation>
    </message>
    <message>
        <source>Read</source>
        <translation>Lesen</translation>
    </message>
    <message>
        <source>Read every register of the servo</source>
        <translation>Jedes Register des Servos lesen</translation>
    </message>
    <message>
        <source>Revert</source>
        <translation>Verwerfen</translation>
    </message>
    <message>
        <source>Drop every edit</source>
        <translation>Alle Änderungen verwerfen</translation>
    </message>
    <message>
        <source>Apply</source>
        <translation>Übernehmen</translation>
    </message>
    <message>
        <source>Write the edited registers, then read them back</source>
        <translation>Die geänderten Register schreiben und dann zurücklesen</translation>
    </message>
</context>
<context>
    <name>MonitorPage</name>
    <message>
        <source>Servos</source>
        <translation>Servos</translation>
    </message>
    <message>
        <source>Plot</source>
        <translation>Diagramm</translation>
    </message>
    <message>
        <source>Plot the %1 in %2</source>
        <translation>%1 in %2 darstellen</translation>
    </message>
    <message>
        <source>Stream</source>
        <translation>Stream</translation>
    </message>
    <message>
        <source>Samples per second for each servo</source>
        <translation>Messwerte pro Sekunde für jedes Servo</translation>
    </message>
    <message>
        <source>%1 Hz</source>
        <translation>%1 Hz</translation>
    </message>
    <message>
        <source>As fast as the bus allows</source>
        <translation>So schnell der Bus erlaubt</translation>
    </message>
    <message>
        <source>Rate:</source>
        <translation>Rate:</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>Start</translation>
    </message>
    <message>
        <source>Start or stop streaming the ticked servos&apos; feedback</source>
        <translation>Streaming der Rückmeldungen der angehakten Servos starten oder stoppen</translation>
    </message>
    <message>
        <source>View</source>
        <translation>Ansicht</translation>
    </message>
    <message>
        <source>How many seconds of history the plot shows</source>
        <translation>Wie viele Sekunden Verlauf das Diagramm zeigt</translation>
    </message>
    <message>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <source>Window:</source>
        <translation>Fenster:</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>Pause</translation>
    </message>
    <message>
        <source>Freeze the plot; samples are still received and recorded</source>
        <translation>Diagramm einfrieren; Messwerte werden weiter empfangen und aufgezeichnet</translation>
    </message>
    <message>
        <source>Reset zoom</source>
        <translation>Zoom zurücksetzen</translation>
    </message>
    <message>
        <source>Back to the live view over the whole window</source>
        <translation>Zurück zur Live-Ansicht über das ganze Fenster</translation>
    </message>
    <message>
        <source>Export PNG…</source>
        <translation>PNG exportieren…</translation>
    </message>
    <message>
        <source>Save the charts as they are shown as one PNG image</source>
        <translation>Die Diagramme wie angezeigt als ein PNG-Bild speichern</translation>
    </message>
    <message>
        <source>There is no bus to monitor.</source>
        <translation>Es gibt keinen Bus zum Überwachen.</translation>
    </message>
    <message>
        <source>Tick at least one servo to monitor.</source>
        <translation>Haken Sie mindestens ein Servo zum Überwachen an.</translation>
    </message>
    <message>
        <source>Monitoring did not start: %1</source>
        <translation>Überwachung wurde nicht gestartet: %1</translation>
    </message>
    <message>
        <source>Plot saved to %1.</source>
        <translation>Diagramm in %1 gespeichert.</translation>
    </message>
    <message>
        <source>Stopped</source>
        <translation>Gestoppt</translation>
    </message>
    <message>
        <source>Recording stopped: the bus was disconnected.</source>
        <translation>Aufzeichnung gestoppt: Die Verbindung zum Bus wurde getrennt.</translation>
    </message>
    <message>
        <source>Export plot</source>
        <translation>Diagramm exportieren</translation>
    </message>
    <message>
        <source>PNG images (*.png)</source>
        <translation>PNG-Bilder (*.png)</translation>
    </message>
    <message>
        <source>Monitoring stopped: no servo is ticked.</source>
        <translation>Überwachung gestoppt: Kein Servo ist angehakt.</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Stopp</translation>
    </message>
    <message>
        <source>Resume</source>
        <translation>Fortsetzen</translation>
    </message>
    <message>
        <source> · plot paused (samples are still received)</source>
        <translation> · Diagramm pausiert (Messwerte werden weiter empfangen)</translation>
    </message>
    <message>
        <source>Streaming · %1 cycles/s · %2 samples/s · %3 missed · %4 late</source>
        <translation>Streaming · %1 Zyklen/s · %2 Messwerte/s · %3 verpasst · %4 verspätet</translation>
    </message>
    <message>
        <source>Shared bus · showing the other program&apos;s reads, none of ServoBench&apos;s own</source>
        <translation>Geteilter Bus · zeigt die Lesevorgänge des anderen Programms, keine eigenen von ServoBench</translation>
    </message>
    <message>
        <source>The scan found no servo: monitoring stays stopped.</source>
        <translation>Der Scan fand kein Servo: Die Überwachung bleibt angehalten.</translation>
    </message>
    <message>
        <source>Monitoring again, after the scan.</source>
        <translation>Nach dem Scan wird wieder überwacht.</translation>
    </message>
    <message>
        <source>The Monitor could not start again after the scan: %1</source>
        <translation>Die Überwachung konnte nach dem Scan nicht wieder starten: %1</translation>
    </message>
    <message>
        <source>Monitoring paused while the bus is scanned; it starts again with the servos found.</source>
        <translation>Überwachung angehalten, während der Bus gescannt wird; sie startet danach mit den gefundenen Servos wieder.</translation>
    </message>
</context>
<context>
    <name>MonitorReadouts</name>
    <message>
        <source>Servo</source>
        <translation>Servo</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>Moving</source>
        <translation>Bewegt sich</translation>
    </message>
    <message>
        <source>Status</source>
        <translation>Status</translation>
    </message>
    <message>
        <source>Samples/s</source>
        <translation>Messwerte/s</translation>
    </message>
    <message>
        <source>Missed</source>
        <translation>Verpasst</translation>
    </message>
    <message>
        <source>State</source>
        <translation>Zustand</translation>
    </message>
    <message>
        <source>The servo&apos;s protection bits that tripped (register 65)</source>
        <translation>Die ausgelösten Schutzbits des Servos (Register 65)</translation>
    </message>
    <message>
        <source>Cycles in which the servo was asked and did not answer</source>
        <translation>Zyklen, in denen das Servo abgefragt wurde und nicht antwortete</translation>
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
        <translation>ja</translation>
    </message>
    <message>
        <source>no</source>
        <translation>nein</translation>
    </message>
    <message>
        <source>Not answering</source>
        <translation>Antwortet nicht</translation>
    </message>
    <message>
        <source>Stopped</source>
        <translation>Gestoppt</translation>
    </message>
    <message>
        <source>Waiting</source>
        <translation>Wartet</translation>
    </message>
    <message>
        <source>OK</source>
        <translation>OK</translation>
    </message>
    <message>
        <source>ID %1 at %2</source>
        <translation>ID %1 bei %2</translation>
    </message>
    <message>
        <source>none</source>
        <translation>keine</translation>
    </message>
</context>
<context>
    <name>MonitorRecording</name>
    <message>
        <source>Recording</source>
        <translation>Aufzeichnung</translation>
    </message>
    <message>
        <source>Record CSV…</source>
        <translation>CSV aufzeichnen…</translation>
    </message>
    <message>
        <source>Write every sample of the ticked servos to a CSV file</source>
        <translation>Jeden Messwert der angehakten Servos in eine CSV-Datei schreiben</translation>
    </message>
    <message numerus="yes">
        <source>%Ln row(s) saved to %1.</source>
        <translation>
            <numerusform>%Ln Zeile in %1 gespeichert.</numerusform>
            <numerusform>%Ln Zeilen in %1 gespeichert.</numerusform>
        </translation>
    </message>
    <message>
        <source>Record telemetry</source>
        <translation>Telemetrie aufzeichnen</translation>
    </message>
    <message>
        <source>CSV files (*.csv)</source>
        <translation>CSV-Dateien (*.csv)</translation>
    </message>
    <message>
        <source>Not recording.</source>
        <translation>Keine Aufzeichnung.</translation>
    </message>
    <message numerus="yes">
        <source>Recording to %1: %Ln row(s).</source>
        <translation>
            <numerusform>Aufzeichnung in %1: %Ln Zeile.</numerusform>
            <numerusform>Aufzeichnung in %1: %Ln Zeilen.</numerusform>
        </translation>
    </message>
    <message>
        <source>Stop recording</source>
        <translation>Aufzeichnung stoppen</translation>
    </message>
    <message numerus="yes">
        <source>Recording to %1 failed after %Ln row(s): %2</source>
        <translation>
            <numerusform>Aufzeichnung in %1 nach %Ln Zeile fehlgeschlagen: %2</numerusform>
            <numerusform>Aufzeichnung in %1 nach %Ln Zeilen fehlgeschlagen: %2</numerusform>
        </translation>
    </message>
    <message>
        <source>Recording failed.</source>
        <translation>Aufzeichnung fehlgeschlagen.</translation>
    </message>
</context>
<context>
    <name>MonitorServoList</name>
    <message>
        <source>The servos to stream; ticking or unticking one while streaming restarts the stream</source>
        <translation>Die zu streamenden Servos; An- oder Abhaken eines Servos während des Streamings startet den Stream neu</translation>
    </message>
    <message>
        <source>unknown model</source>
        <translation>unbekanntes Modell</translation>
    </message>
    <message>
        <source>Unknown model: its feedback cannot be decoded</source>
        <translation>Unbekanntes Modell: Seine Rückmeldungen können nicht dekodiert werden</translation>
    </message>
    <message>
        <source>Scan the bus to find servos.</source>
        <translation>Scannen Sie den Bus, um Servos zu finden.</translation>
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
        <translation>Servo %1</translation>
    </message>
    <message>
        <source>%1 (servo %2)</source>
        <translation>%1 (Servo %2)</translation>
    </message>
    <message>
        <source>the file is empty: a recording starts with a header line (time_s and one column per joint)</source>
        <translation>die Datei ist leer: Eine Aufzeichnung beginnt mit einer Kopfzeile (time_s und eine Spalte pro Gelenk)</translation>
    </message>
    <message>
        <source>the first column of the header is &quot;%1&quot;, not time_s: this is not a motion recording</source>
        <translation>die erste Spalte der Kopfzeile ist &quot;%1&quot;, nicht time_s: Dies ist keine Bewegungsaufzeichnung</translation>
    </message>
    <message>
        <source>column &quot;%1&quot; names no servo: a joint&apos;s column is id_N or NAME@N, N its servo&apos;s ID (0 to 253)</source>
        <translation>Spalte &quot;%1&quot; nennt kein Servo: Die Spalte eines Gelenks heißt id_N oder NAME@N, wobei N die ID seines Servos ist (0 bis 253)</translation>
    </message>
    <message>
        <source>servo %1 has two columns</source>
        <translation>Servo %1 hat zwei Spalten</translation>
    </message>
    <message>
        <source>the header names no joint after time_s</source>
        <translation>die Kopfzeile nennt nach time_s kein Gelenk</translation>
    </message>
    <message>
        <source>line %1</source>
        <translation>Zeile %1</translation>
    </message>
    <message>
        <source>line %1 has %2 cells where the header has %3</source>
        <translation>Zeile %1 hat %2 Zellen, die Kopfzeile aber %3</translation>
    </message>
    <message>
        <source>line %1: the time &quot;%2&quot; is not a number of seconds from 0</source>
        <translation>Zeile %1: die Zeit &quot;%2&quot; ist keine Anzahl Sekunden ab 0</translation>
    </message>
    <message>
        <source>line %1: the time goes back, from %2 s to %3 s</source>
        <translation>Zeile %1: die Zeit läuft rückwärts, von %2 s auf %3 s</translation>
    </message>
    <message>
        <source>line %1: &quot;%2&quot; is no position of %3 (a number of steps)</source>
        <translation>Zeile %1: &quot;%2&quot; ist keine Position von %3 (eine Anzahl Schritte)</translation>
    </message>
    <message>
        <source>the recording has a header but no frame</source>
        <translation>die Aufzeichnung hat eine Kopfzeile, aber keinen Frame</translation>
    </message>
    <message>
        <source>the file is too large for a motion recording</source>
        <translation>die Datei ist zu groß für eine Bewegungsaufzeichnung</translation>
    </message>
    <message>
        <source>nothing was recorded</source>
        <translation>es wurde nichts aufgezeichnet</translation>
    </message>
</context>
<context>
    <name>MotionTestPanel</name>
    <message>
        <source>Step and sweep tests</source>
        <translation>Sprung- und Schwenktests</translation>
    </message>
    <message>
        <source>Goal speed of the test moves (0: the servo&apos;s maximum).</source>
        <translation>Zielgeschwindigkeit der Testbewegungen (0: Maximum des Servos).</translation>
    </message>
    <message>
        <source>Acceleration of the test moves (0: the servo&apos;s maximum).</source>
        <translation>Beschleunigung der Testbewegungen (0: Maximum des Servos).</translation>
    </message>
    <message>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <source>Step test: how long the response is recorded after the step.</source>
        <translation>Sprungtest: wie lange die Antwort nach dem Sprung aufgezeichnet wird.</translation>
    </message>
    <message>
        <source>Sweep: moves between the two positions, to and back counting as two.</source>
        <translation>Schwenken: Fahrten zwischen den beiden Positionen, hin und zurück zählt als zwei.</translation>
    </message>
    <message>
        <source>From</source>
        <translation>Von</translation>
    </message>
    <message>
        <source>To</source>
        <translation>Nach</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>Geschwindigkeit</translation>
    </message>
    <message>
        <source>Acceleration</source>
        <translation>Beschleunigung</translation>
    </message>
    <message>
        <source>Record</source>
        <translation>Aufzeichnen</translation>
    </message>
    <message>
        <source>Sweep legs</source>
        <translation>Schwenkfahrten</translation>
    </message>
    <message>
        <source>Step test…</source>
        <translation>Sprungtest…</translation>
    </message>
    <message>
        <source>Move to From, then step to To and measure the response.</source>
        <translation>Zu „Von“ fahren, dann auf „Nach“ springen und die Antwort messen.</translation>
    </message>
    <message>
        <source>Sweep…</source>
        <translation>Schwenken…</translation>
    </message>
    <message>
        <source>Move back and forth between From and To.</source>
        <translation>Zwischen „Von“ und „Nach“ hin und her fahren.</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Stopp</translation>
    </message>
    <message>
        <source>Stop the running test; the servo holds where it is.</source>
        <translation>Den laufenden Test stoppen; das Servo hält an seiner Stelle.</translation>
    </message>
    <message>
        <source>From 10 % to 90 % of the step.</source>
        <translation>Von 10 % bis 90 % des Sprungs.</translation>
    </message>
    <message>
        <source>How far the peak went beyond the target, as a share of the step.</source>
        <translation>Wie weit die Spitze über das Ziel hinausging, als Anteil des Sprungs.</translation>
    </message>
    <message>
        <source>From the step command until the position stays within the settling band.</source>
        <translation>Vom Sprungbefehl, bis die Position im Toleranzband bleibt.</translation>
    </message>
    <message>
        <source>Target minus the mean position over the last tenth of the recording.</source>
        <translation>Ziel minus mittlere Position über das letzte Zehntel der Aufzeichnung.</translation>
    </message>
    <message>
        <source>2 % of the step, at least 2 steps, either side of the target.</source>
        <translation>2 % des Sprungs, mindestens 2 Schritte, beiderseits des Ziels.</translation>
    </message>
    <message>
        <source>Rise time</source>
        <translation>Anstiegszeit</translation>
    </message>
    <message>
        <source>Overshoot</source>
        <translation>Überschwingen</translation>
    </message>
    <message>
        <source>Settling time</source>
        <translation>Einschwingzeit</translation>
    </message>
    <message>
        <source>Steady-state error</source>
        <translation>Bleibende Regelabweichung</translation>
    </message>
    <message>
        <source>Settling band</source>
        <translation>Toleranzband</translation>
    </message>
    <message>
        <source>Target</source>
        <translation>Ziel</translation>
    </message>
    <message>
        <source>Time since the step (ms)</source>
        <translation>Zeit seit dem Sprung (ms)</translation>
    </message>
    <message>
        <source>The horn of %1 will move to %2, then step to %3 and hold there.</source>
        <translation>Das Servohorn von %1 fährt zu %2, springt dann auf %3 und hält dort.</translation>
    </message>
    <message>
        <source>The horn of %1 will move to %2, then sweep %3 times between %2 and %4.</source>
        <translation>Das Servohorn von %1 fährt zu %2 und schwenkt dann %3 Mal zwischen %2 und %4.</translation>
    </message>
    <message>
        <source>The servo will move</source>
        <translation>Das Servo wird sich bewegen</translation>
    </message>
    <message>
        <source>Keep hands, cables and other parts clear of the horn, and detach any load it could damage or be damaged by. Stop or All torque off halts it.</source>
        <translation>Halten Sie Hände, Kabel und andere Teile vom Servohorn fern und entfernen Sie jede Last, die es beschädigen oder von ihm beschädigt werden könnte. „Stopp“ oder „Alle Drehmomente aus“ hält es an.</translation>
    </message>
    <message>
        <source>Move the servo</source>
        <translation>Servo bewegen</translation>
    </message>
    <message>
        <source>Step test done: %1 samples over %2 s.</source>
        <translation>Sprungtest fertig: %1 Messwerte über %2 s.</translation>
    </message>
    <message>
        <source>Sweep done: %1 of %2 legs reached their goal.</source>
        <translation>Schwenken fertig: %1 von %2 Fahrten haben ihr Ziel erreicht.</translation>
    </message>
    <message>
        <source>A leg took %1 ms on average.</source>
        <translation>Eine Fahrt dauerte im Mittel %1 ms.</translation>
    </message>
    <message>
        <source>Stopped: %1</source>
        <translation>Gestoppt: %1</translation>
    </message>
    <message>
        <source>No test run yet for this servo.</source>
        <translation>Für dieses Servo wurde noch kein Test ausgeführt.</translation>
    </message>
    <message>
        <source>%1 ms</source>
        <translation>%1 ms</translation>
    </message>
    <message>
        <source>did not reach 90 % of the step</source>
        <translation>hat 90 % des Sprungs nicht erreicht</translation>
    </message>
    <message>
        <source>%1 %</source>
        <translation>%1 %</translation>
    </message>
    <message>
        <source>did not settle within %1 s</source>
        <translation>hat sich nicht innerhalb von %1 s eingeschwungen</translation>
    </message>
    <message>
        <source>%1 steps</source>
        <translation>%1 Schritte</translation>
    </message>
    <message>
        <source>± %1 steps</source>
        <translation>± %1 Schritte</translation>
    </message>
    <message>
        <source>Position (%1)</source>
        <translation>Position (%1)</translation>
    </message>
    <message>
        <source>Sweep ends</source>
        <translation>Enden des Schwenks</translation>
    </message>
</context>
<context>
    <name>MotionTestRefusal</name>
    <message>
        <source>A test is already running.</source>
        <translation>Es läuft bereits ein Test.</translation>
    </message>
    <message>
        <source>The bus is not connected.</source>
        <translation>Der Bus ist nicht verbunden.</translation>
    </message>
    <message>
        <source>No servo is selected.</source>
        <translation>Kein Servo ausgewählt.</translation>
    </message>
    <message>
        <source>Servo ID %1 is being identified; wait until it is back.</source>
        <translation>Servo-ID %1 wird gerade identifiziert; warten Sie, bis es wieder zurück ist.</translation>
    </message>
    <message>
        <source>This servo&apos;s model is unknown: ServoBench does not move it.</source>
        <translation>Das Modell dieses Servos ist unbekannt: ServoBench bewegt es nicht.</translation>
    </message>
    <message>
        <source>This servo has no goal position register.</source>
        <translation>Dieses Servo hat kein Zielpositionsregister.</translation>
    </message>
    <message>
        <source>Servo ID %1 is not in position mode: set its operating mode to position first.</source>
        <translation>Servo-ID %1 ist nicht im Positionsmodus: Stellen Sie seinen Betriebsmodus zuerst auf Position.</translation>
    </message>
    <message>
        <source>the servo&apos;s angle limits</source>
        <translation>der Winkelgrenzen des Servos</translation>
    </message>
    <message>
        <source>the goal position range</source>
        <translation>des Zielpositionsbereichs</translation>
    </message>
    <message>
        <source>From (%1) and to (%2) must lie within %3, %4 to %5 steps.</source>
        <translation>Von (%1) und Nach (%2) müssen innerhalb %3 liegen, %4 bis %5 Schritte.</translation>
    </message>
    <message>
        <source>From and to must be more than %1 steps apart.</source>
        <translation>Von und Nach müssen mehr als %1 Schritte auseinanderliegen.</translation>
    </message>
    <message>
        <source>%1 must lie between %2 and %3.</source>
        <translation>%1 muss zwischen %2 und %3 liegen.</translation>
    </message>
    <message>
        <source>The recording must last more than 0 and at most %1 seconds.</source>
        <translation>Die Aufzeichnung muss länger als 0 und höchstens %1 Sekunden dauern.</translation>
    </message>
    <message>
        <source>A sweep has 1 to %1 legs.</source>
        <translation>Ein Schwenk hat 1 bis %1 Fahrten.</translation>
    </message>
    <message>
        <source>%1 is no longer on the bus.</source>
        <translation>%1 ist nicht mehr am Bus.</translation>
    </message>
    <message>
        <source>Servo ID %1</source>
        <translation>Servo-ID %1</translation>
    </message>
</context>
<context>
    <name>MotorFinder</name>
    <message>
        <source>this motor</source>
        <translation>dieser Motor</translation>
    </message>
    <message>
        <source>Stopped; nothing was written.</source>
        <translation>Gestoppt; es wurde nichts geschrieben.</translation>
    </message>
    <message>
        <source>ID %1 at %2</source>
        <translation>ID %1 bei %2</translation>
    </message>
    <message>
        <source>several at %1 whose replies collide</source>
        <translation>mehrere bei %1, deren Antworten kollidieren</translation>
    </message>
    <message>
        <source>No servo answers at any rate: check the power and the cable, and connect the next servo.</source>
        <translation>Bei keiner Baudrate antwortet ein Servo: Prüfen Sie Stromversorgung und Kabel und schließen Sie das nächste Servo an.</translation>
    </message>
    <message>
        <source>Two servos answer at ID %1; connect them one at a time.</source>
        <translation>Zwei Servos antworten unter ID %1; schließen Sie sie einzeln an.</translation>
    </message>
    <message>
        <source>At least %1 servos answer (%2): connect one servo at a time.</source>
        <translation>Mindestens %1 Servos antworten (%2): Schließen Sie jeweils nur ein Servo an.</translation>
    </message>
    <message>
        <source>%1 servos answer (%2): connect one servo at a time.</source>
        <translation>%1 Servos antworten (%2): Schließen Sie jeweils nur ein Servo an.</translation>
    </message>
    <message>
        <source>A reply at %1 looked like servo %2, which then did not answer: probably several servos whose replies collide. Connect one servo at a time.</source>
        <translation>Eine Antwort bei %1 sah nach Servo %2 aus, das dann nicht antwortete: vermutlich mehrere Servos, deren Antworten kollidieren. Schließen Sie jeweils nur ein Servo an.</translation>
    </message>
    <message>
        <source>%1 stopped answering: check the power and the cable, then look again.</source>
        <translation>%1 antwortet nicht mehr: Prüfen Sie Stromversorgung und Kabel und suchen Sie dann erneut.</translation>
    </message>
    <message>
        <source>Found %1, model %2 (model number %3), which ServoBench has no register table for; nothing was written.</source>
        <translation>%1 gefunden, Modell %2 (Modellnummer %3), für das ServoBench keine Registertabelle hat; es wurde nichts geschrieben.</translation>
    </message>
    <message>
        <source>Found %1, model %2, but %3 needs model %4. Nothing was written: connect a servo of model %4.</source>
        <translation>%1 gefunden, Modell %2, aber %3 benötigt Modell %4. Es wurde nichts geschrieben: Schließen Sie ein Servo des Modells %4 an.</translation>
    </message>
    <message>
        <source>Found one servo: %1, model %2.</source>
        <translation>Ein Servo gefunden: %1, Modell %2.</translation>
    </message>
</context>
<context>
    <name>MotorSetup</name>
    <message>
        <source>ID %1 answers as model %2, not %3.</source>
        <translation>ID %1 antwortet als Modell %2, nicht %3.</translation>
    </message>
    <message>
        <source>ID %1 answers, but %2.</source>
        <translation>ID %1 antwortet, aber %2.</translation>
    </message>
    <message>
        <source>ID %1 is out of range (0 to %2).</source>
        <translation>ID %1 liegt außerhalb des Bereichs (0 bis %2).</translation>
    </message>
    <message>
        <source>%1 is not a Feetech baud rate.</source>
        <translation>%1 ist keine Feetech-Baudrate.</translation>
    </message>
    <message>
        <source>Looking for the servo at every baud rate…</source>
        <translation>Servo wird bei jeder Baudrate gesucht…</translation>
    </message>
    <message>
        <source>Model %1 cannot run at %2; nothing was written.</source>
        <translation>Modell %1 kann nicht mit %2 laufen; es wurde nichts geschrieben.</translation>
    </message>
    <message>
        <source>The settings do not suit this servo (%1); nothing was written.</source>
        <translation>Die Einstellungen passen nicht zu diesem Servo (%1); es wurde nichts geschrieben.</translation>
    </message>
    <message>
        <source>Stopped before %1. The servo answers as %2; nothing more was written.</source>
        <translation>Gestoppt vor %1. Das Servo antwortet als %2; es wurde nichts weiter geschrieben.</translation>
    </message>
    <message>
        <source>giving it ID %1</source>
        <translation>dem Vergeben von ID %1</translation>
    </message>
    <message>
        <source>Giving it ID %1…</source>
        <translation>ID %1 wird vergeben…</translation>
    </message>
    <message>
        <source>It already has ID %1.</source>
        <translation>Es hat bereits ID %1.</translation>
    </message>
    <message>
        <source>moving it to %1</source>
        <translation>dem Umstellen auf %1</translation>
    </message>
    <message>
        <source>Moving it to %1…</source>
        <translation>Umstellen auf %1…</translation>
    </message>
    <message>
        <source>It already runs at %1.</source>
        <translation>Es läuft bereits mit %1.</translation>
    </message>
    <message>
        <source>writing its settings</source>
        <translation>dem Schreiben seiner Einstellungen</translation>
    </message>
    <message numerus="yes">
        <source>Writing %n setting(s)…</source>
        <translation>
            <numerusform>%n Einstellung wird geschrieben…</numerusform>
            <numerusform>%n Einstellungen werden geschrieben…</numerusform>
        </translation>
    </message>
    <message>
        <source>It already holds every setting.</source>
        <translation>Es hat bereits alle Einstellungen.</translation>
    </message>
    <message>
        <source>Wrote %1 with the EEPROM unlocked, then locked it again.</source>
        <translation>%1 bei entsperrtem EEPROM geschrieben, danach wieder gesperrt.</translation>
    </message>
    <message>
        <source>Wrote %1.</source>
        <translation>%1 geschrieben.</translation>
    </message>
    <message>
        <source>Reading the settings back…</source>
        <translation>Einstellungen werden zurückgelesen…</translation>
    </message>
    <message>
        <source>%1 should be %2 but reads %3</source>
        <translation>%1 sollte %2 sein, ist aber %3</translation>
    </message>
    <message>
        <source>nothing</source>
        <translation>nichts</translation>
    </message>
    <message>
        <source>Verification failed: %1.</source>
        <translation>Verifizierung fehlgeschlagen: %1.</translation>
    </message>
    <message numerus="yes">
        <source>Read back: %n setting(s) hold their values.</source>
        <translation>
            <numerusform>Zurückgelesen: %n Einstellung hat ihren Wert.</numerusform>
            <numerusform>Zurückgelesen: %n Einstellungen haben ihre Werte.</numerusform>
        </translation>
    </message>
    <message>
        <source>The servo</source>
        <translation>Das Servo</translation>
    </message>
    <message numerus="yes">
        <source>%1 is set up: %2, %n setting(s) verified.</source>
        <translation>
            <numerusform>%1 ist eingerichtet: %2, %n Einstellung verifiziert.</numerusform>
            <numerusform>%1 ist eingerichtet: %2, %n Einstellungen verifiziert.</numerusform>
        </translation>
    </message>
    <message>
        <source>Asking ID %1 at %2…</source>
        <translation>ID %1 bei %2 wird abgefragt…</translation>
    </message>
    <message>
        <source>%1 could not be read</source>
        <translation>%1 konnte nicht gelesen werden</translation>
    </message>
    <message>
        <source>%1 is %2, not %3</source>
        <translation>%1 ist %2, nicht %3</translation>
    </message>
    <message>
        <source>%1 could not be read back</source>
        <translation>%1 konnte nicht zurückgelesen werden</translation>
    </message>
    <message>
        <source>%1 reads %2, with bits 0x%3 still set</source>
        <translation>%1 ist %2, die Bits 0x%3 sind noch gesetzt</translation>
    </message>
    <message>
        <source>%1 is %2, with bits 0x%3 set</source>
        <translation>%1 ist %2, mit gesetzten Bits 0x%3</translation>
    </message>
</context>
<context>
    <name>MotorSetupFlow</name>
    <message>
        <source>set up earlier, but ID %1 does not answer now</source>
        <translation>zuvor eingerichtet, aber ID %1 antwortet jetzt nicht</translation>
    </message>
</context>
<context>
    <name>OverloadRecoveryDialog</name>
    <message>
        <source>Recover servo ID %1</source>
        <translation>Servo-ID %1 wiederherstellen</translation>
    </message>
    <message>
        <source>The overload protection of servo ID %1 tripped: its torque is off.

First free the horn (remove what blocks it). Then ServoBench switches its torque off and on again, with the goal at the present position so nothing moves, and reads the overload bit.</source>
        <translation>Der Überlastschutz von Servo-ID %1 hat ausgelöst: Sein Drehmoment ist aus.

Befreien Sie zuerst das Servohorn (entfernen Sie, was es blockiert). Dann schaltet ServoBench sein Drehmoment aus und wieder ein, mit dem Ziel auf der aktuellen Position, sodass sich nichts bewegt, und liest das Überlastbit.</translation>
    </message>
    <message>
        <source>Torque off and on</source>
        <translation>Drehmoment aus und ein</translation>
    </message>
    <message>
        <source>Servo ID %1 is no longer on the bus.</source>
        <translation>Servo-ID %1 ist nicht mehr am Bus.</translation>
    </message>
    <message>
        <source>Reading the status…</source>
        <translation>Status wird gelesen…</translation>
    </message>
    <message>
        <source>Torque off and on…</source>
        <translation>Drehmoment aus und ein…</translation>
    </message>
    <message>
        <source>Check again</source>
        <translation>Erneut prüfen</translation>
    </message>
    <message>
        <source>The recovery failed: %1</source>
        <translation>Die Wiederherstellung ist fehlgeschlagen: %1</translation>
    </message>
</context>
<context>
    <name>PacketLogDock</name>
    <message>
        <source>Packet log</source>
        <translation>Paketprotokoll</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>Pause</translation>
    </message>
    <message>
        <source>Freeze the log to read it; frames arriving meanwhile are kept and appear when you resume</source>
        <translation>Protokoll zum Lesen einfrieren; währenddessen eintreffende Frames werden behalten und erscheinen beim Fortsetzen</translation>
    </message>
    <message>
        <source>Clear</source>
        <translation>Leeren</translation>
    </message>
    <message>
        <source>Remove every frame from the log and reset the counts</source>
        <translation>Alle Frames aus dem Protokoll entfernen und die Zähler zurücksetzen</translation>
    </message>
    <message>
        <source>Export…</source>
        <translation>Exportieren…</translation>
    </message>
    <message>
        <source>Save the frames shown to a tab-separated text file</source>
        <translation>Die angezeigten Frames in eine tabulatorgetrennte Textdatei speichern</translation>
    </message>
    <message>
        <source>Errors only</source>
        <translation>Nur Fehler</translation>
    </message>
    <message>
        <source>Show only frames with an error (bad checksum, timeout, unexpected bytes)</source>
        <translation>Nur Frames mit einem Fehler anzeigen (falsche Prüfsumme, Zeitüberschreitung, unerwartete Bytes)</translation>
    </message>
    <message>
        <source>Direction</source>
        <translation>Richtung</translation>
    </message>
    <message>
        <source>→ out</source>
        <translation>→ gesendet</translation>
    </message>
    <message>
        <source>%1, %2</source>
        <translation>%1, %2</translation>
    </message>
    <message numerus="yes">
        <source>%n frame(s)</source>
        <translation>
            <numerusform>%n Frame</numerusform>
            <numerusform>%n Frames</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n error(s)</source>
        <translation>
            <numerusform>%n Fehler</numerusform>
            <numerusform>%n Fehler</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 (paused)</source>
        <translation>%1 (pausiert)</translation>
    </message>
    <message>
        <source>New frames are kept while paused and appear when you resume</source>
        <translation>Neue Frames werden während der Pause behalten und erscheinen beim Fortsetzen</translation>
    </message>
    <message>
        <source>Export packet log</source>
        <translation>Paketprotokoll exportieren</translation>
    </message>
    <message>
        <source>Tab-separated text (*.tsv *.txt);;All files (*)</source>
        <translation>Tabulatorgetrennter Text (*.tsv *.txt);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Open recording…</source>
        <translation>Aufzeichnung öffnen…</translation>
    </message>
    <message>
        <source>Show a shared bus&apos;s recording (Link &gt; Share this bus…) with the meaning of each frame</source>
        <translation>Die Aufzeichnung eines geteilten Busses (Verbindung &gt; Diesen Bus teilen…) mit der Bedeutung jedes Frames anzeigen</translation>
    </message>
    <message>
        <source>Open a shared bus recording</source>
        <translation>Aufzeichnung eines geteilten Busses öffnen</translation>
    </message>
    <message>
        <source>Share recordings (*.txt);;All files (*)</source>
        <translation>Freigabeaufzeichnungen (*.txt);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Open recording</source>
        <translation>Aufzeichnung öffnen</translation>
    </message>
    <message numerus="yes">
        <source>The log keeps the newest %n frame(s), errors longer; older ones were dropped</source>
        <translation>
            <numerusform>Das Protokoll behält den neuesten %n Frame, Fehler länger; ältere wurden verworfen</numerusform>
            <numerusform>Das Protokoll behält die neuesten %n Frames, Fehler länger; ältere wurden verworfen</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n older error(s) among them</source>
        <translation>
            <numerusform>darunter %n älterer Fehler</numerusform>
            <numerusform>darunter %n ältere Fehler</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>PacketSequence</name>
    <message>
        <source>not a ServoBench packet sequence (the document is not a JSON object)</source>
        <translation>keine ServoBench-Paketfolge (das Dokument ist kein JSON-Objekt)</translation>
    </message>
    <message>
        <source>not a ServoBench packet sequence (&quot;%1&quot; is not &quot;%2&quot;)</source>
        <translation>keine ServoBench-Paketfolge („%1“ ist nicht „%2“)</translation>
    </message>
    <message>
        <source>the packet sequence has format version %1 and was written by a newer ServoBench; this version reads format version %2 and older</source>
        <translation>die Paketfolge hat die Formatversion %1 und stammt von einem neueren ServoBench; diese Version liest Formatversion %2 und älter</translation>
    </message>
    <message>
        <source>It writes to the PTK servo, outside the verified write sequence of its settings page.</source>
        <translation>Er schreibt auf das PTK-Servo, außerhalb der geprüften Schreibfolge seiner Einstellungsseite.</translation>
    </message>
    <message>
        <source>every servo on the bus</source>
        <translation>jedes Servo am Bus</translation>
    </message>
    <message>
        <source>servo %1</source>
        <translation>Servo %1</translation>
    </message>
    <message>
        <source>It restores the factory values of %1 (its settings are lost).</source>
        <translation>Er stellt die Werkswerte von %1 wieder her (die Einstellungen gehen verloren).</translation>
    </message>
    <message>
        <source>It makes the present position the middle of %1 (written to EEPROM).</source>
        <translation>Er macht die aktuelle Position zur Mitte von %1 (ins EEPROM geschrieben).</translation>
    </message>
    <message>
        <source>It asks %1 to store its settings (an EEPROM write).</source>
        <translation>Er lässt %1 seine Einstellungen speichern (ein EEPROM-Schreibvorgang).</translation>
    </message>
    <message>
        <source>It writes %1 of %2, in EEPROM: the servo keeps it when powered off, and a wrong ID or baud rate makes it answer elsewhere.</source>
        <translation>Er schreibt %1 von %2 ins EEPROM: Das Servo behält es auch ohne Strom, und eine falsche ID oder Baudrate lässt es anderswo antworten.</translation>
    </message>
    <message>
        <source>too large to be a packet sequence</source>
        <translation>zu groß für eine Paketfolge</translation>
    </message>
    <message>
        <source>&quot;%1&quot; must be a list of frames</source>
        <translation>„%1“ muss eine Liste von Frames sein</translation>
    </message>
    <message>
        <source>more than %1 frames</source>
        <translation>mehr als %1 Frames</translation>
    </message>
    <message>
        <source>frame %1 is not an object of protocol, hex and baud</source>
        <translation>Frame %1 ist kein Objekt aus protocol, hex und baud</translation>
    </message>
    <message>
        <source>frame %1: its hex is not hexadecimal bytes</source>
        <translation>Frame %1: sein hex ist keine Folge hexadezimaler Bytes</translation>
    </message>
    <message>
        <source>frame %1: the protocol must be feetech or ptk</source>
        <translation>Frame %1: das Protokoll muss feetech oder ptk sein</translation>
    </message>
    <message>
        <source>frame %1 is not a whole %2 frame at a known rate</source>
        <translation>Frame %1 ist kein vollständiger %2-Frame mit bekannter Rate</translation>
    </message>
</context>
<context>
    <name>PacketSequenceFiles</name>
    <message>
        <source>The history is empty: there is nothing to save.</source>
        <translation>Der Verlauf ist leer: Es gibt nichts zu speichern.</translation>
    </message>
    <message>
        <source>Save packet sequence</source>
        <translation>Paketfolge speichern</translation>
    </message>
    <message>
        <source>ServoBench packet sequences (*.json)</source>
        <translation>ServoBench-Paketfolgen (*.json)</translation>
    </message>
    <message numerus="yes">
        <source>Saved %n frame(s).</source>
        <translation>
            <numerusform>%n Frame gespeichert.</numerusform>
            <numerusform>%n Frames gespeichert.</numerusform>
        </translation>
    </message>
    <message>
        <source>Load packet sequence</source>
        <translation>Paketfolge laden</translation>
    </message>
    <message>
        <source>Loaded into the history: select a frame and Resend, or Send all.</source>
        <translation>In den Verlauf geladen: Wählen Sie einen Frame und „Erneut senden“, oder „Alle senden“.</translation>
    </message>
</context>
<context>
    <name>PacketWindow</name>
    <message>
        <source>Packet window</source>
        <translation>Paketfenster</translation>
    </message>
    <message>
        <source>Send this frame?</source>
        <translation>Diesen Frame senden?</translation>
    </message>
    <message>
        <source>Send it?</source>
        <translation>Senden?</translation>
    </message>
    <message>
        <source>Feetech</source>
        <translation>Feetech</translation>
    </message>
    <message>
        <source>PTK</source>
        <translation>PTK</translation>
    </message>
    <message>
        <source>Send</source>
        <translation>Senden</translation>
    </message>
    <message>
        <source>Time</source>
        <translation>Zeit</translation>
    </message>
    <message>
        <source>Frame</source>
        <translation>Frame</translation>
    </message>
    <message>
        <source>Meaning</source>
        <translation>Bedeutung</translation>
    </message>
    <message>
        <source>Answer</source>
        <translation>Antwort</translation>
    </message>
    <message>
        <source>Resend</source>
        <translation>Erneut senden</translation>
    </message>
    <message>
        <source>Send all</source>
        <translation>Alle senden</translation>
    </message>
    <message>
        <source>Send every frame of the history again, oldest first</source>
        <translation>Alle Frames des Verlaufs erneut senden, den ältesten zuerst</translation>
    </message>
    <message>
        <source>Save sequence…</source>
        <translation>Folge speichern…</translation>
    </message>
    <message>
        <source>Load sequence…</source>
        <translation>Folge laden…</translation>
    </message>
    <message>
        <source>Clear</source>
        <translation>Leeren</translation>
    </message>
    <message>
        <source>History (double-click a frame to send it again):</source>
        <translation>Verlauf (Doppelklick auf einen Frame sendet ihn erneut):</translation>
    </message>
    <message>
        <source>The connection closed.</source>
        <translation>Die Verbindung wurde geschlossen.</translation>
    </message>
    <message>
        <source>PING</source>
        <translation>PING</translation>
    </message>
    <message>
        <source>READ</source>
        <translation>READ</translation>
    </message>
    <message>
        <source>WRITE</source>
        <translation>WRITE</translation>
    </message>
    <message>
        <source>REG WRITE</source>
        <translation>REG WRITE</translation>
    </message>
    <message>
        <source>ACTION</source>
        <translation>ACTION</translation>
    </message>
    <message>
        <source>SYNC READ</source>
        <translation>SYNC READ</translation>
    </message>
    <message>
        <source>SYNC WRITE</source>
        <translation>SYNC WRITE</translation>
    </message>
    <message>
        <source>RECOVERY (factory values)</source>
        <translation>RECOVERY (Werkswerte)</translation>
    </message>
    <message>
        <source>REBOOT</source>
        <translation>REBOOT</translation>
    </message>
    <message>
        <source>RESET (clear the status)</source>
        <translation>RESET (Status löschen)</translation>
    </message>
    <message>
        <source>CALIBRATE (middle)</source>
        <translation>CALIBRATE (Mitte)</translation>
    </message>
    <message>
        <source>Another code</source>
        <translation>Anderer Code</translation>
    </message>
    <message>
        <source>254 (0xFE) is the broadcast ID: every servo acts, none answers</source>
        <translation>254 (0xFE) ist die Broadcast-ID: Jedes Servo führt aus, keines antwortet</translation>
    </message>
    <message>
        <source>hex bytes, e.g. 00 08</source>
        <translation>Hex-Bytes, z. B. 00 08</translation>
    </message>
    <message>
        <source>e.g. 1,2,3 or 1-6</source>
        <translation>z. B. 1,2,3 oder 1-6</translation>
    </message>
    <message>
        <source>%L1 bps</source>
        <translation>%L1 bps</translation>
    </message>
    <message>
        <source>Instruction:</source>
        <translation>Befehl:</translation>
    </message>
    <message>
        <source>Code:</source>
        <translation>Code:</translation>
    </message>
    <message>
        <source>ID:</source>
        <translation>ID:</translation>
    </message>
    <message>
        <source>Address:</source>
        <translation>Adresse:</translation>
    </message>
    <message>
        <source>Length:</source>
        <translation>Länge:</translation>
    </message>
    <message>
        <source>Data:</source>
        <translation>Daten:</translation>
    </message>
    <message>
        <source>IDs:</source>
        <translation>IDs:</translation>
    </message>
    <message>
        <source>Baud rate:</source>
        <translation>Baudrate:</translation>
    </message>
    <message>
        <source>Query %1 (command %2)</source>
        <translation>Abfrage %1 (Befehl %2)</translation>
    </message>
    <message>
        <source>Write %1 (command %2)</source>
        <translation>Schreiben %1 (Befehl %2)</translation>
    </message>
    <message>
        <source>Another command</source>
        <translation>Anderer Befehl</translation>
    </message>
    <message>
        <source>Command:</source>
        <translation>Befehl:</translation>
    </message>
    <message>
        <source>First word:</source>
        <translation>Erstes Wort:</translation>
    </message>
    <message>
        <source>Second word:</source>
        <translation>Zweites Wort:</translation>
    </message>
    <message>
        <source>A query is answered with two words; the servo never acknowledges a write. PTK servos talk at 115200 baud.</source>
        <translation>Eine Abfrage wird mit zwei Wörtern beantwortet; ein Schreibvorgang wird vom Servo nie bestätigt. PTK-Servos sprechen mit 115200 Baud.</translation>
    </message>
    <message>
        <source>Data: %1</source>
        <translation>Daten: %1</translation>
    </message>
    <message>
        <source>Data: give the bytes to write.</source>
        <translation>Daten: Geben Sie die zu schreibenden Bytes an.</translation>
    </message>
    <message numerus="yes">
        <source>Data: %n byte(s) for each of the %1 servo(s), one after the other.</source>
        <translation>
            <numerusform>Daten: %n Byte für jedes der %1 Servos, eines nach dem anderen.</numerusform>
            <numerusform>Daten: %n Bytes für jedes der %1 Servos, eines nach dem anderen.</numerusform>
        </translation>
    </message>
    <message>
        <source>Data: none, or the 2-byte position to make the middle.</source>
        <translation>Daten: keine, oder die 2-Byte-Position, die zur Mitte werden soll.</translation>
    </message>
    <message>
        <source>The frame would be %1 bytes; a Feetech frame holds at most %2.</source>
        <translation>Der Frame wäre %1 Bytes lang; ein Feetech-Frame fasst höchstens %2.</translation>
    </message>
    <message>
        <source>The fields do not make a whole frame.</source>
        <translation>Die Felder ergeben keinen vollständigen Frame.</translation>
    </message>
    <message>
        <source>Connect to a Feetech bus first</source>
        <translation>Zuerst mit einem Feetech-Bus verbinden</translation>
    </message>
    <message>
        <source>Connect to a PTK servo first</source>
        <translation>Zuerst mit einem PTK-Servo verbinden</translation>
    </message>
    <message>
        <source>Wait until the frames on their way are answered.</source>
        <translation>Warten Sie, bis die gesendeten Frames beantwortet sind.</translation>
    </message>
    <message>
        <source>There is nothing to send.</source>
        <translation>Es gibt nichts zu senden.</translation>
    </message>
    <message>
        <source>Connect to a Feetech bus first.</source>
        <translation>Verbinden Sie zuerst mit einem Feetech-Bus.</translation>
    </message>
    <message>
        <source>Connect to a PTK servo first.</source>
        <translation>Verbinden Sie zuerst mit einem PTK-Servo.</translation>
    </message>
    <message>
        <source>Nothing was sent.</source>
        <translation>Es wurde nichts gesendet.</translation>
    </message>
    <message>
        <source>sending…</source>
        <translation>wird gesendet…</translation>
    </message>
    <message>
        <source>Choose a frame of the history first.</source>
        <translation>Wählen Sie zuerst einen Frame im Verlauf.</translation>
    </message>
    <message>
        <source>loaded, not sent</source>
        <translation>geladen, nicht gesendet</translation>
    </message>
</context>
<context>
    <name>ParameterPage</name>
    <message>
        <source>Load profile…</source>
        <translation>Profil laden…</translation>
    </message>
    <message>
        <source>Load parameter values from a profile file as edits</source>
        <translation>Parameterwerte aus einer Profildatei als Änderungen laden</translation>
    </message>
    <message>
        <source>Save profile…</source>
        <translation>Profil speichern…</translation>
    </message>
    <message>
        <source>Save the servo&apos;s parameter values to a profile file</source>
        <translation>Die Parameterwerte des Servos in eine Profildatei speichern</translation>
    </message>
    <message>
        <source>Read</source>
        <translation>Lesen</translation>
    </message>
    <message>
        <source>Read every parameter from the servo</source>
        <translation>Jeden Parameter aus dem Servo lesen</translation>
    </message>
    <message>
        <source>Revert</source>
        <translation>Verwerfen</translation>
    </message>
    <message>
        <source>Drop every edit and show the servo&apos;s values again</source>
        <translation>Alle Änderungen verwerfen und wieder die Werte des Servos anzeigen</translation>
    </message>
    <message>
        <source>Apply</source>
        <translation>Übernehmen</translation>
    </message>
    <message>
        <source>Write the edited parameters to the servo, then read them back to verify</source>
        <translation>Die geänderten Parameter auf das Servo schreiben und zur Verifizierung zurücklesen</translation>
    </message>
    <message>
        <source>%v of %m</source>
        <translation>%v von %m</translation>
    </message>
    <message>
        <source>&lt;b&gt;Device&lt;/b&gt; is what the servo reports. Edits are written only when you press &lt;b&gt;Apply&lt;/b&gt;, then read back and verified.</source>
        <translation>&lt;b&gt;Gerät&lt;/b&gt; ist, was das Servo meldet. Änderungen werden erst geschrieben, wenn Sie &lt;b&gt;Übernehmen&lt;/b&gt; drücken, dann zurückgelesen und verifiziert.</translation>
    </message>
    <message>
        <source>Device</source>
        <translation>Gerät</translation>
    </message>
    <message>
        <source>New value</source>
        <translation>Neuer Wert</translation>
    </message>
    <message>
        <source>State</source>
        <translation>Zustand</translation>
    </message>
    <message>
        <source>EEPROM</source>
        <translation>EEPROM</translation>
    </message>
    <message>
        <source>Kept in the servo&apos;s EEPROM: written with the lock opened and closed again, and kept after power-off</source>
        <translation>Im EEPROM des Servos gespeichert: bei geöffneter und danach wieder geschlossener Sperre geschrieben und nach dem Ausschalten erhalten</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source> or </source>
        <translation> oder </translation>
    </message>
    <message>
        <source>%1: %2 to %3%4</source>
        <translation>%1: %2 bis %3%4</translation>
    </message>
    <message>
        <source>Refused</source>
        <translation>Abgelehnt</translation>
    </message>
    <message>
        <source>—</source>
        <translation>—</translation>
    </message>
    <message>
        <source>Not read from the servo yet</source>
        <translation>Noch nicht aus dem Servo gelesen</translation>
    </message>
    <message>
        <source>Changed here; written to the servo when you press Apply</source>
        <translation>Hier geändert; wird beim Drücken von „Übernehmen“ auf das Servo geschrieben</translation>
    </message>
    <message>
        <source>Being written to the servo</source>
        <translation>Wird auf das Servo geschrieben</translation>
    </message>
    <message>
        <source>Written and read back with the same value</source>
        <translation>Geschrieben und mit demselben Wert zurückgelesen</translation>
    </message>
    <message>
        <source>The value read back differs from the value written</source>
        <translation>Der zurückgelesene Wert weicht vom geschriebenen Wert ab</translation>
    </message>
    <message>
        <source>The write did not take effect; the edit is kept so you can try again</source>
        <translation>Der Schreibvorgang hat nicht gewirkt; die Änderung bleibt erhalten, damit Sie es erneut versuchen können</translation>
    </message>
    <message>
        <source>The write went out but no answer confirmed it, so whether the servo took it is not known; the next read settles it, and the edit is kept</source>
        <translation>Der Schreibvorgang wurde gesendet, aber keine Antwort hat ihn bestätigt, daher ist unbekannt, ob das Servo ihn übernommen hat; der nächste Lesevorgang klärt das, und die Änderung bleibt erhalten</translation>
    </message>
</context>
<context>
    <name>PortAccess</name>
    <message>
        <source>process %1</source>
        <translation>Prozess %1</translation>
    </message>
    <message>
        <source>%1 (process %2)</source>
        <translation>%1 (Prozess %2)</translation>
    </message>
</context>
<context>
    <name>PortProbe</name>
    <message>
        <source>Asking for a PTK servo at %1…</source>
        <translation>Suche nach einem PTK-Servo bei %1…</translation>
    </message>
    <message>
        <source>Asking for Feetech servos at %1…</source>
        <translation>Suche nach Feetech-Servos bei %1…</translation>
    </message>
    <message>
        <source>the port refused %1</source>
        <translation>der Anschluss hat %1 abgelehnt</translation>
    </message>
</context>
<context>
    <name>Pose</name>
    <message>
        <source>not a JSON object</source>
        <translation>kein JSON-Objekt</translation>
    </message>
    <message>
        <source>unknown entry &quot;%1&quot;</source>
        <translation>unbekannter Eintrag „%1“</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is missing</source>
        <translation>„%1“ fehlt</translation>
    </message>
    <message>
        <source>&quot;%1&quot;: %2 is not a servo ID (0 to %3)</source>
        <translation>„%1“: %2 ist keine Servo-ID (0 bis %3)</translation>
    </message>
    <message>
        <source>&quot;%1&quot;: %2 is not a Feetech baud rate in bps</source>
        <translation>„%1“: %2 ist keine Feetech-Baudrate in bps</translation>
    </message>
    <message>
        <source>&quot;%1&quot;: %2 is not an integer number of steps</source>
        <translation>„%1“: %2 ist keine ganzzahlige Anzahl von Schritten</translation>
    </message>
    <message>
        <source>&quot;%1&quot;: %2 is out of range (%3 to %4)</source>
        <translation>„%1“: %2 liegt außerhalb des Bereichs (%3 bis %4)</translation>
    </message>
    <message>
        <source>&quot;%1&quot; must be text</source>
        <translation>„%1“ muss Text sein</translation>
    </message>
    <message>
        <source>the pose has no &quot;%1&quot; list</source>
        <translation>die Pose hat keine Liste „%1“</translation>
    </message>
    <message>
        <source>servo entry %1: %2</source>
        <translation>Servoeintrag %1: %2</translation>
    </message>
    <message>
        <source>servo entry %1: ID %2 at %3 bps is already in the pose</source>
        <translation>Servoeintrag %1: ID %2 bei %3 bps ist bereits in der Pose</translation>
    </message>
    <message>
        <source>too large to be a pose</source>
        <translation>zu groß für eine Pose</translation>
    </message>
    <message>
        <source>not a ServoBench pose (the document is not a JSON object)</source>
        <translation>keine ServoBench-Pose (das Dokument ist kein JSON-Objekt)</translation>
    </message>
    <message>
        <source>not a ServoBench pose (&quot;%1&quot; is not &quot;%2&quot;)</source>
        <translation>keine ServoBench-Pose („%1“ ist nicht „%2“)</translation>
    </message>
    <message>
        <source>the pose has format version %1 and was written by a newer ServoBench; this version reads format version %2 and older</source>
        <translation>die Pose hat die Formatversion %1 und wurde von einem neueren ServoBench geschrieben; diese Version liest Formatversion %2 und älter</translation>
    </message>
</context>
<context>
    <name>Profile</name>
    <message>
        <source>expected true or false</source>
        <translation>true oder false erwartet</translation>
    </message>
    <message>
        <source>expected a number</source>
        <translation>Zahl erwartet</translation>
    </message>
    <message>
        <source>%1 is out of range (%2 to %3)</source>
        <translation>%1 liegt außerhalb des Bereichs (%2 bis %3)</translation>
    </message>
    <message>
        <source>%1 is not a whole number</source>
        <translation>%1 ist keine ganze Zahl</translation>
    </message>
    <message>
        <source>%1 is not a multiple of %2</source>
        <translation>%1 ist kein Vielfaches von %2</translation>
    </message>
    <message>
        <source>unknown parameter &quot;%1&quot;</source>
        <translation>unbekannter Parameter „%1“</translation>
    </message>
    <message>
        <source>%1: the raw value %2 cannot be kept in a profile</source>
        <translation>%1: Der Rohwert %2 kann nicht in einem Profil gespeichert werden</translation>
    </message>
    <message>
        <source>the profile names no servo family</source>
        <translation>das Profil nennt keine Servofamilie</translation>
    </message>
    <message>
        <source>the profile is for &quot;%1&quot; servos, not &quot;%2&quot;</source>
        <translation>das Profil ist für „%1“-Servos, nicht für „%2“</translation>
    </message>
    <message>
        <source>&quot;%1&quot; must be text</source>
        <translation>„%1“ muss Text sein</translation>
    </message>
    <message>
        <source>&quot;%1&quot;: &quot;%2&quot; is not an ISO 8601 date and time</source>
        <translation>&quot;%1&quot;: &quot;%2&quot; ist kein Datum mit Uhrzeit nach ISO 8601</translation>
    </message>
    <message>
        <source>the profile has no &quot;%1&quot; object</source>
        <translation>das Profil hat kein Objekt &quot;%1&quot;</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>too large to be a profile</source>
        <translation>zu groß für ein Profil</translation>
    </message>
    <message>
        <source>not a ServoBench profile (the document is not a JSON object)</source>
        <translation>kein ServoBench-Profil (das Dokument ist kein JSON-Objekt)</translation>
    </message>
    <message>
        <source>not a ServoBench profile (&quot;%1&quot; is not &quot;%2&quot;)</source>
        <translation>kein ServoBench-Profil (&quot;%1&quot; ist nicht &quot;%2&quot;)</translation>
    </message>
    <message>
        <source>the profile has format version %1 and was written by a newer ServoBench; this version reads format version %2 and older</source>
        <translation>das Profil hat die Formatversion %1 und wurde von einem neueren ServoBench geschrieben; diese Version liest Formatversion %2 und älter</translation>
    </message>
</context>
<context>
    <name>ProfileActions</name>
    <message>
        <source>Save profile</source>
        <translation>Profil speichern</translation>
    </message>
    <message>
        <source>ServoBench profiles (*.json)</source>
        <translation>ServoBench-Profile (*.json)</translation>
    </message>
    <message>
        <source>Load profile</source>
        <translation>Profil laden</translation>
    </message>
    <message>
        <source>Read the servo before saving a profile: not every value is known.</source>
        <translation>Lesen Sie das Servo vor dem Speichern eines Profils aus: Nicht jeder Wert ist bekannt.</translation>
    </message>
    <message>
        <source>The profile was not loaded: %1</source>
        <translation>Das Profil wurde nicht geladen: %1</translation>
    </message>
    <message>
        <source>The servo already holds every value of this profile</source>
        <translation>Das Servo enthält bereits jeden Wert dieses Profils</translation>
    </message>
    <message>
        <source>Profile loaded as edits: review them, then Apply</source>
        <translation>Profil als Änderungen geladen: Prüfen Sie sie und klicken Sie dann auf Übernehmen</translation>
    </message>
</context>
<context>
    <name>ProfileDiffDialog</name>
    <message>
        <source>Load profile</source>
        <translation>Profil laden</translation>
    </message>
    <message numerus="yes">
        <source>%n parameter(s) in %1 differ from the servo. Loading makes them edits; nothing is written until you press Apply.</source>
        <translation>
            <numerusform>%n Parameter in %1 weicht vom Servo ab. Beim Laden wird er zur Änderung; geschrieben wird erst, wenn Sie Übernehmen drücken.</numerusform>
            <numerusform>%n Parameter in %1 weichen vom Servo ab. Beim Laden werden sie zu Änderungen; geschrieben wird erst, wenn Sie Übernehmen drücken.</numerusform>
        </translation>
    </message>
    <message>
        <source>Parameter</source>
        <translation>Parameter</translation>
    </message>
    <message>
        <source>On the servo</source>
        <translation>Im Servo</translation>
    </message>
    <message>
        <source>In the file</source>
        <translation>In der Datei</translation>
    </message>
    <message>
        <source>not read</source>
        <translation>nicht gelesen</translation>
    </message>
    <message>
        <source>Load as edits</source>
        <translation>Als Änderungen laden</translation>
    </message>
</context>
<context>
    <name>PseudoTerminal</name>
    <message>
        <source>cannot open a pseudo-terminal: %1</source>
        <translation>Pseudo-Terminal kann nicht geöffnet werden: %1</translation>
    </message>
    <message>
        <source>cannot unlock the pseudo-terminal: %1</source>
        <translation>Pseudo-Terminal kann nicht entsperrt werden: %1</translation>
    </message>
    <message>
        <source>cannot name the pseudo-terminal&apos;s slave</source>
        <translation>der Slave des Pseudo-Terminals kann nicht benannt werden</translation>
    </message>
    <message>
        <source>cannot replace the old link %1: %2</source>
        <translation>der alte Link %1 kann nicht ersetzt werden: %2</translation>
    </message>
    <message>
        <source>%1 exists and is not a symlink; choose another --link path</source>
        <translation>%1 existiert und ist kein symbolischer Link; wählen Sie einen anderen Pfad für --link</translation>
    </message>
    <message>
        <source>cannot create the link %1: %2</source>
        <translation>der Link %1 kann nicht angelegt werden: %2</translation>
    </message>
    <message>
        <source>Simulated servos need a pseudo-terminal, which this system does not have: they run on Linux and macOS.</source>
        <translation>Simulierte Servos brauchen ein Pseudo-Terminal, das dieses System nicht hat: Sie laufen unter Linux und macOS.</translation>
    </message>
</context>
<context>
    <name>PtkClient</name>
    <message>
        <source>The servo is not connected.</source>
        <translation>Das Servo ist nicht verbunden.</translation>
    </message>
    <message>
        <source>A read or write is already running.</source>
        <translation>Es läuft bereits ein Lese- oder Schreibvorgang.</translation>
    </message>
    <message>
        <source>There are no changes to apply.</source>
        <translation>Es gibt keine Änderungen zu übernehmen.</translation>
    </message>
    <message>
        <source>%1 has not been read yet.</source>
        <translation>%1 wurde noch nicht gelesen.</translation>
    </message>
    <message>
        <source>Wait until the servo&apos;s read or Apply has finished.</source>
        <translation>Warten Sie, bis das Lesen oder Übernehmen des Servos fertig ist.</translation>
    </message>
</context>
<context>
    <name>PtkSession</name>
    <message>
        <source>Disconnected during Apply; the servo may hold only part of the new values.</source>
        <translation>Verbindung während Übernehmen getrennt; das Servo enthält möglicherweise nur einen Teil der neuen Werte.</translation>
    </message>
    <message>
        <source>Disconnected during the read.</source>
        <translation>Verbindung während des Lesens getrennt.</translation>
    </message>
    <message>
        <source>Not connected.</source>
        <translation>Nicht verbunden.</translation>
    </message>
    <message>
        <source>Busy: a read or write is already running.</source>
        <translation>Beschäftigt: Es läuft bereits ein Lese- oder Schreibvorgang.</translation>
    </message>
    <message>
        <source>No answer to the query for %1.</source>
        <translation>Keine Antwort auf die Abfrage von %1.</translation>
    </message>
    <message>
        <source>Written, but not verified. %1</source>
        <translation>Geschrieben, aber nicht überprüft. %1</translation>
    </message>
    <message>
        <source>The link went down before the values could be read back.</source>
        <translation>Die Verbindung brach ab, bevor die Werte zurückgelesen werden konnten.</translation>
    </message>
    <message>
        <source>The link went down.</source>
        <translation>Die Verbindung brach ab.</translation>
    </message>
    <message>
        <source>%1 has not been read yet; nothing was written.</source>
        <translation>%1 wurde noch nicht gelesen; es wurde nichts geschrieben.</translation>
    </message>
    <message>
        <source>%1; nothing was written.</source>
        <translation>%1; es wurde nichts geschrieben.</translation>
    </message>
    <message>
        <source>The link went down while writing %1; the servo may hold only part of the new values.</source>
        <translation>Die Verbindung brach beim Schreiben von %1 ab; das Servo enthält möglicherweise nur einen Teil der neuen Werte.</translation>
    </message>
    <message>
        <source>The port is open but the servo does not answer. Check that it is powered and plugged into the programmer.</source>
        <translation>Der Anschluss ist offen, aber das Servo antwortet nicht. Prüfen Sie, ob es mit Strom versorgt und am Programmiergerät eingesteckt ist.</translation>
    </message>
    <message>
        <source>The link went down during Apply: %1</source>
        <translation>Die Verbindung brach während Übernehmen ab: %1</translation>
    </message>
    <message>
        <source>The frame was not sent: the link is down.</source>
        <translation>Der Frame wurde nicht gesendet: Die Verbindung ist unterbrochen.</translation>
    </message>
    <message>
        <source>Sent.</source>
        <translation>Gesendet.</translation>
    </message>
    <message>
        <source>The servo answered.</source>
        <translation>Das Servo hat geantwortet.</translation>
    </message>
    <message>
        <source>Sent; the servo did not answer.</source>
        <translation>Gesendet; das Servo hat nicht geantwortet.</translation>
    </message>
</context>
<context>
    <name>PtkWorkspace</name>
    <message>
        <source>Read all parameters</source>
        <translation>Alle Parameter lesen</translation>
    </message>
    <message>
        <source>Read failed: %1</source>
        <translation>Lesen fehlgeschlagen: %1</translation>
    </message>
    <message>
        <source>Nothing was written: %1</source>
        <translation>Es wurde nichts geschrieben: %1</translation>
    </message>
    <message>
        <source>Writing N1…N12, then reading back…</source>
        <translation>N1…N12 werden geschrieben, dann zurückgelesen…</translation>
    </message>
    <message>
        <source>The servo did not take every value: the fields marked Mismatch hold something else than was written.</source>
        <translation>Das Servo hat nicht jeden Wert übernommen: Die als Abweichung markierten Felder enthalten etwas anderes als geschrieben.</translation>
    </message>
    <message>
        <source>Written and verified</source>
        <translation>Geschrieben und überprüft</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>%1 gespeichert</translation>
    </message>
    <message>
        <source>Wait for the running read or Apply to finish before loading a profile.</source>
        <translation>Warten Sie, bis das laufende Lesen oder Übernehmen beendet ist, bevor Sie ein Profil laden.</translation>
    </message>
</context>
<context>
    <name>RecordReplayDialog</name>
    <message>
        <source>Record and replay</source>
        <translation>Aufzeichnung und Wiedergabe</translation>
    </message>
    <message>
        <source>Joints to record</source>
        <translation>Aufzuzeichnende Gelenke</translation>
    </message>
    <message>
        <source>&amp;Open…</source>
        <translation>&amp;Öffnen…</translation>
    </message>
    <message>
        <source>&amp;Save…</source>
        <translation>&amp;Speichern…</translation>
    </message>
    <message>
        <source>Recording</source>
        <translation>Aufzeichnung</translation>
    </message>
    <message>
        <source>Nothing recorded yet.</source>
        <translation>Noch nichts aufgezeichnet.</translation>
    </message>
    <message>
        <source>Replay</source>
        <translation>Wiedergabe</translation>
    </message>
    <message>
        <source> ×</source>
        <translation> ×</translation>
    </message>
    <message>
        <source>2 plays twice as fast, 0.5 at half speed</source>
        <translation>2 spielt doppelt so schnell ab, 0.5 mit halber Geschwindigkeit</translation>
    </message>
    <message>
        <source>Between two loops the arm eases back to the first frame</source>
        <translation>Zwischen zwei Durchläufen fährt der Arm sanft zum ersten Frame zurück</translation>
    </message>
    <message>
        <source>Switch torque off at the end</source>
        <translation>Am Ende Drehmoment abschalten</translation>
    </message>
    <message>
        <source>Otherwise the arm holds the last frame</source>
        <translation>Sonst hält der Arm den letzten Frame</translation>
    </message>
    <message>
        <source>&amp;Play</source>
        <translation>Abs&amp;pielen</translation>
    </message>
    <message>
        <source>Torque on where the arm stands, a gentle move to the first frame, then the frames at their recorded times</source>
        <translation>Drehmoment an, wo der Arm steht, eine sanfte Fahrt zum ersten Frame, dann die Frames zu ihren aufgezeichneten Zeiten</translation>
    </message>
    <message>
        <source>S&amp;top</source>
        <translation>S&amp;topp</translation>
    </message>
    <message>
        <source>Stop recording, or stop the replay with the arm held where it stands</source>
        <translation>Die Aufzeichnung stoppen oder die Wiedergabe stoppen, wobei der Arm an seiner Stelle gehalten wird</translation>
    </message>
    <message>
        <source>Speed:</source>
        <translation>Geschwindigkeit:</translation>
    </message>
    <message>
        <source>Loops:</source>
        <translation>Durchläufe:</translation>
    </message>
    <message>
        <source>Nothing was recorded: not every joint answered.</source>
        <translation>Es wurde nichts aufgezeichnet: Nicht jedes Gelenk hat geantwortet.</translation>
    </message>
    <message numerus="yes">
        <source>Recorded %n frame(s) over %1 s.</source>
        <translation>
            <numerusform>%n Frame über %1 s aufgezeichnet.</numerusform>
            <numerusform>%n Frames über %1 s aufgezeichnet.</numerusform>
        </translation>
    </message>
    <message>
        <source>Stop &amp;recording</source>
        <translation>Aufzeichnung &amp;beenden</translation>
    </message>
    <message numerus="yes">
        <source>Recording: %n frame(s), %1 s</source>
        <translation>
            <numerusform>Aufzeichnung: %n Frame, %1 s</numerusform>
            <numerusform>Aufzeichnung: %n Frames, %1 s</numerusform>
        </translation>
    </message>
    <message>
        <source>Replaying: the arm eases to the first frame first.</source>
        <translation>Wiedergabe: Der Arm fährt zuerst sanft zum ersten Frame.</translation>
    </message>
    <message>
        <source>Stopping: the arm is held where it stands…</source>
        <translation>Wird gestoppt: Der Arm wird an seiner Stelle gehalten…</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>%1 s of %2 s, frame %3 of %4 — %5</source>
        <translation>%1 s von %2 s, Frame %3 von %4 — %5</translation>
    </message>
    <message>
        <source>Open recording</source>
        <translation>Aufzeichnung öffnen</translation>
    </message>
    <message>
        <source>Motion recordings (*.csv)</source>
        <translation>Bewegungsaufzeichnungen (*.csv)</translation>
    </message>
    <message>
        <source>Save recording</source>
        <translation>Aufzeichnung speichern</translation>
    </message>
    <message numerus="yes">
        <source>Opened %1: %n frame(s) over %2 s.</source>
        <translation>
            <numerusform>%1 geöffnet: %n Frame über %2 s.</numerusform>
            <numerusform>%1 geöffnet: %n Frames über %2 s.</numerusform>
        </translation>
    </message>
    <message>
        <source>Saved to %1.</source>
        <translation>In %1 gespeichert.</translation>
    </message>
    <message>
        <source>The servos whose positions are recorded; Record switches their torque off so that they can be moved by hand</source>
        <translation>Die Servos, deren Positionen aufgezeichnet werden; Aufzeichnen schaltet ihr Drehmoment ab, damit sie von Hand bewegt werden können</translation>
    </message>
    <message>
        <source>Torque off and &amp;record</source>
        <translation>Drehmoment aus und &amp;aufzeichnen</translation>
    </message>
    <message>
        <source>Support the arm: torque goes off on the joints to record, so that you can move them by hand</source>
        <translation>Halten Sie den Arm: Das Drehmoment der aufzuzeichnenden Gelenke geht aus, damit Sie sie von Hand bewegen können</translation>
    </message>
    <message>
        <source>%1 · %2 · %3 bps</source>
        <translation>%1 · %2 · %3 bps</translation>
    </message>
    <message numerus="yes">
        <source>Switching torque off on %n joint(s)…</source>
        <translation>
            <numerusform>Drehmoment von %n Gelenk wird abgeschaltet…</numerusform>
            <numerusform>Drehmoment von %n Gelenken wird abgeschaltet…</numerusform>
        </translation>
    </message>
    <message>
        <source>Recording: torque is off, move the joints by hand, then Stop.</source>
        <translation>Aufzeichnung: Das Drehmoment ist aus; bewegen Sie die Gelenke von Hand, dann Stopp.</translation>
    </message>
    <message>
        <source>Torque could not be switched off on %1: %2 Nothing is recorded.</source>
        <translation>Das Drehmoment von %1 ließ sich nicht abschalten: %2 Es wird nichts aufgezeichnet.</translation>
    </message>
    <message>
        <source>its model has no torque enable.</source>
        <translation>sein Modell hat keine Drehmomentfreigabe.</translation>
    </message>
</context>
<context>
    <name>RegisterTable</name>
    <message>
        <source>not valid JSON at offset %1: %2</source>
        <translation>kein gültiges JSON bei Offset %1: %2</translation>
    </message>
    <message>
        <source>the document is not a JSON object</source>
        <translation>das Dokument ist kein JSON-Objekt</translation>
    </message>
    <message>
        <source>unsupported &quot;format&quot; (expected 1)</source>
        <translation>nicht unterstütztes &quot;format&quot; (erwartet: 1)</translation>
    </message>
    <message>
        <source>register &quot;%1&quot; (address %2)</source>
        <translation>Register &quot;%1&quot; (Adresse %2)</translation>
    </message>
    <message>
        <source>unknown field &quot;%1&quot;</source>
        <translation>unbekanntes Feld &quot;%1&quot;</translation>
    </message>
    <message>
        <source>the key must be snake_case</source>
        <translation>der Schlüssel muss snake_case sein</translation>
    </message>
    <message>
        <source>the address must be a whole number from 0 to 255</source>
        <translation>die Adresse muss eine ganze Zahl von 0 bis 255 sein</translation>
    </message>
    <message>
        <source>the size must be 1 or 2 bytes</source>
        <translation>die Größe muss 1 oder 2 Byte betragen</translation>
    </message>
    <message>
        <source>the register runs past address 255</source>
        <translation>das Register reicht über Adresse 255 hinaus</translation>
    </message>
    <message>
        <source>the label is missing</source>
        <translation>die Bezeichnung fehlt</translation>
    </message>
    <message>
        <source>storage must be &quot;eeprom&quot; or &quot;ram&quot;</source>
        <translation>storage muss &quot;eeprom&quot; oder &quot;ram&quot; sein</translation>
    </message>
    <message>
        <source>access must be &quot;ro&quot; or &quot;rw&quot;</source>
        <translation>access muss &quot;ro&quot; oder &quot;rw&quot; sein</translation>
    </message>
    <message>
        <source>the unit must be a string</source>
        <translation>die Einheit muss eine Zeichenkette sein</translation>
    </message>
    <message>
        <source>the scale must be a positive number</source>
        <translation>der Skalierungsfaktor muss eine positive Zahl sein</translation>
    </message>
    <message>
        <source>the sign bit must lie inside the register</source>
        <translation>das Vorzeichenbit muss innerhalb des Registers liegen</translation>
    </message>
    <message>
        <source>min and max must be whole numbers</source>
        <translation>min und max müssen ganze Zahlen sein</translation>
    </message>
    <message>
        <source>min is greater than max</source>
        <translation>min ist größer als max</translation>
    </message>
    <message>
        <source>the range %1..%2 does not fit a %3-byte register</source>
        <translation>der Bereich %1..%2 passt nicht in ein %3-Byte-Register</translation>
    </message>
    <message>
        <source>the default does not fit the register</source>
        <translation>der Standardwert passt nicht in das Register</translation>
    </message>
    <message>
        <source>a choice needs a value that fits the register and a label</source>
        <translation>eine Auswahl braucht einen Wert, der in das Register passt, und eine Bezeichnung</translation>
    </message>
    <message>
        <source>a bit needs an index inside the register and a label</source>
        <translation>ein Bit braucht einen Index innerhalb des Registers und eine Bezeichnung</translation>
    </message>
    <message>
        <source>unknown family &quot;%1&quot;</source>
        <translation>unbekannte Familie &quot;%1&quot;</translation>
    </message>
    <message>
        <source>byte_order must be &quot;little&quot; or &quot;big&quot;</source>
        <translation>byte_order muss &quot;little&quot; oder &quot;big&quot; sein</translation>
    </message>
    <message>
        <source>there are no registers</source>
        <translation>es gibt keine Register</translation>
    </message>
    <message>
        <source>every register must be a JSON object</source>
        <translation>jedes Register muss ein JSON-Objekt sein</translation>
    </message>
    <message>
        <source>the key &quot;%1&quot; is used twice</source>
        <translation>der Schlüssel &quot;%1&quot; wird doppelt verwendet</translation>
    </message>
    <message>
        <source>registers &quot;%1&quot; and &quot;%2&quot; overlap at address %3</source>
        <translation>die Register &quot;%1&quot; und &quot;%2&quot; überlappen bei Adresse %3</translation>
    </message>
    <message>
        <source>families_by_major: &quot;%1&quot; is not a major number with a family</source>
        <translation>families_by_major: &quot;%1&quot; ist keine Hauptnummer mit einer Familie</translation>
    </message>
    <message>
        <source>model &quot;%1&quot;: needs a name and major and minor numbers 0-255</source>
        <translation>Modell &quot;%1&quot;: braucht einen Namen sowie Haupt- und Nebennummer von 0-255</translation>
    </message>
    <message>
        <source>model &quot;%1&quot;: unknown family</source>
        <translation>Modell &quot;%1&quot;: unbekannte Familie</translation>
    </message>
    <message>
        <source>model %1/%2 is listed twice</source>
        <translation>Modell %1/%2 ist doppelt aufgeführt</translation>
    </message>
    <message>
        <source>%1 (model %2/%3)</source>
        <translation>%1 (Modell %2/%3)</translation>
    </message>
    <message>
        <source>Unknown model %1/%2</source>
        <translation>Unbekanntes Modell %1/%2</translation>
    </message>
    <message>
        <source>Raw bytes (unknown model)</source>
        <translation>Rohbytes (unbekanntes Modell)</translation>
    </message>
    <message>
        <source>Byte %1</source>
        <translation>Byte %1</translation>
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
        <translation>torque_enable_values: die Tabelle hat kein torque_enable</translation>
    </message>
    <message>
        <source>torque_enable_values must be an object</source>
        <translation>torque_enable_values muss ein Objekt sein</translation>
    </message>
    <message>
        <source>torque_enable_values: unknown mode &quot;%1&quot;</source>
        <translation>torque_enable_values: unbekannter Modus &quot;%1&quot;</translation>
    </message>
    <message>
        <source>torque_enable_values: &quot;%1&quot; is not one of torque_enable&apos;s choices</source>
        <translation>torque_enable_values: &quot;%1&quot; ist keine der Auswahlmöglichkeiten von torque_enable</translation>
    </message>
    <message>
        <source>torque_enable_values: &quot;%1&quot; is missing</source>
        <translation>torque_enable_values: &quot;%1&quot; fehlt</translation>
    </message>
    <message>
        <source>feedback_block must give the address of present_position and a size that ends at the end of a register</source>
        <translation>feedback_block muss die Adresse von present_position und eine Größe angeben, die am Ende eines Registers endet</translation>
    </message>
    <message>
        <source>baud_rates: every rate must be a positive number, listed once</source>
        <translation>baud_rates: jede Rate muss eine positive Zahl sein und darf nur einmal vorkommen</translation>
    </message>
    <message>
        <source>baud_rates must list the rates of codes 0 to 7</source>
        <translation>baud_rates muss die Raten der Codes 0 bis 7 auflisten</translation>
    </message>
</context>
<context>
    <name>RegisterTableModel</name>
    <message>
        <source>%1 to %2</source>
        <translation>%1 bis %2</translation>
    </message>
    <message>
        <source>On the servo: %1</source>
        <translation>Im Servo: %1</translation>
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
        <translation>RW</translation>
    </message>
    <message>
        <source>RO</source>
        <translation>RO</translation>
    </message>
    <message>
        <source>—</source>
        <translation>—</translation>
    </message>
    <message>
        <source>Addr</source>
        <translation>Adr.</translation>
    </message>
    <message>
        <source>Key</source>
        <translation>Schlüssel</translation>
    </message>
    <message>
        <source>Register</source>
        <translation>Register</translation>
    </message>
    <message>
        <source>Size</source>
        <translation>Größe</translation>
    </message>
    <message>
        <source>Area</source>
        <translation>Bereich</translation>
    </message>
    <message>
        <source>Access</source>
        <translation>Zugriff</translation>
    </message>
    <message>
        <source>Raw</source>
        <translation>Roh</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>Wert</translation>
    </message>
    <message>
        <source>State</source>
        <translation>Zustand</translation>
    </message>
    <message>
        <source>, in steps of %1</source>
        <translation>, in Schritten von %1</translation>
    </message>
    <message>
        <source>%1, snapped</source>
        <comment>state of a register whose typed value was put on a step</comment>
        <translation>%1, auf Schritt gerundet</translation>
    </message>
</context>
<context>
    <name>ReplaceMotorWizard</name>
    <message>
        <source>Replace a motor</source>
        <translation>Motor ersetzen</translation>
    </message>
    <message>
        <source>The Feetech port is closed: open it again to go on.</source>
        <translation>Der Feetech-Anschluss ist geschlossen: Öffnen Sie ihn erneut, um fortzufahren.</translation>
    </message>
    <message>
        <source>A new servo takes the place of one joint of an arm set up and calibrated before. ServoBench sets it up as that joint (its ID, the robot&apos;s baud rate and the joint&apos;s settings, each read back), then calibrates that joint alone and updates the arm&apos;s LeRobot calibration file with it: the file&apos;s other joints stay as they are.</source>
        <translation>Ein neues Servo ersetzt ein Gelenk eines zuvor eingerichteten und kalibrierten Arms. ServoBench richtet es als dieses Gelenk ein (seine ID, die Baudrate des Roboters und die Einstellungen des Gelenks, jeweils zurückgelesen), kalibriert dann nur dieses Gelenk und aktualisiert damit die LeRobot-Kalibrierdatei des Arms: Die anderen Gelenke der Datei bleiben unverändert.</translation>
    </message>
    <message>
        <source>Robot:</source>
        <translation>Roboter:</translation>
    </message>
    <message>
        <source>Joint replaced:</source>
        <translation>Ersetztes Gelenk:</translation>
    </message>
    <message>
        <source>The arm&apos;s LeRobot calibration file</source>
        <translation>Die LeRobot-Kalibrierdatei des Arms</translation>
    </message>
    <message>
        <source>&amp;Browse…</source>
        <translation>&amp;Durchsuchen…</translation>
    </message>
    <message>
        <source>Choose the arm&apos;s LeRobot calibration file</source>
        <translation>Die LeRobot-Kalibrierdatei des Arms auswählen</translation>
    </message>
    <message>
        <source>Calibration file:</source>
        <translation>Kalibrierdatei:</translation>
    </message>
    <message>
        <source>&amp;Next</source>
        <translation>&amp;Weiter</translation>
    </message>
    <message>
        <source>Check that the file has the joint, then set up the new servo</source>
        <translation>Prüfen, ob die Datei das Gelenk enthält, dann das neue Servo einrichten</translation>
    </message>
    <message>
        <source>&amp;Back</source>
        <translation>&amp;Zurück</translation>
    </message>
    <message>
        <source>Choose another joint or file</source>
        <translation>Ein anderes Gelenk oder eine andere Datei wählen</translation>
    </message>
    <message>
        <source>&amp;Find</source>
        <translation>&amp;Suchen</translation>
    </message>
    <message>
        <source>Look for the one servo on the bus, at every ID and baud rate; nothing is written</source>
        <translation>Das eine Servo am Bus suchen, bei jeder ID und Baudrate; es wird nichts geschrieben</translation>
    </message>
    <message>
        <source>&amp;Set up</source>
        <translation>&amp;Einrichten</translation>
    </message>
    <message>
        <source>Give the servo found the joint&apos;s ID, the robot&apos;s baud rate and the joint&apos;s settings, each read back</source>
        <translation>Dem gefundenen Servo die ID des Gelenks, die Baudrate des Roboters und die Einstellungen des Gelenks geben, jeweils zurückgelesen</translation>
    </message>
    <message>
        <source>S&amp;can the arm</source>
        <translation>Arm s&amp;cannen</translation>
    </message>
    <message>
        <source>Look for the arm&apos;s servos at the robot&apos;s baud rate; nothing is written</source>
        <translation>Die Servos des Arms bei der Baudrate des Roboters suchen; es wird nichts geschrieben</translation>
    </message>
    <message>
        <source>&amp;Calibrate the joint…</source>
        <translation>Gelenk &amp;kalibrieren…</translation>
    </message>
    <message>
        <source>Record the new servo&apos;s range by hand and update the calibration file</source>
        <translation>Den Bereich des neuen Servos von Hand aufzeichnen und die Kalibrierdatei aktualisieren</translation>
    </message>
    <message>
        <source>%1 (ID %2)</source>
        <translation>%1 (ID %2)</translation>
    </message>
    <message>
        <source>The arm&apos;s LeRobot calibration</source>
        <translation>LeRobot-Kalibrierung des Arms</translation>
    </message>
    <message>
        <source>LeRobot calibration (*.json)</source>
        <translation>LeRobot-Kalibrierung (*.json)</translation>
    </message>
    <message>
        <source>Open the Feetech port the new servo is connected to first.</source>
        <translation>Öffnen Sie zuerst den Feetech-Anschluss, an dem das neue Servo angeschlossen ist.</translation>
    </message>
    <message>
        <source>Choose the robot and the joint whose motor is replaced.</source>
        <translation>Wählen Sie den Roboter und das Gelenk, dessen Motor ersetzt wird.</translation>
    </message>
    <message>
        <source>Choose the arm&apos;s LeRobot calibration file: the new joint&apos;s calibration goes into it.</source>
        <translation>Wählen Sie die LeRobot-Kalibrierdatei des Arms: Die Kalibrierung des neuen Gelenks wird darin gespeichert.</translation>
    </message>
    <message>
        <source>%1 has no joint with ID %2: choose the file of the arm whose %3 motor is replaced.</source>
        <translation>%1 hat kein Gelenk mit ID %2: Wählen Sie die Datei des Arms, dessen Motor %3 ersetzt wird.</translation>
    </message>
    <message>
        <source>&lt;b&gt;Unplug every servo of the arm from the bus&lt;/b&gt; and connect only the new servo for &lt;b&gt;%1&lt;/b&gt;, then press &lt;i&gt;Find&lt;/i&gt;.&lt;br&gt;&lt;small&gt;Keep the power on. A new servo answers at ID 1 and 1 Mbps; ServoBench finds it at any ID and rate and gives it ID %2 and %3.&lt;/small&gt;</source>
        <translation>&lt;b&gt;Trennen Sie alle Servos des Arms vom Bus&lt;/b&gt; und schließen Sie nur das neue Servo für &lt;b&gt;%1&lt;/b&gt; an, dann drücken Sie &lt;i&gt;Suchen&lt;/i&gt;.&lt;br&gt;&lt;small&gt;Lassen Sie die Stromversorgung eingeschaltet. Ein neues Servo antwortet bei ID 1 und 1 Mbps; ServoBench findet es bei jeder ID und Rate und gibt ihm ID %2 und %3.&lt;/small&gt;</translation>
    </message>
    <message>
        <source>Looking for the servo at every baud rate…</source>
        <translation>Das Servo wird bei jeder Baudrate gesucht…</translation>
    </message>
    <message>
        <source>Setting up the servo…</source>
        <translation>Das Servo wird eingerichtet…</translation>
    </message>
    <message>
        <source>Step %1 of %2: %3</source>
        <translation>Schritt %1 von %2: %3</translation>
    </message>
    <message>
        <source>Nothing was written to any servo.</source>
        <translation>Auf kein Servo wurde etwas geschrieben.</translation>
    </message>
    <message>
        <source>Done before that:</source>
        <translation>Davor erledigt:</translation>
    </message>
    <message>
        <source>&lt;b&gt;Found one servo:&lt;/b&gt; servo %1 at %2, model %3. Press &lt;i&gt;Set up&lt;/i&gt; to make it the %4 joint.</source>
        <translation>&lt;b&gt;Ein Servo gefunden:&lt;/b&gt; Servo %1 bei %2, Modell %3. Drücken Sie &lt;i&gt;Einrichten&lt;/i&gt;, um es zum Gelenk %4 zu machen.</translation>
    </message>
    <message>
        <source>&lt;b&gt;Put the arm back together:&lt;/b&gt; connect every servo in its chain as before, keep the power on, and press &lt;i&gt;Scan the arm&lt;/i&gt;. The %1 joint is then calibrated alone into %2.</source>
        <translation>&lt;b&gt;Bauen Sie den Arm wieder zusammen:&lt;/b&gt; Verbinden Sie alle Servos wie zuvor in ihrer Kette, lassen Sie die Stromversorgung eingeschaltet und drücken Sie &lt;i&gt;Arm scannen&lt;/i&gt;. Danach wird nur das Gelenk %1 kalibriert und in %2 übernommen.</translation>
    </message>
    <message>
        <source>&amp;Calibrate %1…</source>
        <translation>%1 &amp;kalibrieren…</translation>
    </message>
    <message>
        <source>Looking for the arm&apos;s servos at %1…</source>
        <translation>Die Servos des Arms werden bei %1 gesucht…</translation>
    </message>
    <message>
        <source>The new %1 servo does not answer at ID %2 and %3: check its cable and the power, then scan again.</source>
        <translation>Das neue Servo %1 antwortet nicht bei ID %2 und %3: Prüfen Sie sein Kabel und die Stromversorgung und scannen Sie dann erneut.</translation>
    </message>
    <message numerus="yes">
        <source>%n servo(s) answer, the new one among them.</source>
        <translation>
            <numerusform>%n Servo antwortet, darunter das neue.</numerusform>
            <numerusform>%n Servos antworten, darunter das neue.</numerusform>
        </translation>
    </message>
    <message>
        <source>The scan did not list servo %1: scan the arm again.</source>
        <translation>Servo %1 fehlt im Scan: Scannen Sie den Arm erneut.</translation>
    </message>
    <message>
        <source>Stopping after this step…</source>
        <translation>Anhalten nach diesem Schritt…</translation>
    </message>
</context>
<context>
    <name>RequestEngine</name>
    <message>
        <source>stray input discarded before a request</source>
        <translation>Streueingabe vor einer Anfrage verworfen</translation>
    </message>
    <message>
        <source>received while no request was waiting</source>
        <translation>empfangen, während keine Anfrage wartete</translation>
    </message>
    <message>
        <source>unexpected frame, ignored</source>
        <translation>unerwarteter Frame, ignoriert</translation>
    </message>
    <message>
        <source>bad checksum</source>
        <translation>falsche Prüfsumme</translation>
    </message>
    <message>
        <source>bytes that form no frame</source>
        <translation>Bytes, die keinen Frame bilden</translation>
    </message>
    <message>
        <source>no reply (attempt %1 of %2)</source>
        <translation>keine Antwort (Versuch %1 von %2)</translation>
    </message>
    <message>
        <source>came sooner than any answer to this request could: a late answer to an earlier one, discarded</source>
        <translation>kam früher, als eine Antwort auf diese Anfrage kommen konnte: eine verspätete Antwort auf eine frühere, verworfen</translation>
    </message>
    <message>
        <source>garbled: answers at once</source>
        <translation>verstümmelt: gleichzeitige Antworten</translation>
    </message>
    <message numerus="yes">
        <source>%n answer(s) in time; the others are missing</source>
        <translation>
            <numerusform>%n Antwort rechtzeitig; die anderen fehlen</numerusform>
            <numerusform>%n Antworten rechtzeitig; die anderen fehlen</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <comment>frame summary (note)</comment>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>late answer, %1 ms after its request</source>
        <translation>verspätete Antwort, %1 ms nach ihrer Anfrage</translation>
    </message>
    <message>
        <source>late</source>
        <translation>verspätet</translation>
    </message>
    <message>
        <source>late answer, discarded</source>
        <translation>verspätete Antwort, verworfen</translation>
    </message>
    <message>
        <source>heard while several may answer</source>
        <translation>empfangen, während mehrere antworten können</translation>
    </message>
    <message>
        <source>%1: silence was expected, not counted as an error</source>
        <comment>no reply (attempt …)</comment>
        <translation>%1: Stille war erwartet, nicht als Fehler gezählt</translation>
    </message>
</context>
<context>
    <name>RobotActions</name>
    <message>
        <source>&amp;Identify the servo</source>
        <translation>Servo &amp;identifizieren</translation>
    </message>
    <message>
        <source>Apply &amp;profile to selected servos…</source>
        <translation>&amp;Profil für ausgewählte Servos übernehmen…</translation>
    </message>
    <message>
        <source>Apply &amp;template settings to selected servos…</source>
        <translation>&amp;Vorlageneinstellungen für ausgewählte Servos übernehmen…</translation>
    </message>
    <message>
        <source>&amp;Save as robot template…</source>
        <translation>Als Robotervorlage &amp;speichern…</translation>
    </message>
    <message>
        <source>Connect to a Feetech bus first.</source>
        <translation>Verbinden Sie sich zuerst mit einem Feetech-Bus.</translation>
    </message>
    <message>
        <source>The scan is still running.</source>
        <translation>Der Scan läuft noch.</translation>
    </message>
    <message>
        <source>Scan the bus first: no servos are known.</source>
        <translation>Scannen Sie zuerst den Bus: Es sind keine Servos bekannt.</translation>
    </message>
    <message>
        <source>&amp;Identify servo ID %1</source>
        <translation>Servo-ID %1 &amp;identifizieren</translation>
    </message>
    <message>
        <source>Move the servo a little each way, slowly and with little torque, then put it back as it was: you see which servo of the arm it is</source>
        <translation>Das Servo langsam und mit wenig Drehmoment etwas in beide Richtungen bewegen und dann wieder zurückstellen: So sehen Sie, welches Servo des Arms es ist</translation>
    </message>
    <message>
        <source>Servos are being programmed.</source>
        <translation>Servos werden programmiert.</translation>
    </message>
    <message>
        <source>Another operation is still running.</source>
        <translation>Ein anderer Vorgang läuft noch.</translation>
    </message>
    <message>
        <source>Select servos in the tree first (Ctrl+click or Shift+click for several).</source>
        <translation>Wählen Sie zuerst Servos im Baum aus (Strg+Klick oder Umschalt+Klick für mehrere).</translation>
    </message>
    <message>
        <source>Write, verify and report each selected servo in turn</source>
        <translation>Jedes ausgewählte Servo nacheinander schreiben, überprüfen und melden</translation>
    </message>
    <message>
        <source>Describe this arm as a template the set-up wizards offer</source>
        <translation>Diesen Arm als Vorlage beschreiben, die die Einrichtungsassistenten anbieten</translation>
    </message>
    <message>
        <source>Identifying servo ID %1: watch which horn moves…</source>
        <translation>Servo-ID %1 wird identifiziert: Achten Sie darauf, welches Servohorn sich bewegt…</translation>
    </message>
    <message>
        <source>Programming servos</source>
        <translation>Servos programmieren</translation>
    </message>
    <message>
        <source>Starting…</source>
        <translation>Wird gestartet…</translation>
    </message>
    <message>
        <source>Programming %1: some servos failed; see the result table.</source>
        <translation>Programmieren von %1: Einige Servos sind fehlgeschlagen; siehe Ergebnistabelle.</translation>
    </message>
    <message>
        <source>Programming %1: done.</source>
        <translation>Programmieren von %1: fertig.</translation>
    </message>
    <message>
        <source>Apply template settings</source>
        <translation>Vorlageneinstellungen übernehmen</translation>
    </message>
    <message>
        <source>Each selected servo gets the settings of the template&apos;s joint with its ID:</source>
        <translation>Jedes ausgewählte Servo erhält die Einstellungen des Vorlagengelenks mit seiner ID:</translation>
    </message>
    <message>
        <source>Robot template saved to %1</source>
        <translation>Robotervorlage gespeichert unter %1</translation>
    </message>
    <message>
        <source>servo ID %1</source>
        <translation>Servo-ID %1</translation>
    </message>
</context>
<context>
    <name>RobotTemplate</name>
    <message>
        <source>&quot;%1&quot; must be an object of register values</source>
        <translation>&quot;%1&quot; muss ein Objekt mit Registerwerten sein</translation>
    </message>
    <message>
        <source>settings: &quot;%1&quot; is no writable register of %2 servos</source>
        <translation>settings: &quot;%1&quot; ist kein beschreibbares Register von %2-Servos</translation>
    </message>
    <message>
        <source>settings: &quot;%1&quot; is set by its own flow, not by a template</source>
        <translation>settings: &quot;%1&quot; wird über einen eigenen Ablauf gesetzt, nicht über eine Vorlage</translation>
    </message>
    <message>
        <source>settings: &quot;%1&quot; must be a whole number</source>
        <translation>settings: &quot;%1&quot; muss eine ganze Zahl sein</translation>
    </message>
    <message>
        <source>settings: &quot;%1&quot; = %2 is out of range (%3 to %4)</source>
        <translation>settings: &quot;%1&quot; = %2 liegt außerhalb des Bereichs (%3 bis %4)</translation>
    </message>
    <message>
        <source>every joint must be a JSON object</source>
        <translation>jedes Gelenk muss ein JSON-Objekt sein</translation>
    </message>
    <message>
        <source>unknown entry &quot;%1&quot;</source>
        <translation>unbekannter Eintrag &quot;%1&quot;</translation>
    </message>
    <message>
        <source>&quot;%1&quot; must be a name of letters, digits and _ that starts with a letter</source>
        <translation>&quot;%1&quot; muss ein Name aus Buchstaben, Ziffern und _ sein, der mit einem Buchstaben beginnt</translation>
    </message>
    <message>
        <source>&quot;%1&quot; must be a servo ID from 0 to %2</source>
        <translation>&quot;%1&quot; muss eine Servo-ID von 0 bis %2 sein</translation>
    </message>
    <message>
        <source>&quot;%1&quot;: &quot;%2&quot; is no model with a known register table</source>
        <translation>&quot;%1&quot;: &quot;%2&quot; ist kein Modell mit bekannter Registertabelle</translation>
    </message>
    <message>
        <source>&quot;%1&quot; must be true or false</source>
        <translation>&quot;%1&quot; muss true oder false sein</translation>
    </message>
    <message>
        <source>&quot;%1&quot; must be a name for the robot</source>
        <translation>&quot;%1&quot; muss ein Name für den Roboter sein</translation>
    </message>
    <message>
        <source>&quot;%1&quot; must be a Feetech baud rate in bps</source>
        <translation>&quot;%1&quot; muss eine Feetech-Baudrate in bps sein</translation>
    </message>
    <message>
        <source>&quot;%1&quot; must list the robot&apos;s joints</source>
        <translation>&quot;%1&quot; muss die Gelenke des Roboters auflisten</translation>
    </message>
    <message>
        <source>joint %1</source>
        <translation>Gelenk %1</translation>
    </message>
    <message>
        <source>joint %1: the name &quot;%2&quot; is used twice</source>
        <translation>Gelenk %1: der Name &quot;%2&quot; wird doppelt verwendet</translation>
    </message>
    <message>
        <source>joint %1 (%2): ID %3 is already %4&apos;s</source>
        <translation>Gelenk %1 (%2): ID %3 gehört bereits zu %4</translation>
    </message>
    <message>
        <source>the file is too large for a robot template</source>
        <translation>die Datei ist zu groß für eine Robotervorlage</translation>
    </message>
    <message>
        <source>SO-100 follower arm</source>
        <translation>SO-100-Folgearm</translation>
    </message>
    <message>
        <source>SO-100 leader arm</source>
        <translation>SO-100-Führungsarm</translation>
    </message>
    <message>
        <source>SO-101 follower arm</source>
        <translation>SO-101-Folgearm</translation>
    </message>
    <message>
        <source>SO-101 leader arm</source>
        <translation>SO-101-Führungsarm</translation>
    </message>
    <message>
        <source>not a ServoBench robot template (the document is not a JSON object)</source>
        <translation>keine ServoBench-Robotervorlage (das Dokument ist kein JSON-Objekt)</translation>
    </message>
    <message>
        <source>not a ServoBench robot template (&quot;%1&quot; is not &quot;%2&quot;)</source>
        <translation>keine ServoBench-Robotervorlage (&quot;%1&quot; ist nicht &quot;%2&quot;)</translation>
    </message>
    <message>
        <source>the template has format version %1 and was written by a newer ServoBench; this version reads format version %2 and older</source>
        <translation>die Vorlage hat die Formatversion %1 und wurde von einem neueren ServoBench geschrieben; diese Version liest Formatversion %2 und älter</translation>
    </message>
    <message>
        <source>&quot;%1&quot; must be an object of bit numbers by register</source>
        <translation>&quot;%1&quot; muss ein Objekt mit Bitnummern nach Register sein</translation>
    </message>
    <message>
        <source>%1: &quot;%2&quot; is no writable register of %3 servos</source>
        <translation>%1: &quot;%2&quot; ist kein beschreibbares Register von %3-Servos</translation>
    </message>
    <message>
        <source>%1: &quot;%2&quot; is set by its own flow, not by a template</source>
        <translation>%1: &quot;%2&quot; wird über einen eigenen Ablauf gesetzt, nicht über eine Vorlage</translation>
    </message>
    <message>
        <source>%1: &quot;%2&quot; must be a list of bit numbers</source>
        <translation>%1: &quot;%2&quot; muss eine Liste von Bitnummern sein</translation>
    </message>
    <message>
        <source>%1: &quot;%2&quot; has bits 0 to %3</source>
        <translation>%1: &quot;%2&quot; hat die Bits 0 bis %3</translation>
    </message>
</context>
<context>
    <name>RobotTemplateDialog</name>
    <message>
        <source>Replace the template?</source>
        <translation>Vorlage ersetzen?</translation>
    </message>
    <message>
        <source>%1 exists already. Replace it?</source>
        <translation>%1 existiert bereits. Ersetzen?</translation>
    </message>
    <message>
        <source>Save as robot template</source>
        <translation>Als Robotervorlage speichern</translation>
    </message>
    <message>
        <source>Template: %1</source>
        <translation>Vorlage: %1</translation>
    </message>
    <message numerus="yes">
        <source>The %n servo(s) the scan found</source>
        <translation>
            <numerusform>Das vom Scan gefundene Servo</numerusform>
            <numerusform>Die %n vom Scan gefundenen Servos</numerusform>
        </translation>
    </message>
    <message>
        <source>Joint name</source>
        <translation>Gelenkname</translation>
    </message>
    <message>
        <source>ID</source>
        <translation>ID</translation>
    </message>
    <message>
        <source>Model</source>
        <translation>Modell</translation>
    </message>
    <message>
        <source>Full turn</source>
        <translation>Volle Umdrehung</translation>
    </message>
    <message>
        <source>Settings (register units)</source>
        <translation>Einstellungen (Registereinheiten)</translation>
    </message>
    <message>
        <source>Registers set-up writes to this joint: key=value, separated by commas</source>
        <translation>Register, die die Einrichtung für dieses Gelenk schreibt: key=value, durch Kommas getrennt</translation>
    </message>
    <message>
        <source>Turns without end stops (a wrist roll): calibrated over 0-4095</source>
        <translation>Dreht ohne Endanschläge (z. B. Handgelenk drehen): kalibriert über 0-4095</translation>
    </message>
    <message>
        <source>Add joint</source>
        <translation>Gelenk hinzufügen</translation>
    </message>
    <message>
        <source>Remove joint</source>
        <translation>Gelenk entfernen</translation>
    </message>
    <message>
        <source>ID %1 (%2)</source>
        <translation>ID %1 (%2)</translation>
    </message>
    <message>
        <source>Take settings from servo</source>
        <translation>Einstellungen vom Servo holen</translation>
    </message>
    <message>
        <source>The selected joint&apos;s settings get the chosen servo&apos;s present values of the same registers</source>
        <translation>Die Einstellungen des ausgewählten Gelenks erhalten die aktuellen Werte derselben Register des gewählten Servos</translation>
    </message>
    <message>
        <source>Start from:</source>
        <translation>Ausgehend von:</translation>
    </message>
    <message>
        <source>Name:</source>
        <translation>Name:</translation>
    </message>
    <message>
        <source>Baud rate after set-up:</source>
        <translation>Baudrate nach der Einrichtung:</translation>
    </message>
    <message>
        <source>Not offered (unreadable): %1</source>
        <translation>Nicht angeboten (nicht lesbar): %1</translation>
    </message>
    <message>
        <source>My %1</source>
        <translation>Mein %1</translation>
    </message>
    <message>
        <source>My arm</source>
        <translation>Mein Arm</translation>
    </message>
    <message>
        <source>joint %1: the ID &quot;%2&quot; is not a number</source>
        <translation>Gelenk %1: die ID &quot;%2&quot; ist keine Zahl</translation>
    </message>
    <message>
        <source>joint %1: &quot;%2&quot; is not key=value (a register and a whole number)</source>
        <translation>Gelenk %1: &quot;%2&quot; ist nicht key=value (ein Register und eine ganze Zahl)</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is the name of a built-in template: choose another, so the wizards can tell them apart</source>
        <translation>&quot;%1&quot; ist der Name einer eingebauten Vorlage: Wählen Sie einen anderen, damit die Assistenten sie unterscheiden können</translation>
    </message>
    <message>
        <source>Will be saved to %1, where the set-up wizards find it.</source>
        <translation>Wird unter %1 gespeichert, wo die Einrichtungsassistenten sie finden.</translation>
    </message>
    <message>
        <source>The folder %1 cannot be created.</source>
        <translation>Der Ordner %1 kann nicht angelegt werden.</translation>
    </message>
    <message>
        <source>Select a joint and a servo first.</source>
        <translation>Wählen Sie zuerst ein Gelenk und ein Servo aus.</translation>
    </message>
    <message>
        <source>The bus is busy: try again in a moment.</source>
        <translation>Der Bus ist beschäftigt: Versuchen Sie es gleich noch einmal.</translation>
    </message>
    <message>
        <source>Reading servo ID %1…</source>
        <translation>Servo-ID %1 wird gelesen…</translation>
    </message>
    <message>
        <source>Fix the template first: %1</source>
        <translation>Korrigieren Sie zuerst die Vorlage: %1</translation>
    </message>
    <message>
        <source>Joint %1 sets no registers yet: type their keys (key=value), then take their values from a servo.</source>
        <translation>Gelenk %1 setzt noch keine Register: Geben Sie deren Schlüssel ein (key=value) und holen Sie dann ihre Werte von einem Servo.</translation>
    </message>
    <message>
        <source>The servo has no value for %1: kept as they were.</source>
        <translation>Das Servo hat keinen Wert für %1: unverändert belassen.</translation>
    </message>
</context>
<context>
    <name>ScanDialog</name>
    <message>
        <source>Scan the bus</source>
        <translation>Bus scannen</translation>
    </message>
    <message>
        <source>Servo IDs</source>
        <translation>Servo-IDs</translation>
    </message>
    <message>
        <source>From</source>
        <translation>Von</translation>
    </message>
    <message>
        <source>to</source>
        <translation>bis</translation>
    </message>
    <message>
        <source>Baud rates</source>
        <translation>Baudraten</translation>
    </message>
    <message>
        <source>%L1 bps</source>
        <translation>%L1 bps</translation>
    </message>
    <message>
        <source>All</source>
        <translation>Alle</translation>
    </message>
    <message>
        <source>None</source>
        <translation>Keine</translation>
    </message>
    <message>
        <source>Skip baud rates where nothing answers a broadcast PING</source>
        <translation>Baudraten überspringen, bei denen nichts auf einen Broadcast-PING antwortet</translation>
    </message>
    <message>
        <source>Every servo answers a broadcast PING. When no byte at all comes back at a rate, no servo listens there and its IDs need not be asked one by one. Turn off to ask every ID regardless.</source>
        <translation>Jedes Servo antwortet auf einen Broadcast-PING. Kommt bei einer Rate überhaupt kein Byte zurück, hört dort kein Servo zu, und die IDs müssen dort nicht einzeln abgefragt werden. Ausschalten, um trotzdem jede ID abzufragen.</translation>
    </message>
    <message>
        <source>Scan</source>
        <translation>Scannen</translation>
    </message>
    <message>
        <source>Choose at least one baud rate.</source>
        <translation>Wählen Sie mindestens eine Baudrate.</translation>
    </message>
    <message numerus="yes">
        <source>%n ID(s) at %1 baud rate(s). Missing IDs cost a few milliseconds each: the wait adapts to how fast the servos answer.</source>
        <translation>
            <numerusform>%n ID bei %1 Baudrate(n). Fehlende IDs kosten je einige Millisekunden: Die Wartezeit passt sich daran an, wie schnell die Servos antworten.</numerusform>
            <numerusform>%n IDs bei %1 Baudrate(n). Fehlende IDs kosten je einige Millisekunden: Die Wartezeit passt sich daran an, wie schnell die Servos antworten.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>SerialLink</name>
    <message>
        <source>%1 does not exist. Is the adapter plugged in?</source>
        <translation>%1 existiert nicht. Ist der Adapter eingesteckt?</translation>
    </message>
    <message>
        <source>Permission denied on %1. Either another program has it open, or you are not in the group that may use serial ports: run &quot;sudo usermod -aG dialout $USER&quot;, then log out and back in.</source>
        <translation>Zugriff auf %1 verweigert. Entweder hat ein anderes Programm den Anschluss geöffnet, oder Sie sind nicht in der Gruppe, die serielle Anschlüsse verwenden darf: Führen Sie &quot;sudo usermod -aG dialout $USER&quot; aus, melden Sie sich dann ab und wieder an.</translation>
    </message>
    <message>
        <source>Permission denied on %1: another program may have it open.</source>
        <translation>Zugriff auf %1 verweigert: Möglicherweise hat ein anderes Programm den Anschluss geöffnet.</translation>
    </message>
    <message>
        <source>%1 is already open.</source>
        <translation>%1 ist bereits geöffnet.</translation>
    </message>
    <message>
        <source>%1 is not open.</source>
        <translation>%1 ist nicht geöffnet.</translation>
    </message>
    <message>
        <source>Could not write to %1 (%2).</source>
        <translation>Schreiben auf %1 fehlgeschlagen (%2).</translation>
    </message>
    <message>
        <source>Could not read from %1 (%2).</source>
        <translation>Lesen von %1 fehlgeschlagen (%2).</translation>
    </message>
    <message>
        <source>%1 went away: the adapter was unplugged or the device closed.</source>
        <translation>%1 ist verschwunden: Der Adapter wurde abgezogen oder das Gerät geschlossen.</translation>
    </message>
    <message>
        <source>%1 does not support this setting (%2).</source>
        <translation>%1 unterstützt diese Einstellung nicht (%2).</translation>
    </message>
    <message>
        <source>%1 timed out.</source>
        <translation>Zeitüberschreitung bei %1.</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
</context>
<context>
    <name>ServoControlGroups</name>
    <message>
        <source>Torque</source>
        <translation>Drehmoment</translation>
    </message>
    <message>
        <source>Off</source>
        <translation>Aus</translation>
    </message>
    <message>
        <source>Torque off: the horn turns freely (torque enable 0).</source>
        <translation>Drehmoment aus: Das Servohorn dreht sich frei (torque enable 0).</translation>
    </message>
    <message>
        <source>On</source>
        <translation>Ein</translation>
    </message>
    <message>
        <source>Torque on: the servo holds its goal position (torque enable 1).</source>
        <translation>Drehmoment ein: Das Servo hält seine Zielposition (torque enable 1).</translation>
    </message>
    <message>
        <source>Damping</source>
        <translation>Dämpfung</translation>
    </message>
    <message>
        <source>Damping: the horn can be turned by hand against a resistance (torque enable 2).</source>
        <translation>Dämpfung: Das Servohorn lässt sich von Hand gegen einen Widerstand drehen (torque enable 2).</translation>
    </message>
    <message>
        <source>Operating mode</source>
        <translation>Betriebsart</translation>
    </message>
    <message>
        <source>How the servo uses its goal registers. Stored in EEPROM.</source>
        <translation>Wie das Servo seine Zielregister nutzt. Im EEPROM gespeichert.</translation>
    </message>
    <message>
        <source>Set mode…</source>
        <translation>Betriebsart setzen…</translation>
    </message>
    <message>
        <source>Write the chosen operating mode to the servo&apos;s EEPROM.</source>
        <translation>Die gewählte Betriebsart ins EEPROM des Servos schreiben.</translation>
    </message>
    <message>
        <source>Goal position</source>
        <translation>Zielposition</translation>
    </message>
    <message>
        <source>Drag to move the servo: goals are sent as fast as the servo confirms them, always the newest one.</source>
        <translation>Ziehen, um das Servo zu bewegen: Ziele werden so schnell gesendet, wie das Servo sie bestätigt, immer das neueste.</translation>
    </message>
    <message>
        <source>Move</source>
        <translation>Bewegen</translation>
    </message>
    <message>
        <source>Send this goal position with the speed and acceleration below.</source>
        <translation>Diese Zielposition mit der Geschwindigkeit und Beschleunigung unten senden.</translation>
    </message>
    <message>
        <source>Where the horn is: the monitor&apos;s newest sample, or the last read of the present position.</source>
        <translation>Wo das Servohorn steht: der neueste Messwert des Monitors oder der zuletzt gelesene Wert der aktuellen Position.</translation>
    </message>
    <message>
        <source>Goal</source>
        <translation>Ziel</translation>
    </message>
    <message>
        <source>Present</source>
        <translation>Aktuell</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>Geschwindigkeit</translation>
    </message>
    <message>
        <source>Acceleration</source>
        <translation>Beschleunigung</translation>
    </message>
    <message>
        <source>Goal speed (0: the servo&apos;s maximum). The arrows move by one step of the register.</source>
        <translation>Zielgeschwindigkeit (0: Maximum des Servos). Die Pfeile ändern den Wert um einen Registerschritt.</translation>
    </message>
    <message>
        <source>Acceleration (0: the servo&apos;s maximum). The arrows move by one step of the register.</source>
        <translation>Beschleunigung (0: Maximum des Servos). Die Pfeile ändern den Wert um einen Registerschritt.</translation>
    </message>
</context>
<context>
    <name>ServoHealth</name>
    <message>
        <source>bit %1</source>
        <translation>Bit %1</translation>
    </message>
    <message>
        <source>The servo reports a %1 error (status bit %2): its protection tripped.</source>
        <translation>Das Servo meldet einen Fehler: %1 (Statusbit %2); seine Schutzfunktion hat ausgelöst.</translation>
    </message>
    <message>
        <source>The supply reads %1 V, above the servo&apos;s maximum of %2 V: use a supply the servo is made for.</source>
        <translation>Die Versorgungsspannung beträgt %1 V, über dem Maximum des Servos von %2 V: Verwenden Sie eine Versorgung, für die das Servo ausgelegt ist.</translation>
    </message>
    <message>
        <source>The supply reads %1 V, below the servo&apos;s minimum of %2 V: charge the battery or check the supply and its wires.</source>
        <translation>Die Versorgungsspannung beträgt %1 V, unter dem Minimum des Servos von %2 V: Laden Sie den Akku oder prüfen Sie die Versorgung und ihre Leitungen.</translation>
    </message>
    <message>
        <source>The supply reads %1 V, close to the servo&apos;s maximum of %2 V.</source>
        <translation>Die Versorgungsspannung beträgt %1 V, nahe am Maximum des Servos von %2 V.</translation>
    </message>
    <message>
        <source>The supply reads %1 V, close to the servo&apos;s minimum of %2 V.</source>
        <translation>Die Versorgungsspannung beträgt %1 V, nahe am Minimum des Servos von %2 V.</translation>
    </message>
    <message>
        <source>The servo is at %1 °C, at or over its maximum of %2 °C: let it cool and look for what makes it work so hard.</source>
        <translation>Das Servo hat %1 °C, am oder über seinem Maximum von %2 °C: Lassen Sie es abkühlen und suchen Sie die Ursache der hohen Belastung.</translation>
    </message>
    <message>
        <source>The servo is at %1 °C, within %2 °C of its maximum of %3 °C.</source>
        <translation>Das Servo hat %1 °C, weniger als %2 °C unter seinem Maximum von %3 °C.</translation>
    </message>
    <message numerus="yes">
        <source>None of %n feedback read(s) was answered: check the servo&apos;s cable and power.</source>
        <translation>
            <numerusform>Die Rückmeldeabfrage wurde nicht beantwortet: Prüfen Sie Kabel und Stromversorgung des Servos.</numerusform>
            <numerusform>Keine der %n Rückmeldeabfragen wurde beantwortet: Prüfen Sie Kabel und Stromversorgung des Servos.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%1 of %n feedback read(s) went unanswered even after retries (%2): check the cable, its connectors and the bus&apos;s length.</source>
        <translation>
            <numerusform>%1 von %n Rückmeldeabfrage blieb auch nach Wiederholungen unbeantwortet (%2): Prüfen Sie das Kabel, seine Stecker und die Länge des Busses.</numerusform>
            <numerusform>%1 von %n Rückmeldeabfragen blieben auch nach Wiederholungen unbeantwortet (%2): Prüfen Sie das Kabel, seine Stecker und die Länge des Busses.</numerusform>
        </translation>
    </message>
    <message>
        <source>Every read was answered, but not at the first try (%1): the line is noisy or marginal.</source>
        <translation>Jede Abfrage wurde beantwortet, aber nicht beim ersten Versuch (%1): Die Leitung ist gestört oder grenzwertig.</translation>
    </message>
    <message>
        <source>OK</source>
        <translation>OK</translation>
    </message>
    <message>
        <source>Warning</source>
        <translation>Warnung</translation>
    </message>
    <message>
        <source>Fault</source>
        <translation>Fehler</translation>
    </message>
    <message>
        <source>Its settings could not be read: %1</source>
        <translation>Seine Einstellungen konnten nicht gelesen werden: %1</translation>
    </message>
    <message>
        <source>ServoBench has no register table for model %1: only its answers are checked.</source>
        <translation>ServoBench hat keine Registertabelle für Modell %1: Nur seine Antworten werden geprüft.</translation>
    </message>
    <message>
        <source>The servo works at %1 % load while the check reads it, at or over its overload level of %2 %: something pushes against the horn.</source>
        <translation>Das Servo arbeitet während der Prüfung mit %1 % Last, am oder über seiner Überlastschwelle von %2 %: Etwas drückt gegen das Servohorn.</translation>
    </message>
    <message>
        <source>The horn stands at %1, outside its angle limits %2 to %3: it cannot be sent back there, and the limits may be wrong.</source>
        <translation>Das Servohorn steht bei %1, außerhalb seiner Winkelgrenzen %2 bis %3: Es kann nicht dorthin zurückgeschickt werden, und die Grenzen sind möglicherweise falsch.</translation>
    </message>
    <message>
        <source>The move test did not complete: %1</source>
        <translation>Der Bewegungstest wurde nicht abgeschlossen: %1</translation>
    </message>
    <message>
        <source>The horn did not follow a move of %1 steps from %2 to %3: it may be blocked, or its torque is limited.</source>
        <translation>Das Servohorn folgte einer Bewegung um %1 Schritte von %2 nach %3 nicht: Es ist möglicherweise blockiert, oder sein Drehmoment ist begrenzt.</translation>
    </message>
    <message>
        <source>The move overshot by %1 %: its gains may be too high.</source>
        <translation>Die Bewegung schwang um %1 % über: Die Verstärkungen sind möglicherweise zu hoch.</translation>
    </message>
    <message>
        <source>The horn stopped %1 steps from its goal: a load holds it off, or its dead zone is wide.</source>
        <translation>Das Servohorn blieb %1 Schritte vor seinem Ziel stehen: Eine Last hält es zurück, oder seine Totzone ist breit.</translation>
    </message>
    <message>
        <source>servo %1 has %2</source>
        <translation>Servo %1 hat %2</translation>
    </message>
    <message>
        <source>Its firmware %1 differs from other %2 servos on the bus (%3): they may behave differently with the same settings.</source>
        <translation>Seine Firmware %1 unterscheidet sich von anderen %2-Servos am Bus (%3): Sie verhalten sich mit denselben Einstellungen möglicherweise unterschiedlich.</translation>
    </message>
    <message>
        <source>%1/%2 answered, %3 retries, %4 timeouts, %5 checksum errors</source>
        <translation>%1/%2 beantwortet, %3 Wiederholungen, %4 Zeitüberschreitungen, %5 Prüfsummenfehler</translation>
    </message>
    <message>
        <source>not measured</source>
        <translation>nicht gemessen</translation>
    </message>
    <message>
        <source>none</source>
        <translation>keine</translation>
    </message>
    <message>
        <source>%1 → %2: rise %3, overshoot %4, steady-state error %5</source>
        <translation>%1 → %2: Anstieg %3, Überschwingen %4, bleibende Regelabweichung %5</translation>
    </message>
    <message>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <source>%1 %</source>
        <translation>%1 %</translation>
    </message>
    <message>
        <source>%1 steps</source>
        <translation>%1 Schritte</translation>
    </message>
</context>
<context>
    <name>ServoTree</name>
    <message>
        <source>Servo</source>
        <translation>Servo</translation>
    </message>
    <message>
        <source>Model</source>
        <translation>Modell</translation>
    </message>
    <message>
        <source>Family</source>
        <translation>Familie</translation>
    </message>
    <message>
        <source>Firmware</source>
        <translation>Firmware</translation>
    </message>
    <message>
        <source>Bus</source>
        <translation>Bus</translation>
    </message>
    <message>
        <source>unknown</source>
        <translation>unbekannt</translation>
    </message>
    <message>
        <source>ID %1 (shared!)</source>
        <translation>ID %1 (geteilt!)</translation>
    </message>
    <message>
        <source>Two or more servos answer at ID %1: their replies come back garbled. Nothing is written to this ID while it is shared; connect them one at a time and give each its own ID.</source>
        <translation>Zwei oder mehr Servos antworten unter ID %1: Ihre Antworten kommen verstümmelt zurück. Solange die ID geteilt ist, wird nichts an sie geschrieben; schließen Sie die Servos einzeln an und geben Sie jedem seine eigene ID.</translation>
    </message>
    <message>
        <source>It answers with error bits: %1 (the Doctor says why).</source>
        <translation>Es antwortet mit Fehlerbits: %1 (der Doktor sagt, warum).</translation>
    </message>
    <message>
        <source>Model number %1 (major %2, minor %3)</source>
        <translation>Modellnummer %1 (Major %2, Minor %3)</translation>
    </message>
    <message>
        <source>No register table is known for this model: its memory is shown as raw bytes, read-only.</source>
        <translation>Für dieses Modell ist keine Registertabelle bekannt: Sein Speicher wird als Rohbytes angezeigt, schreibgeschützt.</translation>
    </message>
    <message>
        <source>The servos are the joints of the %1</source>
        <translation>Die Servos sind die Gelenke dieses Roboters: %1</translation>
    </message>
</context>
<context>
    <name>SettingsCheck</name>
    <message>
        <source>not written: torque is on, and writing %1 could move the horn; switch the torque off first</source>
        <translation>nicht geschrieben: Das Drehmoment ist an, und das Schreiben von %1 könnte das Servohorn bewegen; schalten Sie das Drehmoment zuerst ab</translation>
    </message>
    <message>
        <source>written, but it reads back %1, not %2</source>
        <translation>geschrieben, aber zurückgelesen ergibt sich %1, nicht %2</translation>
    </message>
    <message>
        <source>not verified: %1</source>
        <translation>nicht überprüft: %1</translation>
    </message>
    <message>
        <source>ServoBench has no register table for model %1.</source>
        <translation>ServoBench hat keine Registertabelle für Modell %1.</translation>
    </message>
    <message>
        <source>nothing to write fixes this</source>
        <translation>kein Schreibvorgang behebt dies</translation>
    </message>
    <message>
        <source>not written: servo %1 does not answer (%2); check its cable and power</source>
        <translation>nicht geschrieben: Servo %1 antwortet nicht (%2); prüfen Sie Kabel und Stromversorgung</translation>
    </message>
    <message>
        <source>%1 is %2; %3 sets %4 (a RAM register: it is lost at power-off and set again at every connect).</source>
        <translation>%1 ist %2; %3 setzt %4 (ein RAM-Register: Es geht beim Ausschalten verloren und wird bei jedem Verbinden neu gesetzt).</translation>
    </message>
    <message>
        <source>%1 is %2; %3 sets %4.</source>
        <translation>%1 ist %2; %3 setzt %4.</translation>
    </message>
    <message>
        <source>%1 is %2 with bits 0x%3 set; %4 clears them.</source>
        <translation>%1 ist %2 mit gesetzten Bits 0x%3; %4 löscht sie.</translation>
    </message>
    <message>
        <source>Phase bit 4 is set: the servo counts whole turns, so its position leaves 0-4095 and goals and calibration no longer match it.</source>
        <translation>Phasen-Bit 4 ist gesetzt: Das Servo zählt ganze Umdrehungen, daher verlässt seine Position 0-4095, und Ziele und Kalibrierung passen nicht mehr dazu.</translation>
    </message>
    <message>
        <source>The torque limit is 0: the servo has no force to move with.</source>
        <translation>Die Drehmomentgrenze ist 0: Das Servo hat keine Kraft, um sich zu bewegen.</translation>
    </message>
    <message>
        <source>The maximum torque is 0: at every power-on the torque limit starts at 0, and the servo does not move.</source>
        <translation>Das maximale Drehmoment ist 0: Bei jedem Einschalten beginnt die Drehmomentgrenze bei 0, und das Servo bewegt sich nicht.</translation>
    </message>
    <message>
        <source>The operating mode is %1, not position (0): a joint does not follow its goal position.</source>
        <translation>Der Betriebsmodus ist %1, nicht Position (0): Ein Gelenk folgt seiner Zielposition nicht.</translation>
    </message>
    <message>
        <source>Both angle limits are 0: the servo turns without end (multi-turn or wheel), not as a joint.</source>
        <translation>Beide Winkelgrenzen sind 0: Das Servo dreht endlos (Multiturn oder Rad), nicht als Gelenk.</translation>
    </message>
    <message>
        <source>The minimum angle limit %1 is not below the maximum %2: the servo refuses every goal.</source>
        <translation>Die untere Winkelgrenze %1 liegt nicht unter der oberen %2: Das Servo lehnt jedes Ziel ab.</translation>
    </message>
    <message>
        <source>The servo waits %1 µs before each answer: every read of the bus is that much slower.</source>
        <translation>Das Servo wartet vor jeder Antwort %1 µs: Jeder Lesevorgang am Bus wird um so viel langsamer.</translation>
    </message>
    <message>
        <source>The EEPROM is unlocked: a stray write would change settings for good.</source>
        <translation>Das EEPROM ist entsperrt: Ein versehentlicher Schreibvorgang würde Einstellungen dauerhaft ändern.</translation>
    </message>
    <message>
        <source>The supply reads %1 V, above the maximum voltage setting of %2 V: the servo reports a voltage error and may not move. Use a supply it is made for, or raise the limit if it is a higher-voltage model.</source>
        <translation>Die Versorgungsspannung beträgt %1 V, über der eingestellten Maximalspannung von %2 V: Das Servo meldet einen Spannungsfehler und bewegt sich womöglich nicht. Verwenden Sie eine Versorgung, für die es ausgelegt ist, oder heben Sie die Grenze an, wenn es ein Modell für höhere Spannung ist.</translation>
    </message>
    <message>
        <source>The supply reads %1 V, below the minimum voltage setting of %2 V: the servo reports a voltage error and may not move. Charge the battery or check the supply.</source>
        <translation>Die Versorgungsspannung beträgt %1 V, unter der eingestellten Minimalspannung von %2 V: Das Servo meldet einen Spannungsfehler und bewegt sich womöglich nicht. Laden Sie den Akku oder prüfen Sie die Versorgung.</translation>
    </message>
    <message>
        <source>Its settings could not be read: %1</source>
        <translation>Seine Einstellungen konnten nicht gelesen werden: %1</translation>
    </message>
    <message>
        <source>fixed, verified</source>
        <translation>behoben, überprüft</translation>
    </message>
</context>
<context>
    <name>SettingsCheckPanel</name>
    <message>
        <source>Finds the settings that stop a servo moving or make it misbehave: multi-turn phase bit, torque limits at 0, a mode other than position, angle limits, a slow return delay, an unlocked EEPROM, mixed firmware, voltage limits the supply breaks, and what differs from the robot template. It only reads; Fix writes the expected value and reads it back (limits, offset, mode, torque limit and phase only with torque off).</source>
        <translation>Findet die Einstellungen, die ein Servo an der Bewegung hindern oder es fehlerhaft arbeiten lassen: Multiturn-Phasenbit, Drehmomentgrenzen bei 0, ein anderer Betriebsmodus als Position, Winkelgrenzen, eine lange Antwortverzögerung, ein entsperrtes EEPROM, gemischte Firmware, Spannungsgrenzen, die die Versorgung verletzt, und was von der Robotervorlage abweicht. Es wird nur gelesen; „Beheben“ schreibt den erwarteten Wert und liest ihn zurück (Grenzen, Offset, Modus, Drehmomentgrenze und Phase nur bei abgeschaltetem Drehmoment).</translation>
    </message>
    <message>
        <source>Also compare the servos with this robot template&apos;s settings</source>
        <translation>Die Servos auch mit den Einstellungen dieser Robotervorlage vergleichen</translation>
    </message>
    <message>
        <source>No robot template</source>
        <translation>Keine Robotervorlage</translation>
    </message>
    <message>
        <source>Check settings</source>
        <translation>Einstellungen prüfen</translation>
    </message>
    <message>
        <source>Read the settings of every servo found</source>
        <translation>Die Einstellungen jedes gefundenen Servos lesen</translation>
    </message>
    <message>
        <source>Fix all</source>
        <translation>Alle beheben</translation>
    </message>
    <message>
        <source>Write the expected value of every finding that a write fixes, each read back</source>
        <translation>Für jeden Befund, den ein Schreibvorgang behebt, den erwarteten Wert schreiben und jeweils zurücklesen</translation>
    </message>
    <message>
        <source>Robot:</source>
        <translation>Roboter:</translation>
    </message>
    <message>
        <source>ID</source>
        <translation>ID</translation>
    </message>
    <message>
        <source>Setting</source>
        <translation>Einstellung</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>Wert</translation>
    </message>
    <message>
        <source>Expected</source>
        <translation>Erwartet</translation>
    </message>
    <message>
        <source>Why</source>
        <translation>Warum</translation>
    </message>
    <message>
        <source>Fix</source>
        <translation>Beheben</translation>
    </message>
    <message>
        <source>Result</source>
        <translation>Ergebnis</translation>
    </message>
    <message>
        <source>No problem found in the settings.</source>
        <translation>In den Einstellungen wurde kein Problem gefunden.</translation>
    </message>
    <message numerus="yes">
        <source>%n finding(s).</source>
        <translation>
            <numerusform>%n Befund.</numerusform>
            <numerusform>%n Befunde.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Reading the settings of %n servo(s)…</source>
        <translation>
            <numerusform>Einstellungen von %n Servo werden gelesen…</numerusform>
            <numerusform>Einstellungen von %n Servos werden gelesen…</numerusform>
        </translation>
    </message>
    <message>
        <source>There is no finding in row %1.</source>
        <translation>In Zeile %1 gibt es keinen Befund.</translation>
    </message>
    <message>
        <source>Writing and reading back…</source>
        <translation>Schreiben und Zurücklesen…</translation>
    </message>
    <message>
        <source>Nothing to write fixes this</source>
        <translation>Kein Schreibvorgang behebt dies</translation>
    </message>
    <message>
        <source>Write %1 = %2 to servo %3 and read it back</source>
        <translation>%1 = %2 auf Servo %3 schreiben und zurücklesen</translation>
    </message>
    <message>
        <source>Fixed, verified</source>
        <translation>Behoben, überprüft</translation>
    </message>
    <message>
        <source>%1 Check again to see the servos as they are now.</source>
        <translation>%1 Prüfen Sie erneut, um die Servos in ihrem jetzigen Zustand zu sehen.</translation>
    </message>
</context>
<context>
    <name>SettingsFile</name>
    <message>
        <source>the file is too large for a profile or a robot template</source>
        <translation>die Datei ist zu groß für ein Profil oder eine Robotervorlage</translation>
    </message>
    <message>
        <source>servo %1 is of an unknown model (%2); nothing is written to it</source>
        <translation>Servo %1 hat ein unbekanntes Modell (%2); es wird nichts darauf geschrieben</translation>
    </message>
    <message>
        <source>%1 has no joint with ID %2</source>
        <translation>%1 hat kein Gelenk mit ID %2</translation>
    </message>
    <message>
        <source>joint %1 of %2 is a %3, but servo %4 is a %5</source>
        <translation>Gelenk %1 von %2 ist ein %3, aber Servo %4 ist ein %5</translation>
    </message>
    <message>
        <source>%1 does not fit servo %2: %3</source>
        <translation>%1 passt nicht zu Servo %2: %3</translation>
    </message>
    <message>
        <source>Not copied from the profile: %1 (each servo&apos;s own calibration, not a setting to copy; use a robot template or Load calibration for it).</source>
        <translation>Nicht aus dem Profil kopiert: %1 (die eigene Kalibrierung jedes Servos, keine Einstellung zum Kopieren; verwenden Sie dafür eine Robotervorlage oder Kalibrierung laden).</translation>
    </message>
    <message>
        <source>written and verified</source>
        <translation>geschrieben und überprüft</translation>
    </message>
    <message>
        <source>unchanged</source>
        <translation>unverändert</translation>
    </message>
    <message>
        <source>failed</source>
        <translation>fehlgeschlagen</translation>
    </message>
    <message>
        <source>torque is on: switch it off before changing the position offset, limits or phase</source>
        <translation>Drehmoment ist an: Schalten Sie es ab, bevor Sie Positionsoffset, Grenzen oder Phase ändern</translation>
    </message>
</context>
<context>
    <name>SetupWizard</name>
    <message>
        <source>Set up motors</source>
        <translation>Motoren einrichten</translation>
    </message>
    <message>
        <source>Robot:</source>
        <translation>Roboter:</translation>
    </message>
    <message>
        <source>Check the bus</source>
        <translation>Bus prüfen</translation>
    </message>
    <message>
        <source>Ask every joint&apos;s ID at the robot&apos;s rate: joints whose servo already answers there, as its model and with its settings, are done</source>
        <translation>Jede Gelenk-ID mit der Rate des Roboters abfragen: Gelenke, deren Servo dort bereits antwortet, als richtiges Modell und mit seinen Einstellungen, sind erledigt</translation>
    </message>
    <message>
        <source>Joint</source>
        <translation>Gelenk</translation>
    </message>
    <message>
        <source>ID</source>
        <translation>ID</translation>
    </message>
    <message>
        <source>Model</source>
        <translation>Modell</translation>
    </message>
    <message>
        <source>Status</source>
        <translation>Status</translation>
    </message>
    <message>
        <source>&amp;Find</source>
        <translation>&amp;Suchen</translation>
    </message>
    <message>
        <source>Look for the one servo on the bus, at every ID and baud rate; nothing is written</source>
        <translation>Das eine Servo am Bus suchen, bei jeder ID und Baudrate; es wird nichts geschrieben</translation>
    </message>
    <message>
        <source>&amp;Set up</source>
        <translation>&amp;Einrichten</translation>
    </message>
    <message>
        <source>Give the servo found the joint&apos;s ID, the robot&apos;s baud rate and the joint&apos;s settings, each read back</source>
        <translation>Dem gefundenen Servo die ID des Gelenks, die Baudrate des Roboters und die Einstellungen des Gelenks geben, jeweils zurückgelesen</translation>
    </message>
    <message>
        <source>S&amp;top</source>
        <translation>S&amp;topp</translation>
    </message>
    <message>
        <source>Stop before the next step; a step under way ends first, so the servo&apos;s EEPROM is always locked again</source>
        <translation>Vor dem nächsten Schritt anhalten; ein laufender Schritt wird zuerst beendet, damit das EEPROM des Servos immer wieder gesperrt ist</translation>
    </message>
    <message>
        <source>Done</source>
        <translation>Erledigt</translation>
    </message>
    <message>
        <source>Failed: %1</source>
        <translation>Fehlgeschlagen: %1</translation>
    </message>
    <message>
        <source>Current</source>
        <translation>Aktuell</translation>
    </message>
    <message>
        <source>To do</source>
        <translation>Ausstehend</translation>
    </message>
    <message>
        <source>Current, %1</source>
        <translation>Aktuell, %1</translation>
    </message>
    <message>
        <source>Not connected</source>
        <translation>Nicht verbunden</translation>
    </message>
    <message>
        <source>Open the Feetech port the servos are connected to first.</source>
        <translation>Öffnen Sie zuerst den Feetech-Anschluss, an dem die Servos angeschlossen sind.</translation>
    </message>
    <message>
        <source>All done</source>
        <translation>Alles erledigt</translation>
    </message>
    <message>
        <source>Every joint of the %1 is set up. Connect the servos in a chain and press &lt;i&gt;Check the bus&lt;/i&gt; to confirm them together.</source>
        <translation>Jedes Gelenk von %1 ist eingerichtet. Verbinden Sie die Servos in einer Kette und drücken Sie &lt;i&gt;Bus prüfen&lt;/i&gt;, um sie gemeinsam zu bestätigen.</translation>
    </message>
    <message>
        <source>Joint %1 of %2: %3</source>
        <translation>Gelenk %1 von %2: %3</translation>
    </message>
    <message>
        <source>Connect only the &lt;b&gt;%1&lt;/b&gt; servo (ID will be %2) and press &lt;i&gt;Find&lt;/i&gt;.&lt;br&gt;&lt;small&gt;Unplug every other servo from the bus first and keep the power on. A new servo answers at ID 1 and 1 Mbps; ServoBench finds it at any ID and rate.&lt;/small&gt;</source>
        <translation>Schließen Sie nur das Servo &lt;b&gt;%1&lt;/b&gt; an (die ID wird %2) und drücken Sie &lt;i&gt;Suchen&lt;/i&gt;.&lt;br&gt;&lt;small&gt;Trennen Sie zuerst alle anderen Servos vom Bus und lassen Sie die Stromversorgung eingeschaltet. Ein neues Servo antwortet bei ID 1 und 1 Mbps; ServoBench findet es bei jeder ID und Rate.&lt;/small&gt;</translation>
    </message>
    <message>
        <source>servo %1 at %2, model %3, firmware %4</source>
        <translation>Servo %1 bei %2, Modell %3, Firmware %4</translation>
    </message>
    <message>
        <source>Asking every joint&apos;s ID at %1…</source>
        <translation>Jede Gelenk-ID wird bei %1 abgefragt…</translation>
    </message>
    <message>
        <source>Looking for the servo at every baud rate…</source>
        <translation>Das Servo wird bei jeder Baudrate gesucht…</translation>
    </message>
    <message>
        <source>Stopping after this step…</source>
        <translation>Anhalten nach diesem Schritt…</translation>
    </message>
    <message>
        <source>Step %1 of %2: %3</source>
        <translation>Schritt %1 von %2: %3</translation>
    </message>
    <message>
        <source>Nothing was written to any servo.</source>
        <translation>Auf kein Servo wurde etwas geschrieben.</translation>
    </message>
    <message>
        <source>&lt;b&gt;Found one servo:&lt;/b&gt; %1.</source>
        <translation>&lt;b&gt;Ein Servo gefunden:&lt;/b&gt; %1.</translation>
    </message>
    <message>
        <source>It answers where %1 should: it may be the %1 servo, already set up. Set it up as %2 only if it is the %2 servo.</source>
        <translation>Es antwortet dort, wo %1 antworten sollte: Es könnte das bereits eingerichtete Servo %1 sein. Richten Sie es nur dann als %2 ein, wenn es das Servo %2 ist.</translation>
    </message>
    <message numerus="yes">
        <source>Press &lt;i&gt;Set up&lt;/i&gt; to give it ID %2, %3 and the %1 settings (%n value(s), each read back).</source>
        <translation>
            <numerusform>Drücken Sie &lt;i&gt;Einrichten&lt;/i&gt;, um ihm ID %2, %3 und die Einstellungen von %1 zu geben (%n Wert, zurückgelesen).</numerusform>
            <numerusform>Drücken Sie &lt;i&gt;Einrichten&lt;/i&gt;, um ihm ID %2, %3 und die Einstellungen von %1 zu geben (%n Werte, jeweils zurückgelesen).</numerusform>
        </translation>
    </message>
    <message>
        <source>Done before that:</source>
        <translation>Davor erledigt:</translation>
    </message>
    <message>
        <source>Unplug it and connect the next servo: &lt;b&gt;%1&lt;/b&gt;.</source>
        <translation>Trennen Sie es ab und schließen Sie das nächste Servo an: &lt;b&gt;%1&lt;/b&gt;.</translation>
    </message>
    <message>
        <source>Every joint is set up.</source>
        <translation>Alle Gelenke sind eingerichtet.</translation>
    </message>
    <message numerus="yes">
        <source>Checked the bus at %1: %2 of %n joint(s) set up.</source>
        <translation>
            <numerusform>Bus bei %1 geprüft: %2 von %n Gelenk eingerichtet.</numerusform>
            <numerusform>Bus bei %1 geprüft: %2 von %n Gelenken eingerichtet.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>ShareAlerts</name>
    <message>
        <source>Servo %1 reports overload: it stopped holding (torque off) until it is switched on again. Look for a blocked joint or a load too heavy for it.</source>
        <translation>Servo %1 meldet Überlast: es hält nicht mehr (Drehmoment aus), bis es wieder eingeschaltet wird. Nach einem blockierten Gelenk oder einer zu schweren Last suchen.</translation>
    </message>
    <message>
        <source>Servo %1 answers with error bits set: %2.</source>
        <translation>Servo %1 antwortet mit gesetzten Fehlerbits: %2.</translation>
    </message>
    <message>
        <source>Answers at ID %1 come garbled again and again: two servos may share this ID. Connect them one at a time and give each its own ID.</source>
        <translation>Antworten unter ID %1 kommen immer wieder verstümmelt: zwei Servos teilen sich womöglich diese ID. Sie einzeln anschließen und jedem eine eigene ID geben.</translation>
    </message>
    <message>
        <source>Servo %1 is at %2 °C, within %3 °C of its maximum (%4 °C): it will soon cut its torque. Let it cool, or lighten its load.</source>
        <translation>Servo %1 hat %2 °C, weniger als %3 °C unter seinem Maximum (%4 °C): es schaltet bald sein Drehmoment ab. Abkühlen lassen oder die Last verringern.</translation>
    </message>
    <message>
        <source>Servo %1 measures %2 V, outside its limits %3-%4 V: check the supply.</source>
        <translation>Servo %1 misst %2 V, außerhalb seiner Grenzen %3-%4 V: die Versorgung prüfen.</translation>
    </message>
    <message>
        <source>The program set phase bit 4 of servo %1 (multi-turn): its positions will leave 0-4095 and a calibration made without it no longer fits.</source>
        <translation>Das Programm hat Phasen-Bit 4 von Servo %1 gesetzt (Mehrfachumdrehung): seine Positionen verlassen 0-4095, und eine Kalibrierung ohne dieses Bit passt nicht mehr.</translation>
    </message>
    <message>
        <source>The program switched torque on at servo %1 with its goal %2 steps from where it stands (%3 → %4): the horn jumps.</source>
        <translation>Das Programm hat das Drehmoment von Servo %1 eingeschaltet, während sein Ziel %2 Schritte von seiner Stellung entfernt ist (%3 → %4): das Horn springt.</translation>
    </message>
    <message>
        <source>The program unlocked the EEPROM of servo %1 and has not locked it again: a stray write now changes its settings for good.</source>
        <translation>Das Programm hat das EEPROM von Servo %1 entsperrt und nicht wieder gesperrt: ein versehentlicher Schreibvorgang ändert seine Einstellungen jetzt dauerhaft.</translation>
    </message>
</context>
<context>
    <name>ShareCommand</name>
    <message>
        <source>share takes no --%1</source>
        <translation>share kennt kein --%1</translation>
    </message>
    <message>
        <source>share takes no arguments besides its options</source>
        <translation>share nimmt außer seinen Optionen keine Argumente</translation>
    </message>
    <message>
        <source>share needs --port: the adapter the servos are on</source>
        <translation>share braucht --port: den Adapter, an dem die Servos hängen</translation>
    </message>
    <message>
        <source>share needs --link PATH: the path the other program opens</source>
        <translation>share braucht --link PFAD: den Pfad, den das andere Programm öffnet</translation>
    </message>
    <message>
        <source>Sharing %1 at %2 baud: give the other program %3 (%4). Ctrl-C ends.</source>
        <translation>%1 wird mit %2 Baud geteilt: dem anderen Programm %3 (%4) geben. Strg-C beendet.</translation>
    </message>
    <message>
        <source>alert %1 at ID %2: %3</source>
        <translation>Warnung %1 bei ID %2: %3</translation>
    </message>
    <message>
        <source>Output: %1.</source>
        <translation>Ausgabe: %1.</translation>
    </message>
</context>
<context>
    <name>ShareDialog</name>
    <message>
        <source>Share this bus</source>
        <translation>Diesen Bus teilen</translation>
    </message>
    <message>
        <source>ServoBench keeps the port and gives another program (LeRobot, a script) a port of its own: open the path below in it. Every byte passes both ways unchanged. Its traffic shows in the packet log, its servos in the servo tree, its reads of position, load, voltage and temperature in the Monitor, without a read of ServoBench&apos;s own. ServoBench&apos;s operations wait for the gaps between its transactions; a scan or a new baud rate waits until sharing stops; All torque off always goes.</source>
        <translation>ServoBench behält den Port und gibt einem anderen Programm (LeRobot, einem Skript) einen eigenen Port: Öffnen Sie darin den Pfad unten. Jedes Byte läuft unverändert in beide Richtungen. Sein Datenverkehr erscheint im Paketprotokoll, seine Servos im Servobaum, seine Lesevorgänge von Position, Last, Spannung und Temperatur im Monitor, ohne einen eigenen Lesevorgang von ServoBench. Die Operationen von ServoBench warten auf die Lücken zwischen seinen Transaktionen; ein Scan oder eine neue Baudrate wartet, bis die Freigabe endet; „Alle Drehmomente aus“ geht immer durch.</translation>
    </message>
    <message>
        <source>The path the other program opens as its serial port</source>
        <translation>Der Pfad, den das andere Programm als seinen seriellen Port öffnet</translation>
    </message>
    <message>
        <source>&amp;Copy path</source>
        <translation>Pfad &amp;kopieren</translation>
    </message>
    <message>
        <source>No recording</source>
        <translation>Keine Aufzeichnung</translation>
    </message>
    <message>
        <source>Every frame with its time and direction; the packet log&apos;s Open recording… shows it</source>
        <translation>Jeder Frame mit Zeit und Richtung; „Aufzeichnung öffnen…“ im Paketprotokoll zeigt sie an</translation>
    </message>
    <message>
        <source>C&amp;hoose…</source>
        <translation>&amp;Auswählen…</translation>
    </message>
    <message>
        <source>&amp;Watch: read the program&apos;s servos in its idle gaps</source>
        <translation>&amp;Beobachten: die Servos des Programms in seinen Pausen lesen</translation>
    </message>
    <message>
        <source>One READ at a time, only while the program leaves the bus quiet, so alerts also cover what the program does not read itself</source>
        <translation>Jeweils ein READ, nur solange das Programm den Bus ruhen lässt, damit Warnungen auch abdecken, was das Programm nicht selbst liest</translation>
    </message>
    <message>
        <source>Path for the other program:</source>
        <translation>Pfad für das andere Programm:</translation>
    </message>
    <message>
        <source>Recording file:</source>
        <translation>Aufzeichnungsdatei:</translation>
    </message>
    <message>
        <source>Alerts:</source>
        <translation>Warnungen:</translation>
    </message>
    <message>
        <source>Copied %1: paste it as the other program&apos;s port.</source>
        <translation>%1 kopiert: Fügen Sie es als Port des anderen Programms ein.</translation>
    </message>
    <message>
        <source>Record the shared bus to</source>
        <translation>Geteilten Bus aufzeichnen in</translation>
    </message>
    <message>
        <source>Share recordings (*.txt);;All files (*)</source>
        <translation>Freigabeaufzeichnungen (*.txt);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>&amp;Start sharing</source>
        <translation>Freigabe &amp;starten</translation>
    </message>
    <message>
        <source>Not sharing.</source>
        <translation>Keine Freigabe.</translation>
    </message>
    <message>
        <source>Connect to a Feetech bus first.</source>
        <translation>Verbinden Sie sich zuerst mit einem Feetech-Bus.</translation>
    </message>
    <message>
        <source>&amp;Stop sharing</source>
        <translation>Freigabe &amp;beenden</translation>
    </message>
    <message>
        <source>Starting…</source>
        <translation>Wird gestartet…</translation>
    </message>
    <message>
        <source>Sharing at %1 baud: give the other program %2 (the pseudo-terminal %3).</source>
        <translation>Geteilt mit %1 Baud: Geben Sie dem anderen Programm %2 (das Pseudo-Terminal %3).</translation>
    </message>
    <message>
        <source>From the program: %1 frame(s). Back to it: %2 frame(s). Unanswered: %3. Garbled bytes: %4. Alerts: %5. Watch reads: %6.</source>
        <translation>Vom Programm: %1 Frame(s). Zurück: %2 Frame(s). Unbeantwortet: %3. Verstümmelte Bytes: %4. Warnungen: %5. Beobachtungs-Lesevorgänge: %6.</translation>
    </message>
    <message>
        <source>%1  ID %2: %3</source>
        <translation>%1  ID %2: %3</translation>
    </message>
</context>
<context>
    <name>ShareLogEntries</name>
    <message>
        <source>Shared bus: %1</source>
        <translation>Geteilter Bus: %1</translation>
    </message>
    <message>
        <source>Not a whole frame (passed on to the other program)</source>
        <translation>Kein vollständiger Frame (an das andere Programm weitergegeben)</translation>
    </message>
    <message>
        <source>Not a whole frame</source>
        <translation>Kein vollständiger Frame</translation>
    </message>
    <message>
        <source>Other program: %1</source>
        <translation>Anderes Programm: %1</translation>
    </message>
    <message>
        <source>ServoBench (shared bus): %1</source>
        <translation>ServoBench (geteilter Bus): %1</translation>
    </message>
</context>
<context>
    <name>ShareRecording</name>
    <message>
        <source>it is larger than any recording (1 GiB)</source>
        <translation>sie ist größer als jede Aufzeichnung (1 GiB)</translation>
    </message>
    <message>
        <source>line %1 is not &quot;&lt;seconds&gt; &lt;direction&gt; &lt;hex&gt;&quot;</source>
        <translation>Zeile %1 ist nicht &quot;&lt;seconds&gt; &lt;direction&gt; &lt;hex&gt;&quot;</translation>
    </message>
    <message>
        <source>this is no ServoBench share recording</source>
        <translation>dies ist keine ServoBench-Freigabeaufzeichnung</translation>
    </message>
</context>
<context>
    <name>ShareRecordingWindow</name>
    <message>
        <source>Recording %1</source>
        <translation>Aufzeichnung %1</translation>
    </message>
    <message numerus="yes">
        <source>%n frame(s) and note(s) from %1, in the order they passed; the time is seconds since sharing began.</source>
        <translation>
            <numerusform>%n Eintrag (Frame oder Hinweis) aus %1; die Zeit ist in Sekunden seit Beginn der Freigabe angegeben.</numerusform>
            <numerusform>%n Frames und Hinweise aus %1, in der Reihenfolge ihres Durchlaufs; die Zeit ist in Sekunden seit Beginn der Freigabe angegeben.</numerusform>
        </translation>
    </message>
    <message>
        <source>Time (s)</source>
        <translation>Zeit (s)</translation>
    </message>
    <message>
        <source>From</source>
        <translation>Von</translation>
    </message>
    <message>
        <source>Bytes</source>
        <translation>Bytes</translation>
    </message>
    <message>
        <source>Meaning</source>
        <translation>Bedeutung</translation>
    </message>
    <message>
        <source>Error</source>
        <translation>Fehler</translation>
    </message>
    <message>
        <source>program → bus</source>
        <translation>Programm → Bus</translation>
    </message>
    <message>
        <source>bus → program</source>
        <translation>Bus → Programm</translation>
    </message>
    <message>
        <source>ServoBench → bus</source>
        <translation>ServoBench → Bus</translation>
    </message>
    <message>
        <source>bus → ServoBench</source>
        <translation>Bus → ServoBench</translation>
    </message>
    <message>
        <source>note</source>
        <translation>Hinweis</translation>
    </message>
</context>
<context>
    <name>SharedIdCheck</name>
    <message>
        <source>Two or more servos answer at ID %1 (their replies come back garbled): nothing is written to it while it is shared. Connect them one at a time and give each its own ID.</source>
        <translation>Zwei oder mehr Servos antworten unter ID %1 (ihre Antworten kommen verstümmelt zurück): Solange die ID geteilt ist, wird nichts an sie geschrieben. Schließen Sie die Servos einzeln an und geben Sie jedem seine eigene ID.</translation>
    </message>
</context>
<context>
    <name>ShortcutsDialog</name>
    <message>
        <source>Keyboard shortcuts</source>
        <translation>Tastenkürzel</translation>
    </message>
    <message>
        <source>Keys</source>
        <translation>Tasten</translation>
    </message>
    <message>
        <source>Command</source>
        <translation>Befehl</translation>
    </message>
</context>
<context>
    <name>SimLog</name>
    <message>
        <source>cannot write the log %1: %2</source>
        <translation>das Protokoll %1 kann nicht geschrieben werden: %2</translation>
    </message>
</context>
<context>
    <name>SimulatorData</name>
    <message>
        <source>must be an object</source>
        <translation>muss ein Objekt sein</translation>
    </message>
    <message>
        <source>must be a whole number from %1 to %2</source>
        <translation>muss eine ganze Zahl von %1 bis %2 sein</translation>
    </message>
    <message>
        <source>the document is not a JSON object</source>
        <translation>das Dokument ist kein JSON-Objekt</translation>
    </message>
    <message>
        <source>is not a field of this file</source>
        <translation>ist kein Feld dieser Datei</translation>
    </message>
    <message>
        <source>must be %1</source>
        <translation>muss %1 sein</translation>
    </message>
    <message>
        <source>is not a Feetech family (scs, sts, sms, hls)</source>
        <translation>ist keine Feetech-Familie (scs, sts, sms, hls)</translation>
    </message>
    <message>
        <source>is not a field of a family</source>
        <translation>ist kein Feld einer Familie</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>%1: %2 %3</source>
        <translation>%1: %2 %3</translation>
    </message>
</context>
<context>
    <name>SimulatorDock</name>
    <message>
        <source>Simulator</source>
        <translation>Simulator</translation>
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
        <translation>Rate</translation>
    </message>
    <message>
        <source>Model</source>
        <translation>Modell</translation>
    </message>
    <message>
        <source>Position</source>
        <translation>Position</translation>
    </message>
    <message>
        <source>Torque</source>
        <translation>Drehmoment</translation>
    </message>
    <message>
        <source>Bench</source>
        <translation>Werkbank</translation>
    </message>
    <message>
        <source>The servos on the simulated bus, as they are now</source>
        <translation>Die Servos am simulierten Bus in ihrem aktuellen Zustand</translation>
    </message>
    <message>
        <source>Horn</source>
        <translation>Servohorn</translation>
    </message>
    <message>
        <source>Sweep</source>
        <translation>Schwenken</translation>
    </message>
    <message>
        <source>Where the hand starts, and comes back to</source>
        <translation>Wo die Hand beginnt und wohin sie zurückkehrt</translation>
    </message>
    <message>
        <source>Where the hand turns back</source>
        <translation>Wo die Hand umkehrt</translation>
    </message>
    <message>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <source>How long one sweep there and back takes</source>
        <translation>Wie lange ein Schwenk hin und zurück dauert</translation>
    </message>
    <message>
        <source>until let go</source>
        <translation>bis Loslassen</translation>
    </message>
    <message>
        <source>×</source>
        <translation>×</translation>
    </message>
    <message>
        <source>How many times; 0 sweeps until Let go</source>
        <translation>Wie oft; 0 schwenkt bis Loslassen</translation>
    </message>
    <message>
        <source>to</source>
        <translation>bis</translation>
    </message>
    <message>
        <source>The hand sweeps the selected joint from the first position to the second and back</source>
        <translation>Die Hand schwenkt das ausgewählte Gelenk von der ersten zur zweiten Position und zurück</translation>
    </message>
    <message>
        <source>Let go</source>
        <translation>Loslassen</translation>
    </message>
    <message>
        <source>The hand stops every sweep</source>
        <translation>Die Hand beendet jeden Schwenk</translation>
    </message>
    <message>
        <source>Plug in a factory-new servo…</source>
        <translation>Fabrikneues Servo anschließen…</translation>
    </message>
    <message>
        <source>Adds a servo as it comes from the factory: ID 1, its family&apos;s default rate</source>
        <translation>Fügt ein Servo im Auslieferungszustand hinzu: ID 1, Standardrate seiner Familie</translation>
    </message>
    <message>
        <source>Unplug</source>
        <translation>Abziehen</translation>
    </message>
    <message>
        <source>Takes the selected servo off the bus</source>
        <translation>Nimmt das ausgewählte Servo vom Bus</translation>
    </message>
    <message>
        <source>Put at ID…</source>
        <translation>Auf ID setzen…</translation>
    </message>
    <message>
        <source>Changes the selected servo&apos;s ID in its EEPROM, as a set-up would; two servos may then share one</source>
        <translation>Ändert die ID des ausgewählten Servos in seinem EEPROM, wie es eine Einrichtung täte; zwei Servos können sich dann eine ID teilen</translation>
    </message>
    <message>
        <source>Power-cycle</source>
        <translation>Aus- und einschalten</translation>
    </message>
    <message>
        <source>Switches the bus off and on: torque off, RAM back to its power-on values</source>
        <translation>Schaltet den Bus aus und wieder ein: Drehmoment aus, RAM zurück auf die Einschaltwerte</translation>
    </message>
    <message>
        <source>No simulated Feetech bus is running.</source>
        <translation>Es läuft kein simulierter Feetech-Bus.</translation>
    </message>
    <message>
        <source>The simulator refused.</source>
        <translation>Der Simulator hat abgelehnt.</translation>
    </message>
    <message>
        <source>Select a servo in the list first.</source>
        <translation>Wählen Sie zuerst ein Servo in der Liste aus.</translation>
    </message>
    <message>
        <source>on</source>
        <translation>ein</translation>
    </message>
    <message>
        <source>off, hand sweeping</source>
        <translation>aus, Hand schwenkt</translation>
    </message>
    <message>
        <source>off</source>
        <translation>aus</translation>
    </message>
    <message>
        <source>%1 V, %2 °C</source>
        <translation>%1 V, %2 °C</translation>
    </message>
    <message>
        <source>Select a servo to turn its horn by hand</source>
        <translation>Wählen Sie ein Servo, um sein Servohorn von Hand zu drehen</translation>
    </message>
    <message>
        <source>Servo #%1 has its torque on: it holds its position against the hand. Switch its torque off to turn it.</source>
        <translation>Servo #%1 hat Drehmoment an: Es hält seine Position gegen die Hand. Schalten Sie sein Drehmoment ab, um es zu drehen.</translation>
    </message>
    <message>
        <source>Turns servo #%1&apos;s horn by hand, as during a calibration</source>
        <translation>Dreht das Servohorn von Servo #%1 von Hand, wie bei einer Kalibrierung</translation>
    </message>
    <message>
        <source>Turned servo #%1 to %2.</source>
        <translation>Servo #%1 auf %2 gedreht.</translation>
    </message>
    <message>
        <source>The hand sweeps servo #%1 from %2 to %3 and back every %4 s.</source>
        <translation>Die Hand schwenkt Servo #%1 alle %4 s von %2 nach %3 und zurück.</translation>
    </message>
    <message>
        <source>The hand let go.</source>
        <translation>Die Hand hat losgelassen.</translation>
    </message>
    <message>
        <source>Plugged in a factory-new %1 at ID 1.</source>
        <translation>Fabrikneues %1 bei ID 1 angeschlossen.</translation>
    </message>
    <message>
        <source>Unplugged servo #%1.</source>
        <translation>Servo #%1 abgezogen.</translation>
    </message>
    <message>
        <source>Servo #%1 is now at ID %2.</source>
        <translation>Servo #%1 hat jetzt ID %2.</translation>
    </message>
    <message>
        <source>Power-cycled the simulated bus.</source>
        <translation>Simulierten Bus aus- und eingeschaltet.</translation>
    </message>
    <message>
        <source>Plug in a factory-new servo</source>
        <translation>Fabrikneues Servo anschließen</translation>
    </message>
    <message>
        <source>Model (it comes at ID 1, at its family&apos;s default rate):</source>
        <translation>Modell (es kommt mit ID 1 und der Standardrate seiner Familie):</translation>
    </message>
    <message>
        <source>Put at ID</source>
        <translation>Auf ID setzen</translation>
    </message>
    <message>
        <source>New ID for servo #%1 (another servo may have it too):</source>
        <translation>Neue ID für Servo #%1 (ein anderes Servo kann sie ebenfalls haben):</translation>
    </message>
    <message>
        <source>Bench case</source>
        <translation>Werkbank-Szenario</translation>
    </message>
    <message>
        <source>What goes wrong on a real bench, played on the selected servo or on the whole bus</source>
        <translation>Was auf einer echten Werkbank schiefgeht, abgespielt am ausgewählten Servo oder am ganzen Bus</translation>
    </message>
    <message>
        <source>Play</source>
        <translation>Abspielen</translation>
    </message>
    <message>
        <source>Plays the chosen bench case now</source>
        <translation>Spielt das gewählte Werkbank-Szenario jetzt ab</translation>
    </message>
    <message>
        <source>Plug back in</source>
        <translation>Wieder einstecken</translation>
    </message>
    <message>
        <source>Puts the servo unplugged last back on the bus, as it was</source>
        <translation>Steckt das zuletzt abgezogene Servo wieder an den Bus, so wie es war</translation>
    </message>
    <message>
        <source>ID %1 (%2)</source>
        <translation>ID %1 (%2)</translation>
    </message>
    <message>
        <source>Nothing was unplugged</source>
        <translation>Es wurde nichts abgezogen</translation>
    </message>
    <message>
        <source>Puts %1, unplugged last, back on the bus as it was</source>
        <translation>Steckt %1, zuletzt abgezogen, so wie es war wieder an den Bus</translation>
    </message>
    <message>
        <source>Plugged %1 back in.</source>
        <translation>%1 wieder eingesteckt.</translation>
    </message>
</context>
<context>
    <name>SkippableQuestion</name>
    <message>
        <source>Don&apos;t ask again</source>
        <translation>Nicht mehr fragen</translation>
    </message>
    <message>
        <source>View &gt; Ask skipped questions again brings it back</source>
        <translation>Ansicht &gt; Übersprungene Fragen wieder stellen holt sie zurück</translation>
    </message>
</context>
<context>
    <name>TelemetryPlot</name>
    <message>
        <source>There is nothing to export: choose at least one quantity to plot.</source>
        <translation>Es gibt nichts zu exportieren: Wählen Sie mindestens eine Größe zur Darstellung.</translation>
    </message>
    <message>
        <source>No file name was given for the image.</source>
        <translation>Für das Bild wurde kein Dateiname angegeben.</translation>
    </message>
    <message>
        <source>The plot could not be drawn into an image (it has no size).</source>
        <translation>Das Diagramm konnte nicht in ein Bild gezeichnet werden (es hat keine Größe).</translation>
    </message>
    <message>
        <source>Could not save the plot to %1: %2.</source>
        <translation>Das Diagramm konnte nicht unter %1 gespeichert werden: %2.</translation>
    </message>
    <message>
        <source>Drag across a time span to zoom in, right-click to zoom out, or turn the wheel; Reset zoom goes back to live data</source>
        <translation>Über eine Zeitspanne ziehen zum Vergrößern, Rechtsklick zum Verkleinern, oder das Mausrad drehen; Zoom zurücksetzen kehrt zu den Live-Daten zurück</translation>
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
        <translation>Zeit (s)</translation>
    </message>
</context>
<context>
    <name>TeleopDialog</name>
    <message>
        <source>Teleoperate</source>
        <translation>Teleoperation</translation>
    </message>
    <message>
        <source>Arms</source>
        <translation>Arme</translation>
    </message>
    <message>
        <source>The leader arm&apos;s adapter: a second port, not the one the window has open</source>
        <translation>Der Adapter des Führungsarms: ein zweiter Anschluss, nicht der, den das Fenster geöffnet hat</translation>
    </message>
    <message>
        <source>Re&amp;fresh</source>
        <translation>&amp;Aktualisieren</translation>
    </message>
    <message>
        <source>List the serial ports again</source>
        <translation>Die seriellen Anschlüsse erneut auflisten</translation>
    </message>
    <message>
        <source>The arm on %1 (the window&apos;s bus)</source>
        <translation>Der Arm an %1 (der Bus des Fensters)</translation>
    </message>
    <message>
        <source>None: connect to the follower arm&apos;s bus first</source>
        <translation>Keiner: Verbinden Sie sich zuerst mit dem Bus des Folgearms</translation>
    </message>
    <message>
        <source>A LeRobot calibration file (.json)</source>
        <translation>Eine LeRobot-Kalibrierdatei (.json)</translation>
    </message>
    <message>
        <source>Browse…</source>
        <translation>Durchsuchen…</translation>
    </message>
    <message>
        <source>The follower&apos;s calibration file</source>
        <translation>Die Kalibrierdatei des Folgearms</translation>
    </message>
    <message>
        <source>The leader&apos;s calibration file</source>
        <translation>Die Kalibrierdatei des Führungsarms</translation>
    </message>
    <message>
        <source> °/s</source>
        <translation> °/s</translation>
    </message>
    <message>
        <source>No joint of the follower moves faster, so it eases to the leader&apos;s pose at the start</source>
        <translation>Kein Gelenk des Folgearms bewegt sich schneller, sodass er zu Beginn sanft in die Pose des Führungsarms fährt</translation>
    </message>
    <message>
        <source> Hz</source>
        <translation> Hz</translation>
    </message>
    <message>
        <source>How often the leader is read; each reading is one write to the follower, as fast as the follower&apos;s bus takes them</source>
        <translation>Wie oft der Führungsarm gelesen wird; jeder Messwert ergibt einen Schreibvorgang auf den Folgearm, so schnell, wie der Bus des Folgearms sie aufnimmt</translation>
    </message>
    <message>
        <source>Follower:</source>
        <translation>Folgearm:</translation>
    </message>
    <message>
        <source>Follower&apos;s calibration:</source>
        <translation>Kalibrierung des Folgearms:</translation>
    </message>
    <message>
        <source>Leader port:</source>
        <translation>Anschluss des Führungsarms:</translation>
    </message>
    <message>
        <source>Leader&apos;s calibration:</source>
        <translation>Kalibrierung des Führungsarms:</translation>
    </message>
    <message>
        <source>Maximum speed:</source>
        <translation>Höchstgeschwindigkeit:</translation>
    </message>
    <message>
        <source>Rate:</source>
        <translation>Rate:</translation>
    </message>
    <message>
        <source>&amp;Start</source>
        <translation>&amp;Starten</translation>
    </message>
    <message>
        <source>Check both arms against their files, hold the follower where it stands, then follow the leader</source>
        <translation>Beide Arme mit ihren Dateien abgleichen, den Folgearm an seiner Stelle halten und dann dem Führungsarm folgen</translation>
    </message>
    <message>
        <source>S&amp;top</source>
        <translation>S&amp;topp</translation>
    </message>
    <message>
        <source>Stop following: the follower holds where it is</source>
        <translation>Folgen beenden: Der Folgearm hält an seiner Stelle</translation>
    </message>
    <message>
        <source>Joints (LeRobot&apos;s units: −100…100, the gripper 0…100)</source>
        <translation>Gelenke (Einheiten von LeRobot: −100…100, der Greifer 0…100)</translation>
    </message>
    <message>
        <source>Joint</source>
        <translation>Gelenk</translation>
    </message>
    <message>
        <source>Leader</source>
        <translation>Führungsarm</translation>
    </message>
    <message>
        <source>Follower&apos;s goal</source>
        <translation>Ziel des Folgearms</translation>
    </message>
    <message>
        <source>The joints both files name show here once started.</source>
        <translation>Die Gelenke, die beide Dateien nennen, erscheinen hier nach dem Start.</translation>
    </message>
    <message>
        <source>Loop: not running.</source>
        <translation>Schleife: läuft nicht.</translation>
    </message>
    <message>
        <source>Simulated SO-101 leader arm</source>
        <translation>Simulierter SO-101-Führungsarm</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>LeRobot calibration files (*.json);;All files (*)</source>
        <translation>LeRobot-Kalibrierdateien (*.json);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>The simulated leader arm could not start: %1</source>
        <translation>Der simulierte Führungsarm konnte nicht starten: %1</translation>
    </message>
    <message>
        <source>—</source>
        <translation>—</translation>
    </message>
    <message>
        <source>Where the leader&apos;s %1 is</source>
        <translation>Wo %1 des Führungsarms steht</translation>
    </message>
    <message>
        <source>The goal last sent to the follower&apos;s %1, within its speed limit</source>
        <translation>Das zuletzt an %1 des Folgearms gesendete Ziel, innerhalb seiner Geschwindigkeitsgrenze</translation>
    </message>
    <message>
        <source>Loop: waiting for the leader&apos;s first reading.</source>
        <translation>Schleife: wartet auf den ersten Messwert des Führungsarms.</translation>
    </message>
    <message numerus="yes">
        <source>Loop: %1 cycles a second; leader to follower %2 ms (median %3 ms); %n cycle(s) so far</source>
        <translation>
            <numerusform>Schleife: %1 Zyklen pro Sekunde; Führungs- zu Folgearm %2 ms (Median %3 ms); bisher %n Zyklus</numerusform>
            <numerusform>Schleife: %1 Zyklen pro Sekunde; Führungs- zu Folgearm %2 ms (Median %3 ms); bisher %n Zyklen</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Loop: stopped after %n cycle(s); leader to follower %1 ms (median)</source>
        <translation>
            <numerusform>Schleife: nach %n Zyklus gestoppt; Führungs- zu Folgearm %1 ms (Median)</numerusform>
            <numerusform>Schleife: nach %n Zyklen gestoppt; Führungs- zu Folgearm %1 ms (Median)</numerusform>
        </translation>
    </message>
    <message>
        <source>Degrees from the middle (LeRobot&apos;s use_degrees, its default)</source>
        <translation>Grad ab der Mitte (LeRobots use_degrees, sein Standard)</translation>
    </message>
    <message>
        <source>Range onto range, −100 to 100 (LeRobot&apos;s range_m100_100)</source>
        <translation>Bereich auf Bereich, −100 bis 100 (LeRobots range_m100_100)</translation>
    </message>
    <message>
        <source>How a leader&apos;s joint position becomes the follower&apos;s goal, as LeRobot&apos;s teleoperation does it: the same angle from the middle of each arm&apos;s range, or the same share of each range. The gripper is always share of range.</source>
        <translation>Wie die Gelenkposition des Führungsarms zum Ziel des Folgearms wird, wie LeRobots Teleoperation es tut: derselbe Winkel ab der Mitte des Bereichs jedes Arms oder derselbe Anteil jedes Bereichs. Der Greifer folgt immer dem Anteil des Bereichs.</translation>
    </message>
    <message>
        <source>Joints map:</source>
        <translation>Gelenkzuordnung:</translation>
    </message>
    <message>
        <source>The simulated leader&apos;s calibration file could not be made: %1</source>
        <translation>Die Kalibrierdatei des simulierten Führungsarms ließ sich nicht anlegen: %1</translation>
    </message>
</context>
<context>
    <name>TeleopMapping</name>
    <message>
        <source>%1 (not in the leader&apos;s file)</source>
        <translation>%1 (nicht in der Datei des Führungsarms)</translation>
    </message>
    <message>
        <source>%1 (not in the follower&apos;s file)</source>
        <translation>%1 (nicht in der Datei des Folgearms)</translation>
    </message>
</context>
<context>
    <name>UnlockedNotice</name>
    <message>
        <source>Lock EEPROM</source>
        <translation>EEPROM sperren</translation>
    </message>
    <message>
        <source>Writes the lock register (1) and reads it back. Nothing else changes.</source>
        <translation>Schreibt das Sperrregister (1) und liest es zurück. Sonst ändert sich nichts.</translation>
    </message>
    <message>
        <source>Dismiss</source>
        <translation>Ausblenden</translation>
    </message>
    <message>
        <source>Hides this note for this servo until the next connection; the lock stays open.</source>
        <translation>Blendet diesen Hinweis für dieses Servo bis zur nächsten Verbindung aus; die Sperre bleibt offen.</translation>
    </message>
    <message>
        <source>Note: servo %1&apos;s EEPROM is unlocked (lock = 0), as some programs (LeRobot among them) leave it: anything written to its settings now stays after a power cut. ServoBench locks it after each of its own writes; Lock EEPROM locks it now.</source>
        <translation>Hinweis: Das EEPROM von Servo %1 ist entsperrt (lock = 0), wie manche Programme (darunter LeRobot) es hinterlassen: Alles, was jetzt in seine Einstellungen geschrieben wird, bleibt nach einem Stromausfall erhalten. ServoBench sperrt es nach jedem eigenen Schreibvorgang; „EEPROM sperren“ sperrt es jetzt.</translation>
    </message>
</context>
<context>
    <name>VirtualFeetechBus</name>
    <message>
        <source>a Feetech bus needs at least one servo</source>
        <translation>ein Feetech-Bus braucht mindestens ein Servo</translation>
    </message>
    <message>
        <source>servo %1: model %2 has no register table to simulate</source>
        <translation>Servo %1: Modell %2 hat keine Registertabelle zum Simulieren</translation>
    </message>
    <message>
        <source>servo %1: unknown model &quot;%2&quot;</source>
        <translation>Servo %1: unbekanntes Modell &quot;%2&quot;</translation>
    </message>
    <message>
        <source>servo ID %1 is out of range: IDs are 0 to %2</source>
        <translation>Servo-ID %1 liegt außerhalb des Bereichs: IDs sind 0 bis %2</translation>
    </message>
    <message>
        <source>servo %1: %2 bps is not a Feetech baud rate (%3)</source>
        <translation>Servo %1: %2 bps ist keine Feetech-Baudrate (%3)</translation>
    </message>
    <message>
        <source>two servos have ID %1 at %2 bps</source>
        <translation>zwei Servos haben ID %1 bei %2 bps</translation>
    </message>
    <message>
        <source>cannot write the state file %1: %2</source>
        <translation>die Zustandsdatei %1 kann nicht geschrieben werden: %2</translation>
    </message>
    <message>
        <source>state file %1: %2</source>
        <translation>Zustandsdatei %1: %2</translation>
    </message>
    <message>
        <source>not valid JSON (%1)</source>
        <translation>kein gültiges JSON (%1)</translation>
    </message>
    <message>
        <source>not a format %1 simulator state</source>
        <translation>kein Simulatorzustand im Format %1</translation>
    </message>
    <message>
        <source>it holds %1 servos, the bus has %2</source>
        <translation>sie enthält %1 Servos, der Bus hat %2</translation>
    </message>
    <message>
        <source>servo %1 is a %2 in the file but a %3 on the bus</source>
        <translation>Servo %1 ist in der Datei ein %2, am Bus aber ein %3</translation>
    </message>
    <message>
        <source>servo %1: the EEPROM image is not %2 hex bytes</source>
        <translation>Servo %1: das EEPROM-Abbild hat nicht %2 Hex-Bytes</translation>
    </message>
    <message>
        <source>servo %1: the EEPROM image is of model %2/%3, not %4</source>
        <translation>Servo %1: das EEPROM-Abbild gehört zu Modell %2/%3, nicht %4</translation>
    </message>
    <message>
        <source>servo %1: the EEPROM image holds an invalid ID or baud code</source>
        <translation>Servo %1: das EEPROM-Abbild enthält eine ungültige ID oder einen ungültigen Baudcode</translation>
    </message>
    <message>
        <source>there is no servo #%1 on the bus (it has %2)</source>
        <translation>es gibt kein Servo #%1 am Bus (er hat %2)</translation>
    </message>
    <message>
        <source>no servo has ID %1</source>
        <translation>kein Servo hat ID %1</translation>
    </message>
    <message>
        <source>servos %1 share ID %2: name one by its place, as #N</source>
        <translation>die Servos %1 teilen sich ID %2: Benennen Sie eines über seinen Platz, als #N</translation>
    </message>
    <message>
        <source>larger than any state file (over 16 MB)</source>
        <translation>größer als jede Zustandsdatei (über 16 MB)</translation>
    </message>
</context>
<context>
    <name>WelcomePanel</name>
    <message>
        <source>&lt;h2&gt;Connect your servos&lt;/h2&gt;</source>
        <translation>&lt;h2&gt;Servos verbinden&lt;/h2&gt;</translation>
    </message>
    <message>
        <source>Choose the serial port of your USB adapter and press &lt;b&gt;Connect&lt;/b&gt; (or double-click it), or try ServoBench on simulated servos. Nothing is sent to a servo until you connect.</source>
        <translation>Wählen Sie den seriellen Anschluss Ihres USB-Adapters und drücken Sie &lt;b&gt;Verbinden&lt;/b&gt; (oder doppelklicken Sie ihn), oder probieren Sie ServoBench mit simulierten Servos aus. Bis Sie verbinden, wird nichts an ein Servo gesendet.</translation>
    </message>
    <message>
        <source>Serial ports</source>
        <translation>Serielle Anschlüsse</translation>
    </message>
    <message>
        <source>Port</source>
        <translation>Anschluss</translation>
    </message>
    <message>
        <source>Description</source>
        <translation>Beschreibung</translation>
    </message>
    <message>
        <source>Manufacturer</source>
        <translation>Hersteller</translation>
    </message>
    <message>
        <source>Serial number</source>
        <translation>Seriennummer</translation>
    </message>
    <message>
        <source>USB ID</source>
        <translation>USB-ID</translation>
    </message>
    <message>
        <source>Connect</source>
        <translation>Verbinden</translation>
    </message>
    <message>
        <source>Simulated servos</source>
        <translation>Simulierte Servos</translation>
    </message>
    <message>
        <source>PTK servo</source>
        <translation>PTK-Servo</translation>
    </message>
    <message>
        <source>Feetech bus (five servos)</source>
        <translation>Feetech-Bus (fünf Servos)</translation>
    </message>
    <message>
        <source>SO-101 arm (six STS3215)</source>
        <translation>SO-101-Arm (sechs STS3215)</translation>
    </message>
    <message>
        <source>Wiring</source>
        <translation>Verkabelung</translation>
    </message>
    <message>
        <source>&lt;b&gt;PTK RC servos&lt;/b&gt; (one signal wire, 115200 baud): a 3.3 V or 5 V USB-serial adapter with a 470 Ω resistor from TX to RX. The servo&apos;s signal wire goes to RX, its ground to the adapter&apos;s ground; power the servo from its own supply. The adapter hears its own bytes, and ServoBench expects that.</source>
        <translation>&lt;b&gt;PTK-RC-Servos&lt;/b&gt; (eine Signalleitung, 115200 Baud): ein USB-Seriell-Adapter mit 3,3 V oder 5 V und einem 470-Ω-Widerstand von TX nach RX. Die Signalleitung des Servos kommt an RX, seine Masse an die Masse des Adapters; versorgen Sie das Servo aus einer eigenen Stromquelle. Der Adapter hört seine eigenen Bytes, und ServoBench rechnet damit.</translation>
    </message>
    <message>
        <source>&lt;b&gt;Feetech serial-bus servos&lt;/b&gt;: Feetech&apos;s URT-1 / FE-URT board, or any half-duplex TTL adapter (SCS, STS, HLS) or RS485 adapter (SMS). Chain the servos with their 3-wire cables; power them from the board&apos;s supply (7.4 V or 12 V as the servos ask), never from USB. New servos all answer at ID 1 and 1 Mbps: set them up one at a time (Robot &gt; Set up motors).</source>
        <translation>&lt;b&gt;Feetech-Bus-Servos&lt;/b&gt;: Feetechs URT-1-/FE-URT-Platine oder ein beliebiger Halbduplex-TTL-Adapter (SCS, STS, HLS) bzw. RS485-Adapter (SMS). Verketten Sie die Servos mit ihren 3-adrigen Kabeln und versorgen Sie sie über die Platine (7,4 V oder 12 V, wie die Servos es verlangen), nie über USB. Neue Servos antworten alle unter ID 1 mit 1 Mbps: Richten Sie sie einzeln ein (Roboter &gt; Motoren einrichten).</translation>
    </message>
    <message>
        <source>Nothing answers? Leave Protocol on &lt;b&gt;Auto&lt;/b&gt; and connect: ServoBench finds the family and rate, and the Doctor says what is wrong.</source>
        <translation>Nichts antwortet? Lassen Sie das Protokoll auf &lt;b&gt;Auto&lt;/b&gt; und verbinden Sie: ServoBench findet Familie und Rate, und die Diagnose sagt, was nicht stimmt.</translation>
    </message>
    <message>
        <source>No serial port found. Plug in the USB adapter: it shows up here by itself.</source>
        <translation>Kein serieller Anschluss gefunden. Stecken Sie den USB-Adapter ein: Er erscheint hier von selbst.</translation>
    </message>
    <message>
        <source>Choose a serial port first</source>
        <translation>Wählen Sie zuerst einen seriellen Anschluss</translation>
    </message>
</context>
<context>
    <name>feetech</name>
    <message>
        <source>voltage</source>
        <translation>Spannung</translation>
    </message>
    <message>
        <source>encoder</source>
        <translation>Encoder</translation>
    </message>
    <message>
        <source>temperature</source>
        <translation>Temperatur</translation>
    </message>
    <message>
        <source>current</source>
        <translation>Strom</translation>
    </message>
    <message>
        <source>angle</source>
        <translation>Winkel</translation>
    </message>
    <message>
        <source>overload</source>
        <translation>Überlast</translation>
    </message>
    <message>
        <source>bit 6</source>
        <translation>Bit 6</translation>
    </message>
    <message>
        <source>bit 7</source>
        <translation>Bit 7</translation>
    </message>
</context>
<context>
    <name>feetech::BatchProgram</name>
    <message>
        <source>Servos are being programmed already.</source>
        <translation>Es werden bereits Servos programmiert.</translation>
    </message>
    <message>
        <source>The bus is not connected.</source>
        <translation>Der Bus ist nicht verbunden.</translation>
    </message>
    <message>
        <source>Another operation is still running.</source>
        <translation>Ein anderer Vorgang läuft noch.</translation>
    </message>
    <message>
        <source>Select the servos to program first.</source>
        <translation>Wählen Sie zuerst die zu programmierenden Servos aus.</translation>
    </message>
    <message>
        <source>Programming servo ID %1 (%2 of %3)…</source>
        <translation>Servo-ID %1 wird programmiert (%2 von %3)…</translation>
    </message>
    <message>
        <source>Servo ID %1 is no longer on the bus.</source>
        <translation>Servo-ID %1 ist nicht mehr am Bus.</translation>
    </message>
    <message>
        <source>Servo ID %1 has edits that are not applied: apply or revert them first.</source>
        <translation>Servo-ID %1 hat nicht übernommene Änderungen: Übernehmen oder verwerfen Sie sie zuerst.</translation>
    </message>
    <message>
        <source>%1 is %2</source>
        <translation>%1 ist %2</translation>
    </message>
    <message>
        <source>not verified: %1</source>
        <translation>nicht überprüft: %1</translation>
    </message>
    <message>
        <source>The bus was disconnected.</source>
        <translation>Die Verbindung zum Bus wurde getrennt.</translation>
    </message>
</context>
<context>
    <name>feetech::MotionTest</name>
    <message>
        <source>All torque off: the test was stopped.</source>
        <translation>Alle Drehmomente aus: Der Test wurde abgebrochen.</translation>
    </message>
    <message>
        <source>%1 is no longer on the bus: the test was stopped.</source>
        <translation>%1 ist nicht mehr am Bus: Der Test wurde abgebrochen.</translation>
    </message>
    <message>
        <source>The test was stopped.</source>
        <translation>Der Test wurde abgebrochen.</translation>
    </message>
    <message>
        <source>Servo ID %1</source>
        <translation>Servo-ID %1</translation>
    </message>
    <message>
        <source>Moving to the start position %1…</source>
        <translation>Fahrt zur Startposition %1…</translation>
    </message>
    <message>
        <source>Step to %1: recording for %2 s…</source>
        <translation>Sprung auf %1: Aufzeichnung für %2 s…</translation>
    </message>
    <message>
        <source>Too few position samples arrived during the recording (%1): does %2 answer?</source>
        <translation>Während der Aufzeichnung kamen zu wenige Positionsmesswerte an (%1): Antwortet %2?</translation>
    </message>
    <message>
        <source>Step test done.</source>
        <translation>Sprungtest fertig.</translation>
    </message>
    <message>
        <source>Sweep leg %1 of %2: moving to %3…</source>
        <translation>Schwenkfahrt %1 von %2: Fahrt nach %3…</translation>
    </message>
    <message>
        <source>Sweep done: %1 of %2 legs reached their goal.</source>
        <translation>Schwenken fertig: %1 von %2 Fahrten haben ihr Ziel erreicht.</translation>
    </message>
    <message>
        <source>No position samples arrived from %1: is it answering?</source>
        <translation>Von %1 kamen keine Positionsmesswerte an: Antwortet es?</translation>
    </message>
    <message>
        <source>%1 did not settle at %2 within %3 s; going on from %4.</source>
        <translation>%1 hat sich nicht innerhalb von %3 s bei %2 eingependelt; weiter ab %4.</translation>
    </message>
    <message>
        <source>Writing to %1 failed: %2</source>
        <translation>Schreiben auf %1 fehlgeschlagen: %2</translation>
    </message>
    <message>
        <source>The bus was disconnected: the test was stopped.</source>
        <translation>Die Verbindung zum Bus wurde getrennt: Der Test wurde abgebrochen.</translation>
    </message>
    <message>
        <source>The test was stopped: %1</source>
        <translation>Der Test wurde abgebrochen: %1</translation>
    </message>
    <message>
        <source>A motion test is running on servo ID %1.</source>
        <translation>Auf Servo-ID %1 läuft ein Bewegungstest.</translation>
    </message>
</context>
<context>
    <name>feetech::TelemetryRecorder</name>
    <message>
        <source>No file name was given for the recording.</source>
        <translation>Für die Aufzeichnung wurde kein Dateiname angegeben.</translation>
    </message>
    <message>
        <source>The telemetry output is not open for writing.</source>
        <translation>Die Telemetrieausgabe ist nicht zum Schreiben geöffnet.</translation>
    </message>
    <message>
        <source>The telemetry output cannot be written.</source>
        <translation>Die Telemetrieausgabe kann nicht geschrieben werden.</translation>
    </message>
    <message numerus="yes">
        <source>%1; the %n row(s) written before it are kept whole in %2.</source>
        <translation>
            <numerusform>%1; die zuvor geschriebene %n Zeile bleibt vollständig in %2 erhalten.</numerusform>
            <numerusform>%1; die zuvor geschriebenen %n Zeilen bleiben vollständig in %2 erhalten.</numerusform>
        </translation>
    </message>
    <message>
        <source>%1; the incomplete file %2 was removed.</source>
        <translation>%1; die unvollständige Datei %2 wurde entfernt.</translation>
    </message>
</context>
<context>
    <name>feetech::TeleopBus</name>
    <message>
        <source>The follower&apos;s bus is not open.</source>
        <translation>Der Bus des Folgearms ist nicht geöffnet.</translation>
    </message>
</context>
<context>
    <name>feetech::Teleoperation</name>
    <message>
        <source>Connect to the follower arm&apos;s bus first: it is the bus the window has open.</source>
        <translation>Verbinden Sie sich zuerst mit dem Bus des Folgearms: Es ist der Bus, den das Fenster geöffnet hat.</translation>
    </message>
    <message>
        <source>Choose the leader arm&apos;s port.</source>
        <translation>Wählen Sie den Anschluss des Führungsarms.</translation>
    </message>
    <message>
        <source>The leader&apos;s port is the follower&apos;s: the leader and the follower are two arms on two adapters.</source>
        <translation>Der Anschluss des Führungsarms ist der des Folgearms: Führungs- und Folgearm sind zwei Arme an zwei Adaptern.</translation>
    </message>
    <message>
        <source>The two files name different joints: %1.</source>
        <translation>Die beiden Dateien nennen verschiedene Gelenke: %1.</translation>
    </message>
    <message>
        <source>The follower&apos;s joint %1 (servo %2) is not on the bus the window has open: scan it, or choose the follower&apos;s file.</source>
        <translation>Gelenk %1 (Servo %2) des Folgearms ist nicht an dem Bus, den das Fenster geöffnet hat: Scannen Sie den Bus oder wählen Sie die Datei des Folgearms.</translation>
    </message>
    <message>
        <source>Opening the leader&apos;s port…</source>
        <translation>Anschluss des Führungsarms wird geöffnet…</translation>
    </message>
    <message>
        <source>Stopped before the follower moved.</source>
        <translation>Gestoppt, bevor sich der Folgearm bewegt hat.</translation>
    </message>
    <message>
        <source>Checking the leader&apos;s joints…</source>
        <translation>Gelenke des Führungsarms werden geprüft…</translation>
    </message>
    <message>
        <source>The leader was lost: %1</source>
        <translation>Der Führungsarm ist nicht mehr erreichbar: %1</translation>
    </message>
    <message>
        <source>The leader&apos;s port could not be opened: %1</source>
        <translation>Der Anschluss des Führungsarms konnte nicht geöffnet werden: %1</translation>
    </message>
    <message>
        <source>The follower was lost: %1. It could not be told to hold.</source>
        <translation>Der Folgearm ist nicht mehr erreichbar: %1. Er konnte nicht angewiesen werden zu halten.</translation>
    </message>
    <message>
        <source>Checking the follower&apos;s joints…</source>
        <translation>Gelenke des Folgearms werden geprüft…</translation>
    </message>
    <message>
        <source>The leader&apos;s joint %1 (servo %2) does not answer: %3</source>
        <translation>Gelenk %1 (Servo %2) des Führungsarms antwortet nicht: %3</translation>
    </message>
    <message>
        <source>its model is unknown</source>
        <translation>sein Modell ist unbekannt</translation>
    </message>
    <message>
        <source>The follower holds where it stands…</source>
        <translation>Der Folgearm hält an seiner Stelle…</translation>
    </message>
    <message>
        <source>The follower&apos;s torque could not be switched on.</source>
        <translation>Das Drehmoment des Folgearms konnte nicht eingeschaltet werden.</translation>
    </message>
    <message>
        <source>Servo %1 reports no position.</source>
        <translation>Servo %1 meldet keine Position.</translation>
    </message>
    <message>
        <source>Following the leader.</source>
        <translation>Folgt dem Führungsarm.</translation>
    </message>
    <message>
        <source>The follower could not be told to hold.</source>
        <translation>Der Folgearm konnte nicht angewiesen werden zu halten.</translation>
    </message>
    <message>
        <source>Stopped: the follower holds where it is.</source>
        <translation>Gestoppt: Der Folgearm hält an seiner Stelle.</translation>
    </message>
    <message>
        <source>%1 The follower holds where it is.</source>
        <translation>%1 Der Folgearm hält an seiner Stelle.</translation>
    </message>
    <message>
        <source>Choose the follower&apos;s LeRobot calibration file: the one saved when the follower arm was calibrated (Robot › Calibrate arm…).</source>
        <translation>Wählen Sie die LeRobot-Kalibrierdatei des Folgearms: die beim Kalibrieren des Folgearms gespeicherte (Roboter › Arm kalibrieren…).</translation>
    </message>
    <message>
        <source>Choose the leader&apos;s LeRobot calibration file: the one saved when the leader arm was calibrated.</source>
        <translation>Wählen Sie die LeRobot-Kalibrierdatei des Führungsarms: die beim Kalibrieren des Führungsarms gespeicherte.</translation>
    </message>
    <message>
        <source>The leader&apos;s %1 (servo %2) does not hold what %3 says (%4). Nothing was written. Connect to the leader arm and write the file to it (Robot › Load calibration…), or choose the leader&apos;s own file.</source>
        <translation>%1 des Führungsarms (Servo %2) hält nicht, was %3 angibt (%4). Es wurde nichts geschrieben. Verbinden Sie sich mit dem Führungsarm und schreiben Sie die Datei hinein (Roboter › Kalibrierung laden…), oder wählen Sie die eigene Datei des Führungsarms.</translation>
    </message>
    <message>
        <source>The follower&apos;s %1 (servo %2) does not hold what %3 says (%4). Nothing was written. Write the file to the follower (Robot › Load calibration…), or choose the follower&apos;s own file.</source>
        <translation>%1 des Folgearms (Servo %2) hält nicht, was %3 angibt (%4). Es wurde nichts geschrieben. Schreiben Sie die Datei in den Folgearm (Roboter › Kalibrierung laden…), oder wählen Sie die eigene Datei des Folgearms.</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <source>Programmer and live monitor for PTK and Feetech servos</source>
        <translation>Programmiergerät und Live-Monitor für PTK- und Feetech-Servos</translation>
    </message>
    <message>
        <source>Start the simulated servos and connect to the PTK servo (the Feetech bus is in the port list).</source>
        <translation>Die simulierten Servos starten und mit dem PTK-Servo verbinden (der Feetech-Bus steht in der Anschlussliste).</translation>
    </message>
    <message>
        <source>Start the simulated servos, connect to the Feetech bus and scan it.</source>
        <translation>Die simulierten Servos starten, mit dem Feetech-Bus verbinden und ihn scannen.</translation>
    </message>
    <message>
        <source>Connect to PORT at start.</source>
        <translation>Beim Start mit PORT verbinden.</translation>
    </message>
    <message>
        <source>Start a simulated SO-101 arm (six STS3215 at IDs 1-6, set up), connect to it and scan it; the Simulator dock turns its joints by hand.</source>
        <translation>Einen simulierten SO-101-Arm starten (sechs STS3215 mit IDs 1-6, eingerichtet), mit ihm verbinden und ihn scannen; im Simulator-Dock drehen Sie seine Gelenke von Hand.</translation>
    </message>
</context>
<context>
    <name>model::ParameterModel</name>
    <message>
        <source>unknown parameter &quot;%1&quot;</source>
        <translation>unbekannter Parameter &quot;%1&quot;</translation>
    </message>
    <message>
        <source>%1 is read-only</source>
        <translation>%1 ist schreibgeschützt</translation>
    </message>
    <message>
        <source>%1 must be between %2 and %3</source>
        <translation>%1 muss zwischen %2 und %3 liegen</translation>
    </message>
    <message>
        <source>Edited</source>
        <translation>Geändert</translation>
    </message>
    <message>
        <source>Writing</source>
        <translation>Wird geschrieben</translation>
    </message>
    <message>
        <source>Verified</source>
        <translation>Überprüft</translation>
    </message>
    <message>
        <source>Mismatch</source>
        <translation>Abweichung</translation>
    </message>
    <message>
        <source>Failed</source>
        <translation>Fehlgeschlagen</translation>
    </message>
    <message>
        <source>%1: %2 to %3</source>
        <translation>%1: %2 bis %3</translation>
    </message>
    <message>
        <source>Key</source>
        <translation>Schlüssel</translation>
    </message>
    <message>
        <source>Parameter</source>
        <translation>Parameter</translation>
    </message>
    <message>
        <source>Device</source>
        <translation>Gerät</translation>
    </message>
    <message>
        <source>Edit</source>
        <translation>Änderung</translation>
    </message>
    <message>
        <source>Unit</source>
        <translation>Einheit</translation>
    </message>
    <message>
        <source>State</source>
        <translation>Zustand</translation>
    </message>
    <message>
        <source>Unknown</source>
        <translation>Unbekannt</translation>
    </message>
</context>
<context>
    <name>ptk</name>
    <message>
        <source>Gain</source>
        <translation>Verstärkung</translation>
    </message>
    <message>
        <source>Damping</source>
        <translation>Dämpfung</translation>
    </message>
    <message>
        <source>Deadband</source>
        <translation>Totband</translation>
    </message>
    <message>
        <source>Neutral</source>
        <translation>Neutralstellung</translation>
    </message>
    <message>
        <source>Minimum angle</source>
        <translation>Minimaler Winkel</translation>
    </message>
    <message>
        <source>Maximum angle</source>
        <translation>Maximaler Winkel</translation>
    </message>
    <message>
        <source>Minimum pulse width</source>
        <translation>Minimale Impulsbreite</translation>
    </message>
    <message>
        <source>Maximum pulse width</source>
        <translation>Maximale Impulsbreite</translation>
    </message>
    <message>
        <source>Inversion</source>
        <translation>Drehrichtungsumkehr</translation>
    </message>
    <message>
        <source>Maximum power</source>
        <translation>Maximale Leistung</translation>
    </message>
    <message>
        <source>Overload protection power</source>
        <translation>Überlastschutz-Leistung</translation>
    </message>
    <message>
        <source>Overload protection time</source>
        <translation>Überlastschutz-Zeit</translation>
    </message>
    <message>
        <source>Soft start</source>
        <translation>Sanftanlauf</translation>
    </message>
    <message>
        <source>Off</source>
        <translation>Aus</translation>
    </message>
    <message>
        <source>On</source>
        <translation>Ein</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not NAME=VALUE</source>
        <translation>&quot;%1&quot; ist nicht NAME=VALUE</translation>
    </message>
    <message>
        <source>unknown parameter &quot;%1&quot; (known: %2)</source>
        <translation>unbekannter Parameter &quot;%1&quot; (bekannt: %2)</translation>
    </message>
    <message>
        <source>%1: &quot;%2&quot; is not a number</source>
        <translation>%1: &quot;%2&quot; ist keine Zahl</translation>
    </message>
    <message>
        <source>Response</source>
        <translation>Ansprechverhalten</translation>
    </message>
    <message>
        <source>Travel</source>
        <translation>Stellweg</translation>
    </message>
    <message>
        <source>Power</source>
        <translation>Leistung</translation>
    </message>
    <message>
        <source>%1 must be between %2 and %3%4</source>
        <translation>%1 muss zwischen %2 und %3%4 liegen</translation>
    </message>
</context>
<context>
    <name>seriallink::PacketLogModel</name>
    <message>
        <source>The log could not be written.</source>
        <translation>Das Protokoll konnte nicht geschrieben werden.</translation>
    </message>
    <message>
        <source>Cannot write %1: %2</source>
        <translation>%1 kann nicht geschrieben werden: %2</translation>
    </message>
    <message>
        <source>→ out</source>
        <translation>→ gesendet</translation>
    </message>
    <message>
        <source>← in</source>
        <translation>← empfangen</translation>
    </message>
    <message>
        <source>echo</source>
        <translation>Echo</translation>
    </message>
    <message>
        <source>stray</source>
        <translation>Streudaten</translation>
    </message>
    <message numerus="yes">
        <source>%n byte(s)</source>
        <translation>
            <numerusform>%n Byte</numerusform>
            <numerusform>%n Bytes</numerusform>
        </translation>
    </message>
    <message>
        <source>Time</source>
        <translation>Zeit</translation>
    </message>
    <message>
        <source>Direction</source>
        <translation>Richtung</translation>
    </message>
    <message>
        <source>Bytes</source>
        <translation>Bytes</translation>
    </message>
    <message>
        <source>Meaning</source>
        <translation>Bedeutung</translation>
    </message>
    <message>
        <source>Error</source>
        <translation>Fehler</translation>
    </message>
</context>
<context>
    <name>servoctl</name>
    <message>
        <source>--%1 takes no value</source>
        <translation>--%1 nimmt keinen Wert an</translation>
    </message>
    <message>
        <source>--%1 needs a value</source>
        <translation>--%1 braucht einen Wert</translation>
    </message>
    <message>
        <source>unknown option --%1</source>
        <translation>unbekannte Option --%1</translation>
    </message>
    <message>
        <source>--%1: &quot;%2&quot; is not a number</source>
        <translation>--%1: &quot;%2&quot; ist keine Zahl</translation>
    </message>
    <message>
        <source>--%1: %2 is out of range (%3 to %4)</source>
        <translation>--%1: %2 liegt außerhalb des Bereichs (%3 bis %4)</translation>
    </message>
    <message>
        <source>--ids: &quot;%1&quot; is not an ID</source>
        <translation>--ids: &quot;%1&quot; ist keine ID</translation>
    </message>
    <message>
        <source>--ids: ID %1 is over %2</source>
        <translation>--ids: ID %1 ist größer als %2</translation>
    </message>
    <message>
        <source>--ids: the range %1 runs backwards</source>
        <translation>--ids: der Bereich %1 läuft rückwärts</translation>
    </message>
    <message>
        <source>--ids needs at least one ID</source>
        <translation>--ids braucht mindestens eine ID</translation>
    </message>
    <message>
        <source>ptk commands need --port PATH (see servoctl ports)</source>
        <translation>ptk-Befehle brauchen --port PATH (siehe servoctl ports)</translation>
    </message>
    <message>
        <source>%1 bps</source>
        <translation>%1 bps</translation>
    </message>
    <message>
        <source>unknown model, raw bytes only</source>
        <translation>unbekanntes Modell, nur Rohbytes</translation>
    </message>
    <message>
        <source>servo %1 at %2: %3 (%4), firmware %5</source>
        <translation>Servo %1 bei %2: %3 (%4), Firmware %5</translation>
    </message>
    <message>
        <source>feetech commands need --port PATH (see servoctl ports)</source>
        <translation>feetech-Befehle brauchen --port PATH (siehe servoctl ports)</translation>
    </message>
    <message>
        <source>%1 could not be opened</source>
        <translation>%1 konnte nicht geöffnet werden</translation>
    </message>
    <message>
        <source>%1 (at %2; servoctl feetech scan --baud all looks at every rate)</source>
        <translation>%1 (bei %2; servoctl feetech scan --baud all sucht bei jeder Rate)</translation>
    </message>
    <message>
        <source>servo %1 answers PING but its identity (addresses 0-8) could not be read: %2</source>
        <translation>Servo %1 antwortet auf PING, aber seine Identität (Adressen 0-8) konnte nicht gelesen werden: %2</translation>
    </message>
    <message>
        <source>the servo did not finish in time</source>
        <translation>das Servo wurde nicht rechtzeitig fertig</translation>
    </message>
    <message>
        <source>feetech needs a command (try servoctl --help)</source>
        <translation>feetech braucht einen Befehl (versuchen Sie servoctl --help)</translation>
    </message>
    <message>
        <source>unknown feetech command &quot;%1&quot;: use %2</source>
        <translation>unbekannter feetech-Befehl &quot;%1&quot;: verwenden Sie %2</translation>
    </message>
    <message>
        <source>%1 takes no arguments</source>
        <translation>%1 nimmt keine Argumente an</translation>
    </message>
    <message>
        <source>%1 needs %2</source>
        <translation>%1 braucht %2</translation>
    </message>
    <message>
        <source>%1: &quot;%2&quot; is not a Feetech baud rate (%3)</source>
        <translation>%1: &quot;%2&quot; ist keine Feetech-Baudrate (%3)</translation>
    </message>
    <message>
        <source>%1 needs --id N</source>
        <translation>%1 braucht --id N</translation>
    </message>
    <message>
        <source>--ids: a scan covers one range of IDs, such as 0-20</source>
        <translation>--ids: ein Scan deckt einen ID-Bereich ab, etwa 0-20</translation>
    </message>
    <message>
        <source>id</source>
        <translation>ID</translation>
    </message>
    <message>
        <source>baud</source>
        <translation>Baud</translation>
    </message>
    <message>
        <source>model</source>
        <translation>Modell</translation>
    </message>
    <message>
        <source>number</source>
        <translation>Nummer</translation>
    </message>
    <message>
        <source>family</source>
        <translation>Fam.</translation>
    </message>
    <message>
        <source>firmware</source>
        <translation>Firmware</translation>
    </message>
    <message>
        <source>no servo answered (try --baud all, or check power and wiring)</source>
        <translation>kein Servo hat geantwortet (versuchen Sie --baud all, oder prüfen Sie Stromversorgung und Verkabelung)</translation>
    </message>
    <message>
        <source>%1; answered in %2 ms</source>
        <translation>%1; antwortete in %2 ms</translation>
    </message>
    <message>
        <source>no register table is known for this model: the bytes are shown as they are, and nothing can be written</source>
        <translation>für dieses Modell ist keine Registertabelle bekannt: Die Bytes werden unverändert angezeigt, und es kann nichts geschrieben werden</translation>
    </message>
    <message>
        <source>addr</source>
        <translation>Adr.</translation>
    </message>
    <message>
        <source>key</source>
        <translation>Schlüssel</translation>
    </message>
    <message>
        <source>value</source>
        <translation>Wert</translation>
    </message>
    <message>
        <source>meaning</source>
        <translation>Bedeutung</translation>
    </message>
    <message>
        <source>%1 needs the register KEYs to read</source>
        <translation>%1 braucht die Schlüssel (KEY) der zu lesenden Register</translation>
    </message>
    <message>
        <source>%1: &quot;%2&quot; is not a register key</source>
        <translation>%1: &quot;%2&quot; ist kein Registerschlüssel</translation>
    </message>
    <message>
        <source>%1 servos have no register &quot;%2&quot; (servoctl feetech read lists them)</source>
        <translation>%1-Servos haben kein Register &quot;%2&quot; (servoctl feetech read listet sie auf)</translation>
    </message>
    <message numerus="yes">
        <source>written to servo %1 and verified: %n register(s)</source>
        <translation>
            <numerusform>auf Servo %1 geschrieben und überprüft: %n Register</numerusform>
            <numerusform>auf Servo %1 geschrieben und überprüft: %n Register</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 needs KEY=VALUE arguments</source>
        <translation>%1 braucht Argumente der Form KEY=VALUE</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not KEY=VALUE</source>
        <translation>&quot;%1&quot; ist nicht KEY=VALUE</translation>
    </message>
    <message>
        <source>the ID changes how the servo is reached: use servoctl feetech set-id --id N NEW</source>
        <translation>die ID ändert, wie das Servo erreicht wird: verwenden Sie servoctl feetech set-id --id N NEW</translation>
    </message>
    <message>
        <source>the baud rate changes how the servo is reached: use servoctl feetech set-baud --id N BAUD</source>
        <translation>die Baudrate ändert, wie das Servo erreicht wird: verwenden Sie servoctl feetech set-baud --id N BAUD</translation>
    </message>
    <message>
        <source>%1 is given twice</source>
        <translation>%1 ist doppelt angegeben</translation>
    </message>
    <message>
        <source>servo %1 is of an unknown model (%2); nothing is written to it</source>
        <translation>Servo %1 hat ein unbekanntes Modell (%2); es wird nichts darauf geschrieben</translation>
    </message>
    <message>
        <source>%1 is read-only</source>
        <translation>%1 ist schreibgeschützt</translation>
    </message>
    <message>
        <source>%1 = %2 is outside its range (%3 to %4) and is left out of the profile</source>
        <translation>%1 = %2 liegt außerhalb seines Bereichs (%3 bis %4) und wird nicht ins Profil übernommen</translation>
    </message>
    <message>
        <source>one FILE</source>
        <translation>genau eine Datei (FILE)</translation>
    </message>
    <message>
        <source>servo %1 is of an unknown model (%2): no profile can be saved</source>
        <translation>Servo %1 hat ein unbekanntes Modell (%2): Es kann kein Profil gespeichert werden</translation>
    </message>
    <message>
        <source>saved servo %1 (%2) to %3</source>
        <translation>Servo %1 (%2) in %3 gespeichert</translation>
    </message>
    <message>
        <source>note: the profile was saved from a %1, this servo is a %2</source>
        <translation>Hinweis: Das Profil wurde von einem %1 gespeichert, dieses Servo ist ein %2</translation>
    </message>
    <message>
        <source>servo %1 already holds every value of %2; nothing written</source>
        <translation>Servo %1 enthält bereits jeden Wert von %2; nichts geschrieben</translation>
    </message>
    <message>
        <source>the NEW ID</source>
        <translation>die neue ID (NEW)</translation>
    </message>
    <message>
        <source>%1: &quot;%2&quot; is not an ID (0 to %3)</source>
        <translation>%1: &quot;%2&quot; ist keine ID (0 bis %3)</translation>
    </message>
    <message>
        <source>servo %1 already has ID %1; nothing written</source>
        <translation>Servo %1 hat bereits ID %1; nichts geschrieben</translation>
    </message>
    <message>
        <source>the new BAUD rate in bits per second</source>
        <translation>die neue Baudrate (BAUD) in Bit pro Sekunde</translation>
    </message>
    <message>
        <source>servo %1 already runs at %2; nothing written</source>
        <translation>Servo %1 läuft bereits mit %2; nichts geschrieben</translation>
    </message>
    <message>
        <source>%1 servos do not support %2</source>
        <translation>%1-Servos unterstützen %2 nicht</translation>
    </message>
    <message>
        <source>--backup needs a FILE</source>
        <translation>--backup braucht eine Datei (FILE)</translation>
    </message>
    <message>
        <source>servo %1 is of an unknown model (%2): no backup can be saved, so it is not reset</source>
        <translation>Servo %1 hat ein unbekanntes Modell (%2): Es kann keine Sicherung gespeichert werden, daher wird es nicht zurückgesetzt</translation>
    </message>
    <message>
        <source>the backup could not be saved, so the servo was not reset: %1</source>
        <translation>die Sicherung konnte nicht gespeichert werden, daher wurde das Servo nicht zurückgesetzt: %1</translation>
    </message>
    <message>
        <source>backup of servo %1 saved to %2</source>
        <translation>Sicherung von Servo %1 in %2 gespeichert</translation>
    </message>
    <message>
        <source>%1 needs --ids LIST (such as 1,2,5-7)</source>
        <translation>%1 braucht --ids LIST (etwa 1,2,5-7)</translation>
    </message>
    <message>
        <source>--ids names servo %1 twice</source>
        <translation>--ids nennt Servo %1 doppelt</translation>
    </message>
    <message>
        <source>servo %1 is of an unknown model (%2): its feedback cannot be decoded</source>
        <translation>Servo %1 hat ein unbekanntes Modell (%2): Seine Rückmeldung kann nicht dekodiert werden</translation>
    </message>
    <message>
        <source>servoctl: servo %1 stopped answering</source>
        <translation>servoctl: Servo %1 antwortet nicht mehr</translation>
    </message>
    <message>
        <source>servoctl: servo %1 answers again</source>
        <translation>servoctl: Servo %1 antwortet wieder</translation>
    </message>
    <message>
        <source>no servo answered the telemetry requests</source>
        <translation>kein Servo hat auf die Telemetrie-Anfragen geantwortet</translation>
    </message>
    <message>
        <source>--rate must be a number of samples per second from 1 to 1000, or max</source>
        <translation>--rate muss eine Anzahl Messwerte pro Sekunde von 1 bis 1000 oder max sein</translation>
    </message>
    <message>
        <source>ptk needs a command: read, write, save, load or monitor</source>
        <translation>ptk braucht einen Befehl: read, write, save, load oder monitor</translation>
    </message>
    <message>
        <source>ptk takes no --rate: the servo is polled every 50 ms</source>
        <translation>ptk nimmt kein --rate an: Das Servo wird alle 50 ms abgefragt</translation>
    </message>
    <message>
        <source>only ptk monitor takes --duration</source>
        <translation>nur ptk monitor nimmt --duration an</translation>
    </message>
    <message>
        <source>unknown ptk command &quot;%1&quot;: use read, write, save, load or monitor</source>
        <translation>unbekannter ptk-Befehl &quot;%1&quot;: verwenden Sie read, write, save, load oder monitor</translation>
    </message>
    <message>
        <source>ptk read takes no arguments</source>
        <translation>ptk read nimmt keine Argumente an</translation>
    </message>
    <message>
        <source>%1: wrote %2, the servo holds %3</source>
        <translation>%1: %2 geschrieben, das Servo enthält %3</translation>
    </message>
    <message>
        <source>nothing</source>
        <translation>nichts</translation>
    </message>
    <message>
        <source>written and verified</source>
        <translation>geschrieben und überprüft</translation>
    </message>
    <message>
        <source>verification failed: %1</source>
        <translation>Überprüfung fehlgeschlagen: %1</translation>
    </message>
    <message>
        <source>ptk write needs NAME=VALUE arguments (names: %1)</source>
        <translation>ptk write braucht Argumente der Form NAME=VALUE (Namen: %1)</translation>
    </message>
    <message>
        <source>ptk save needs one FILE</source>
        <translation>ptk save braucht genau eine Datei (FILE)</translation>
    </message>
    <message>
        <source>the folder of %1 does not exist</source>
        <translation>der Ordner von %1 existiert nicht</translation>
    </message>
    <message>
        <source>saved %1</source>
        <translation>%1 gespeichert</translation>
    </message>
    <message>
        <source>ptk load needs one FILE</source>
        <translation>ptk load braucht genau eine Datei (FILE)</translation>
    </message>
    <message>
        <source>ptk monitor takes no arguments</source>
        <translation>ptk monitor nimmt keine Argumente an</translation>
    </message>
    <message>
        <source>--duration must be a number of seconds above 0</source>
        <translation>--duration muss eine Anzahl Sekunden über 0 sein</translation>
    </message>
    <message>
        <source>choose --csv or --json, not both</source>
        <translation>wählen Sie --csv oder --json, nicht beides</translation>
    </message>
    <message>
        <source>the servo did not answer</source>
        <translation>das Servo hat nicht geantwortet</translation>
    </message>
    <message>
        <source>no command given (try servoctl --help)</source>
        <translation>kein Befehl angegeben (versuchen Sie servoctl --help)</translation>
    </message>
    <message>
        <source>unknown command &quot;%1&quot; (try servoctl --help)</source>
        <translation>unbekannter Befehl &quot;%1&quot; (versuchen Sie servoctl --help)</translation>
    </message>
    <message>
        <source>%1 takes no --%2</source>
        <translation>%1 nimmt kein --%2 an</translation>
    </message>
    <message>
        <source>ports takes no arguments</source>
        <translation>ports nimmt keine Argumente an</translation>
    </message>
    <message>
        <source>no serial ports found</source>
        <translation>keine seriellen Anschlüsse gefunden</translation>
    </message>
    <message>
        <source>decode needs the bytes to decode, as hex</source>
        <translation>decode braucht die zu dekodierenden Bytes als Hex</translation>
    </message>
    <message>
        <source>--family must be ptk or feetech</source>
        <translation>--family muss ptk oder feetech sein</translation>
    </message>
    <message>
        <source>no PTK (AF FA) or Feetech (FF FF) header found; name the protocol with --family</source>
        <translation>kein PTK-Header (AF FA) oder Feetech-Header (FF FF) gefunden; nennen Sie das Protokoll mit --family</translation>
    </message>
    <message>
        <source> [checksum ok]</source>
        <translation> [Prüfsumme ok]</translation>
    </message>
    <message>
        <source> [BAD CHECKSUM]</source>
        <translation> [FALSCHE PRÜFSUMME]</translation>
    </message>
    <message>
        <source>packet needs a protocol: ptk or feetech</source>
        <translation>packet braucht ein Protokoll: ptk oder feetech</translation>
    </message>
    <message>
        <source>unknown protocol &quot;%1&quot;: use ptk or feetech</source>
        <translation>unbekanntes Protokoll &quot;%1&quot;: verwenden Sie ptk oder feetech</translation>
    </message>
    <message>
        <source>packet ptk needs query CMD or write NAME=VALUE...</source>
        <translation>packet ptk braucht query CMD oder write NAME=VALUE...</translation>
    </message>
    <message>
        <source>packet ptk query needs exactly one command</source>
        <translation>packet ptk query braucht genau einen Befehl</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a command byte (0-255) or N1..N8</source>
        <translation>&quot;%1&quot; ist kein Befehlsbyte (0-255) oder N1..N8</translation>
    </message>
    <message>
        <source>unknown PTK packet &quot;%1&quot;: use query or write</source>
        <translation>unbekanntes PTK-Paket &quot;%1&quot;: verwenden Sie query oder write</translation>
    </message>
    <message>
        <source>packet ptk write needs NAME=VALUE arguments</source>
        <translation>packet ptk write braucht Argumente der Form NAME=VALUE</translation>
    </message>
    <message>
        <source>write %1 also carries %2; give it too</source>
        <translation>write %1 überträgt auch %2; geben Sie es ebenfalls an</translation>
    </message>
    <message>
        <source>packet feetech needs one instruction (try servoctl --help)</source>
        <translation>packet feetech braucht genau eine Instruktion (versuchen Sie servoctl --help)</translation>
    </message>
    <message>
        <source>%1 needs --id</source>
        <translation>%1 braucht --id</translation>
    </message>
    <message>
        <source>%1 needs a unicast ID (0-253), not %2</source>
        <translation>%1 braucht eine Unicast-ID (0-253), nicht %2</translation>
    </message>
    <message>
        <source>%1 needs --addr</source>
        <translation>%1 braucht --addr</translation>
    </message>
    <message>
        <source>%1 needs --data</source>
        <translation>%1 braucht --data</translation>
    </message>
    <message>
        <source>--data is empty</source>
        <translation>--data ist leer</translation>
    </message>
    <message>
        <source>%1 needs --len</source>
        <translation>%1 braucht --len</translation>
    </message>
    <message>
        <source>the packet would be %1 bytes; the limit is %2</source>
        <translation>das Paket wäre %1 Bytes lang; die Grenze ist %2</translation>
    </message>
    <message>
        <source>calibrate --data is a 2-byte position in the family&apos;s byte order</source>
        <translation>calibrate --data ist eine 2-Byte-Position in der Bytereihenfolge der Familie</translation>
    </message>
    <message>
        <source>%1 needs --ids</source>
        <translation>%1 braucht --ids</translation>
    </message>
    <message>
        <source>--data must hold %1 or %2 bytes (--len %1 for %3 servos)</source>
        <translation>--data muss %1 oder %2 Bytes enthalten (--len %1 für %3-Servos)</translation>
    </message>
    <message>
        <source>the SYNC WRITE would exceed %1 bytes</source>
        <translation>das SYNC WRITE würde %1 Bytes überschreiten</translation>
    </message>
    <message>
        <source>unknown Feetech instruction &quot;%1&quot; (try servoctl --help)</source>
        <translation>unbekannte Feetech-Instruktion &quot;%1&quot; (versuchen Sie servoctl --help)</translation>
    </message>
    <message>
        <source>--%1 is given twice</source>
        <translation>--%1 ist doppelt angegeben</translation>
    </message>
    <message>
        <source>--ids: &quot;%1&quot; has an empty place between commas</source>
        <translation>--ids: &quot;%1&quot; hat eine leere Stelle zwischen Kommas</translation>
    </message>
    <message>
        <source>%1 needs --port PATH (see servoctl ports)</source>
        <translation>%1 braucht --port PATH (siehe servoctl ports)</translation>
    </message>
    <message>
        <source>detect takes no arguments</source>
        <translation>detect nimmt keine Argumente an</translation>
    </message>
    <message>
        <source>PTK servo at 115200 bps%1</source>
        <translation>PTK-Servo bei 115200 bps%1</translation>
    </message>
    <message>
        <source>, adapter echo</source>
        <translation>, Adapter-Echo</translation>
    </message>
    <message numerus="yes">
        <source>Feetech bus%1: %n servo(s)</source>
        <translation>
            <numerusform>Feetech-Bus%1: %n Servo</numerusform>
            <numerusform>Feetech-Bus%1: %n Servos</numerusform>
        </translation>
    </message>
    <message>
        <source>interrupted before the probe ended</source>
        <translation>unterbrochen, bevor die Erkennung endete</translation>
    </message>
    <message>
        <source>nothing answers on %1</source>
        <translation>auf %1 antwortet nichts</translation>
    </message>
    <message>
        <source>doctor takes no arguments (the expected IDs go in --expect)</source>
        <translation>doctor nimmt keine Argumente an (die erwarteten IDs gehören in --expect)</translation>
    </message>
    <message>
        <source>doctor --baud names the rate of the --expect servos</source>
        <translation>doctor --baud nennt die Rate der Servos aus --expect</translation>
    </message>
    <message>
        <source>--baud %1 is not a Feetech rate (%2)</source>
        <translation>--baud %1 ist keine Feetech-Rate (%2)</translation>
    </message>
    <message>
        <source>A PTK servo answers on %1.</source>
        <translation>Auf %1 antwortet ein PTK-Servo.</translation>
    </message>
    <message numerus="yes">
        <source>The bus holds what was expected: %n servo(s).</source>
        <translation>
            <numerusform>Der Bus enthält das Erwartete: %n Servo.</numerusform>
            <numerusform>Der Bus enthält das Erwartete: %n Servos.</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 needs --ids LIST (such as 1-6)</source>
        <translation>%1 braucht --ids LIST (etwa 1-6)</translation>
    </message>
    <message>
        <source>--ids names no servo</source>
        <translation>--ids nennt kein Servo</translation>
    </message>
    <message>
        <source>--names gives %1 name(s) for %2 servo(s) in --ids</source>
        <translation>--names gibt %1 Name(n) für %2 Servo(s) in --ids an</translation>
    </message>
    <message>
        <source>--names: &quot;%1&quot; is not a joint name (letters, digits and _, a letter first)</source>
        <translation>--names: &quot;%1&quot; ist kein Gelenkname (Buchstaben, Ziffern und _, zuerst ein Buchstabe)</translation>
    </message>
    <message>
        <source>--names: &quot;%1&quot; is given twice</source>
        <translation>--names: &quot;%1&quot; ist doppelt angegeben</translation>
    </message>
    <message>
        <source>servo %1 (%2) has no position offset on a 4096-step encoder: it cannot be calibrated; nothing was written</source>
        <translation>Servo %1 (%2) hat keinen Positionsoffset bei einem 4096-Schritt-Encoder: Es kann nicht kalibriert werden; es wurde nichts geschrieben</translation>
    </message>
    <message>
        <source>--full-turn: servo %1 is not in --ids</source>
        <translation>--full-turn: Servo %1 ist nicht in --ids</translation>
    </message>
    <message>
        <source>%1 needs --out FILE: the LeRobot calibration file to save</source>
        <translation>%1 braucht --out FILE: die zu speichernde LeRobot-Kalibrierdatei</translation>
    </message>
    <message>
        <source>%1 needs --duration S when standard input is not a terminal (Enter on a terminal ends the recording otherwise)</source>
        <translation>%1 braucht --duration S, wenn die Standardeingabe kein Terminal ist (sonst beendet Enter auf einem Terminal die Aufzeichnung)</translation>
    </message>
    <message>
        <source>servo %1: torque could not be switched off: %2</source>
        <translation>Servo %1: Drehmoment konnte nicht abgeschaltet werden: %2</translation>
    </message>
    <message>
        <source>%1 (servo %2): refused, nothing written: %3</source>
        <translation>%1 (Servo %2): abgelehnt, nichts geschrieben: %3</translation>
    </message>
    <message>
        <source>%1 (servo %2): offset %3, limits %4 to %5</source>
        <translation>%1 (Servo %2): Offset %3, Grenzen %4 bis %5</translation>
    </message>
    <message>
        <source> (not written: --dry-run)</source>
        <translation> (nicht geschrieben: --dry-run)</translation>
    </message>
    <message>
        <source>, written and verified</source>
        <translation>, geschrieben und überprüft</translation>
    </message>
    <message>
        <source>, NOT verified: %1</source>
        <translation>, NICHT überprüft: %1</translation>
    </message>
    <message numerus="yes">
        <source>saved %n joint(s) to %1</source>
        <translation>
            <numerusform>%n Gelenk in %1 gespeichert</numerusform>
            <numerusform>%n Gelenke in %1 gespeichert</numerusform>
        </translation>
    </message>
    <message>
        <source>no joint could be calibrated; %1 was not written</source>
        <translation>kein Gelenk konnte kalibriert werden; %1 wurde nicht geschrieben</translation>
    </message>
    <message>
        <source>not every joint was calibrated: see the refusals above</source>
        <translation>nicht jedes Gelenk wurde kalibriert: siehe die Ablehnungen oben</translation>
    </message>
    <message>
        <source>servoctl: torque is off; move every joint through its whole range for %1 s</source>
        <translation>servoctl: Drehmoment ist aus; bewegen Sie jedes Gelenk %1 s lang durch seinen ganzen Bereich</translation>
    </message>
    <message>
        <source>servoctl: torque is off; move every joint through its whole range, then press Enter</source>
        <translation>servoctl: Drehmoment ist aus; bewegen Sie jedes Gelenk durch seinen ganzen Bereich und drücken Sie dann Enter</translation>
    </message>
    <message>
        <source>interrupted: nothing was written (torque stays off)</source>
        <translation>unterbrochen: nichts geschrieben (Drehmoment bleibt aus)</translation>
    </message>
    <message>
        <source>joint</source>
        <translation>Gelenk</translation>
    </message>
    <message>
        <source>min</source>
        <translation>Min</translation>
    </message>
    <message>
        <source>present</source>
        <translation>aktuell</translation>
    </message>
    <message>
        <source>max</source>
        <translation>Max</translation>
    </message>
    <message>
        <source>  (stopped answering)</source>
        <translation>  (antwortet nicht mehr)</translation>
    </message>
    <message>
        <source>%1 needs save or load</source>
        <translation>%1 braucht save oder load</translation>
    </message>
    <message>
        <source>unknown %1 command &quot;%2&quot;: use save or load</source>
        <translation>unbekannter %1-Befehl &quot;%2&quot;: verwenden Sie save oder load</translation>
    </message>
    <message>
        <source>servo %1 holds the limits %2 to %3, which are no calibrated range (min = max = 0 is multi-turn mode); %4 was not written</source>
        <translation>Servo %1 hat die Grenzen %2 bis %3, die kein kalibrierter Bereich sind (min = max = 0 ist der Multiturn-Modus); %4 wurde nicht geschrieben</translation>
    </message>
    <message numerus="yes">
        <source>saved the calibration of %n servo(s) to %1</source>
        <translation>
            <numerusform>Kalibrierung von %n Servo in %1 gespeichert</numerusform>
            <numerusform>Kalibrierung von %n Servos in %1 gespeichert</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 (servo %2)</source>
        <translation>%1 (Servo %2)</translation>
    </message>
    <message>
        <source>%1: already holds the file&apos;s values</source>
        <translation>%1: enthält bereits die Werte der Datei</translation>
    </message>
    <message>
        <source>torque is on: the new offset would move the horn; switch torque off (support the arm) and load again</source>
        <translation>Drehmoment ist an: Der neue Offset würde das Servohorn bewegen; schalten Sie das Drehmoment ab (Arm dabei abstützen) und laden Sie erneut</translation>
    </message>
    <message>
        <source>%1: %2; refused, nothing written: %3</source>
        <translation>%1: %2; abgelehnt, nichts geschrieben: %3</translation>
    </message>
    <message>
        <source>%1: %2; written and verified</source>
        <translation>%1: %2; geschrieben und überprüft</translation>
    </message>
    <message>
        <source>%1: %2; NOT verified: %3</source>
        <translation>%1: %2; NICHT überprüft: %3</translation>
    </message>
    <message>
        <source>the calibration of %1 was not loaded whole: see above</source>
        <translation>die Kalibrierung von %1 wurde nicht vollständig geladen: siehe oben</translation>
    </message>
    <message>
        <source>interrupted: nothing more was sent</source>
        <translation>unterbrochen: nichts mehr gesendet</translation>
    </message>
    <message>
        <source>interrupted: %1</source>
        <translation>unterbrochen: %1</translation>
    </message>
    <message>
        <source>interrupted again before the operation ended: check the servo&apos;s torque and EEPROM lock</source>
        <translation>erneut unterbrochen, bevor der Vorgang endete: Prüfen Sie Drehmoment und EEPROM-Sperre des Servos</translation>
    </message>
    <message>
        <source>servo %1 is of an unknown model (%2): its EEPROM lock is not known</source>
        <translation>Servo %1 hat ein unbekanntes Modell (%2): Seine EEPROM-Sperre ist nicht bekannt</translation>
    </message>
    <message>
        <source>servo %1 is of an unknown model (%2): its status bits are not known</source>
        <translation>Servo %1 hat ein unbekanntes Modell (%2): Seine Statusbits sind nicht bekannt</translation>
    </message>
    <message>
        <source>after the power cycle: servoctl feetech recover --id %1 --check</source>
        <translation>nach dem Aus- und Einschalten: servoctl feetech recover --id %1 --check</translation>
    </message>
    <message>
        <source>not read</source>
        <translation>nicht gelesen</translation>
    </message>
    <message>
        <source>its identity (addresses 0-8) could not be read</source>
        <translation>seine Identität (Adressen 0-8) konnte nicht gelesen werden</translation>
    </message>
    <message>
        <source>moving servo %1 by %2 steps from %3 and back…</source>
        <translation>Servo %1 wird um %2 Schritte von %3 weg und zurück bewegt…</translation>
    </message>
    <message>
        <source>servo %1 (no answer): %2</source>
        <translation>Servo %1 (keine Antwort): %2</translation>
    </message>
    <message>
        <source>servo %1 (%2, firmware %3): %4</source>
        <translation>Servo %1 (%2, Firmware %3): %4</translation>
    </message>
    <message>
        <source>voltage %1, temperature %2, load %3, position %4, status %5</source>
        <translation>Spannung %1, Temperatur %2, Last %3, Position %4, Status %5</translation>
    </message>
    <message>
        <source>steps</source>
        <translation>Schritte</translation>
    </message>
    <message>
        <source>communication: %1</source>
        <translation>Kommunikation: %1</translation>
    </message>
    <message>
        <source>move test: %1</source>
        <translation>Bewegungstest: %1</translation>
    </message>
    <message>
        <source>not run (the servo has a fault)</source>
        <translation>nicht ausgeführt (das Servo hat einen Fehler)</translation>
    </message>
    <message>
        <source>servoctl: %1 samples in %2 s (%3 per second); %4 missed, %5 late</source>
        <translation>servoctl: %1 Messwerte in %2 s (%3 pro Sekunde); %4 verpasst, %5 verspätet</translation>
    </message>
    <message>
        <source>%1 takes --id N or --ids LIST, not both</source>
        <translation>%1 nimmt --id N oder --ids LIST an, nicht beides</translation>
    </message>
    <message>
        <source>servo %1: %2</source>
        <translation>Servo %1: %2</translation>
    </message>
    <message>
        <source>moving servo %1 a little each way, slowly…</source>
        <translation>Servo %1 wird langsam etwas in beide Richtungen bewegt…</translation>
    </message>
    <message numerus="yes">
        <source>%1 to %n servo(s):</source>
        <translation>
            <numerusform>%1 auf %n Servo:</numerusform>
            <numerusform>%1 auf %n Servos:</numerusform>
        </translation>
    </message>
    <message>
        <source>ID</source>
        <translation>ID</translation>
    </message>
    <message>
        <source>status</source>
        <translation>Status</translation>
    </message>
    <message>
        <source>changed / error</source>
        <translation>geändert / Fehler</translation>
    </message>
    <message>
        <source>%1: &quot;%2&quot; has no joint with ID %3</source>
        <translation>%1: &quot;%2&quot; hat kein Gelenk mit ID %3</translation>
    </message>
    <message>
        <source>--model: &quot;%1&quot; is no model with a known register table</source>
        <translation>--model: &quot;%1&quot; ist kein Modell mit bekannter Registertabelle</translation>
    </message>
    <message>
        <source>--model %1 does not match the template&apos;s %2 (a %3)</source>
        <translation>--model %1 passt nicht zu %2 der Vorlage (ein %3)</translation>
    </message>
    <message>
        <source>the set-up ended before it reported; check the port and the cable, then run it again</source>
        <translation>die Einrichtung endete, bevor sie ein Ergebnis meldete; prüfen Sie Anschluss und Kabel und starten Sie sie erneut</translation>
    </message>
    <message>
        <source>ptk takes no --%1</source>
        <translation>ptk nimmt kein --%1 an</translation>
    </message>
    <message>
        <source>--echo must be auto, on or off</source>
        <translation>--echo muss auto, on oder off sein</translation>
    </message>
    <message>
        <source>drive_mode %1 is LeRobot&apos;s software setting (the direction inverted), held by no register: it is kept in the file only</source>
        <translation>drive_mode %1 ist eine Software-Einstellung von LeRobot (die Richtung umgekehrt), die kein Register hält: Sie wird nur in der Datei geführt</translation>
    </message>
    <message>
        <source>%1: note: %2</source>
        <translation>%1: Hinweis: %2</translation>
    </message>
    <message>
        <source>note: servo %1&apos;s EEPROM is unlocked (lock = 0), as some programs (LeRobot among them) leave it: a setting written to it now survives a power cut. servoctl locks it again after each of its own EEPROM writes; to lock it now: servoctl feetech lock --id %1</source>
        <translation>Hinweis: Das EEPROM von Servo %1 ist entsperrt (lock = 0), wie manche Programme (darunter LeRobot) es hinterlassen: Eine jetzt geschriebene Einstellung übersteht einen Stromausfall. servoctl sperrt es nach jedem eigenen EEPROM-Schreibvorgang wieder; um es jetzt zu sperren: servoctl feetech lock --id %1</translation>
    </message>
    <message>
        <source>servo %1 answers with error bits 0x%2 (%3): servoctl doctor says why</source>
        <translation>Servo %1 antwortet mit Fehlerbits 0x%2 (%3): servoctl doctor sagt, warum</translation>
    </message>
    <message>
        <source>decode --log takes the recording only, no bytes</source>
        <translation>decode --log nimmt nur die Aufzeichnung, keine Bytes</translation>
    </message>
    <message>
        <source>share recordings are of Feetech buses: --family feetech</source>
        <translation>Freigabeaufzeichnungen sind von Feetech-Bussen: --family feetech</translation>
    </message>
    <message>
        <source>%1 --update FILE takes the joints&apos; names from the file and saves to it: no --out or --names</source>
        <translation>%1 --update FILE übernimmt die Gelenknamen aus der Datei und speichert in sie: kein --out oder --names</translation>
    </message>
    <message>
        <source>servo %1 is no joint of %2</source>
        <translation>Servo %1 ist kein Gelenk von %2</translation>
    </message>
    <message>
        <source>%1 --robot: %2</source>
        <translation>%1 --robot: %2</translation>
    </message>
    <message numerus="yes">
        <source>fixing %n setting(s)…</source>
        <translation>
            <numerusform>%n Einstellung wird behoben…</numerusform>
            <numerusform>%n Einstellungen werden behoben…</numerusform>
        </translation>
    </message>
    <message>
        <source>nothing to write fixes this</source>
        <translation>kein Schreibvorgang behebt dies</translation>
    </message>
    <message numerus="yes">
        <source>No problem found in the settings of %n servo(s).</source>
        <translation>
            <numerusform>In den Einstellungen von %n Servo wurde kein Problem gefunden.</numerusform>
            <numerusform>In den Einstellungen von %n Servos wurde kein Problem gefunden.</numerusform>
        </translation>
    </message>
    <message>
        <source>SETTING</source>
        <translation>EINSTELLUNG</translation>
    </message>
    <message>
        <source>VALUE</source>
        <translation>WERT</translation>
    </message>
    <message>
        <source>EXPECTED</source>
        <translation>ERWARTET</translation>
    </message>
    <message>
        <source>WHY</source>
        <translation>WARUM</translation>
    </message>
    <message numerus="yes">
        <source>%n finding(s); --fix writes the expected values and reads them back.</source>
        <translation>
            <numerusform>%n Befund; --fix schreibt die erwarteten Werte und liest sie zurück.</numerusform>
            <numerusform>%n Befunde; --fix schreibt die erwarteten Werte und liest sie zurück.</numerusform>
        </translation>
    </message>
    <message>
        <source>servo %1 %2: %3 → %4: %5</source>
        <translation>Servo %1 %2: %3 → %4: %5</translation>
    </message>
    <message>
        <source>--%1 must be %2</source>
        <translation>--%1 muss %2 sein</translation>
    </message>
    <message>
        <source>%1 needs --out FILE: the CSV file to record into</source>
        <translation>%1 braucht --out FILE: die CSV-Datei, in die aufgezeichnet wird</translation>
    </message>
    <message>
        <source>a number of frames per second from 1 to %1</source>
        <translation>eine Anzahl Frames pro Sekunde von 1 bis %1</translation>
    </message>
    <message>
        <source>servo %1 is of an unknown model (%2): its position cannot be read</source>
        <translation>Servo %1 hat ein unbekanntes Modell (%2): Seine Position kann nicht gelesen werden</translation>
    </message>
    <message numerus="yes">
        <source>recording %n joint(s); move them by hand, Ctrl-C ends</source>
        <translation>
            <numerusform>%n Gelenk wird aufgezeichnet; bewegen Sie es von Hand, Ctrl-C beendet</numerusform>
            <numerusform>%n Gelenke werden aufgezeichnet; bewegen Sie sie von Hand, Ctrl-C beendet</numerusform>
        </translation>
    </message>
    <message>
        <source>no frame was recorded: not every servo answered; nothing was written</source>
        <translation>es wurde kein Frame aufgezeichnet: Nicht jedes Servo hat geantwortet; nichts geschrieben</translation>
    </message>
    <message numerus="yes">
        <source>recorded %n frame(s) of %1 joint(s) over %2 s into %3</source>
        <translation>
            <numerusform>%n Frame von %1 Gelenk(en) über %2 s in %3 aufgezeichnet</numerusform>
            <numerusform>%n Frames von %1 Gelenk(en) über %2 s in %3 aufgezeichnet</numerusform>
        </translation>
    </message>
    <message>
        <source>%1; what was recorded until then is in %2</source>
        <translation>%1; was bis dahin aufgezeichnet wurde, steht in %2</translation>
    </message>
    <message>
        <source>column %1 matches no servo: %2; nothing was moved</source>
        <translation>Spalte %1 passt zu keinem Servo: %2; nichts wurde bewegt</translation>
    </message>
    <message>
        <source>column %1: servo %2 is of an unknown model (%3); nothing was moved</source>
        <translation>Spalte %1: Servo %2 hat ein unbekanntes Modell (%3); nichts wurde bewegt</translation>
    </message>
    <message>
        <source>a number above 0 (2 plays twice as fast)</source>
        <translation>eine Zahl über 0 (2 spielt doppelt so schnell ab)</translation>
    </message>
    <message>
        <source>a number of seconds from 0</source>
        <translation>eine Anzahl Sekunden ab 0</translation>
    </message>
    <message>
        <source>interrupted again before the arm was held: check the servos&apos; torque</source>
        <translation>erneut unterbrochen, bevor der Arm gehalten wurde: Prüfen Sie das Drehmoment der Servos</translation>
    </message>
    <message>
        <source>joint %1 (servo %2) does not answer: %3</source>
        <translation>Gelenk %1 (Servo %2) antwortet nicht: %3</translation>
    </message>
    <message>
        <source>joint %1 (servo %2) does not hold what %3 says (%4): write the file to the arm first: servoctl --port %5 feetech calibration load %3</source>
        <translation>Gelenk %1 (Servo %2) enthält nicht, was %3 angibt (%4): Schreiben Sie die Datei zuerst auf den Arm: servoctl --port %5 feetech calibration load %3</translation>
    </message>
    <message>
        <source>%1 needs --port FOLLOWER, --leader PORT, --calibration FILE and --leader-calibration FILE</source>
        <translation>%1 braucht --port FOLLOWER, --leader PORT, --calibration FILE und --leader-calibration FILE</translation>
    </message>
    <message>
        <source>--leader and --port name the same port: the leader and the follower are two arms on two adapters</source>
        <translation>--leader und --port nennen denselben Anschluss: Führungs- und Folgearm sind zwei Arme an zwei Adaptern</translation>
    </message>
    <message>
        <source>the two files name different joints: %1</source>
        <translation>die beiden Dateien nennen verschiedene Gelenke: %1</translation>
    </message>
    <message>
        <source>the follower&apos;s torque could not be switched on</source>
        <translation>das Drehmoment des Folgearms konnte nicht eingeschaltet werden</translation>
    </message>
    <message>
        <source>servoctl: the follower holds; it moves to the leader&apos;s pose at %1°/s at most, then follows. Ctrl-C stops (it holds).</source>
        <translation>servoctl: Der Folgearm hält; er fährt mit höchstens %1°/s in die Pose des Führungsarms und folgt ihm dann. Ctrl-C stoppt (er hält).</translation>
    </message>
    <message>
        <source>%1 was lost: %2</source>
        <translation>%1 ist nicht mehr erreichbar: %2</translation>
    </message>
    <message>
        <source>the follower</source>
        <translation>der Folgearm</translation>
    </message>
    <message>
        <source>the leader</source>
        <translation>der Führungsarm</translation>
    </message>
    <message numerus="yes">
        <source>servoctl: %n frame(s) of the follower&apos;s goals recorded in %1</source>
        <translation>
            <numerusform>servoctl: %n Frame der Ziele des Folgearms in %1 aufgezeichnet</numerusform>
            <numerusform>servoctl: %n Frames der Ziele des Folgearms in %1 aufgezeichnet</numerusform>
        </translation>
    </message>
    <message>
        <source>servoctl: %1 cycle(s) in %2 s (%3 per second), leader to follower %4 ms (median)</source>
        <translation>servoctl: %1 Zyklen in %2 s (%3 pro Sekunde), Führungs- zu Folgearm %4 ms (Median)</translation>
    </message>
    <message>
        <source>servoctl: the follower&apos;s torque is off</source>
        <translation>servoctl: Das Drehmoment des Folgearms ist aus</translation>
    </message>
    <message>
        <source>servoctl: the follower holds where it is</source>
        <translation>servoctl: Der Folgearm hält an seiner Stelle</translation>
    </message>
    <message>
        <source>servoctl: the follower could not be reached to stop it</source>
        <translation>servoctl: Der Folgearm war zum Anhalten nicht erreichbar</translation>
    </message>
    <message numerus="yes">
        <source>dropped %Ln line(s) nobody read</source>
        <translation>
            <numerusform>%Ln Zeile verworfen, die niemand las</numerusform>
            <numerusform>%Ln Zeilen verworfen, die niemand las</numerusform>
        </translation>
    </message>
    <message>
        <source>--norm-mode must be degrees (LeRobot&apos;s use_degrees, the default) or range_m100_100</source>
        <translation>--norm-mode muss degrees (LeRobots use_degrees, der Standard) oder range_m100_100 sein</translation>
    </message>
    <message>
        <source>servoctl: joints map in degrees from the middle of their ranges (LeRobot&apos;s use_degrees, norm mode degrees)</source>
        <translation>servoctl: Gelenke werden in Grad ab der Mitte ihrer Bereiche zugeordnet (LeRobots use_degrees, Normierung degrees)</translation>
    </message>
    <message>
        <source>servoctl: joints map range onto range (LeRobot&apos;s norm mode range_m100_100)</source>
        <translation>servoctl: Gelenke werden Bereich auf Bereich zugeordnet (LeRobots Normierung range_m100_100)</translation>
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
        <translation>Aufruf: servoctl [--port PATH] [--baud N] [--json] [--trace] &lt;command&gt; [args]

Befehle:
  ports                                  serielle Anschlüsse auflisten
  detect                                 herausfinden, was am Anschluss antwortet: ein PTK-Servo
                                         oder ein Feetech-Bus (seine Raten und Servos); es werden
                                         nur Abfragen, PINGs und READs gesendet
  doctor [--expect LIST [--baud N]]      sagen, was mit dem Bus nicht stimmt und was zu tun ist;
                                         LIST: die erwarteten Servos in Kettenreihenfolge
                                         (1,2,3 oder 1-6), bei --baud (1000000)
  ptk read                               die dreizehn Parameter des PTK-Servos lesen
  ptk write NAME=VALUE...                Parameter ändern (vollständige Sequenz, überprüft)
  ptk save FILE | ptk load FILE          Servo in ein Profil speichern / damit programmieren
  ptk monitor [--duration S] [--csv]     fortlaufend abfragen, eine Zeile pro Gesamtaktualisierung
  feetech scan [--baud N|all] [--ids A-B] [--thorough]
                                         die Servos am Bus finden (IDs 0-253)
  feetech ping --id N                    prüfen, ob ein Servo antwortet; sein Modell
  feetech read --id N                    jedes Register eines Servos lesen
  feetech get --id N KEY...              einzelne Register lesen
  feetech set --id N KEY=VALUE...        Register schreiben (Registereinheiten), überprüft
  feetech save --id N FILE               die EEPROM-Einstellungen des Servos in ein Profil speichern
  feetech load --id N FILE               die abweichenden Werte eines Profils schreiben
  feetech load --ids LIST FILE           dasselbe für mehrere Servos (1,2,3 oder 1-6);
                                         FILE darf eine Robotervorlage sein: Jedes Servo erhält
                                         die Einstellungen seines Gelenks nach ID; position_offset
                                         eines Profils wird nicht kopiert; einem Servo mit
                                         Drehmoment an werden Offset-/Grenzänderungen verweigert
  feetech set-id --id N NEW              dem Servo eine neue ID geben (abgelehnt, falls belegt)
  feetech set-baud --id N BAUD           das Servo auf eine andere Baudrate (bps) umstellen
  feetech calibrate-middle --id N        die aktuelle Position zur Mitte machen
  feetech factory-reset --id N [--backup FILE]
                                         Sicherungsprofil speichern, dann Werkswerte wiederherstellen
  feetech reboot --id N                  das Servo neu starten und darauf warten
  feetech lock --id N                    offen gebliebene EEPROM-Sperre schließen, zurücklesen
  feetech recover --id N [--check]       nach einer Überlastabschaltung: Drehmoment aus und an,
                                         Ziel auf die aktuelle Position, Überlastbit gelesen; noch
                                         gesetzt: die Schritte zum Aus-/Einschalten (Exit 1); nach
                                         dem Aus-/Einschalten liest --check nur das Bit
  feetech setup-motor --id N [--baud BPS] [--model MODEL] [--settings ROBOT]
                                         das eine Servo am Bus (beliebige ID, beliebige Rate) erhält
                                         ID N und Rate BPS (Standard 1000000 oder die des
                                         Roboters), überprüft; ROBOT: eine Robotervorlagen-Datei,
                                         deren Gelenk mit ID N das erwartete Modell und die zu
                                         schreibenden und zu prüfenden Einstellungen vorgibt
  feetech identify --id N                das Servo langsam hin und her bewegen, damit Sie es erkennen
  feetech health --ids LIST [--move-test]
                                         jedes Servo prüfen: Modell und Firmware, Spannung und
                                         Temperatur gegenüber seinen Grenzen, Statusbits, Last,
                                         Wiederholungen und Fehler bei 20 Abfragen, Position gegenüber
                                         seinen Grenzen; --move-test bewegt zudem jedes Servo ohne
                                         Fehler um 100 Schritte und zurück (Anstiegszeit, Überschwingen,
                                         bleibende Regelabweichung); Exit 1, wenn ein Servo einen Fehler hat
  feetech check --ids LIST [--robot ROBOT] [--fix]
                                         Einstellungen finden, die ein Servo an der Bewegung hindern oder
                                         es fehlerhaft arbeiten lassen: Phasen-Bit 4 (Multiturn), Drehmomentgrenze
                                         oder max. Drehmoment 0, ein anderer Betriebsmodus als Position,
                                         Winkelgrenzen, Antwortverzögerung, ein offenes EEPROM, gemischte
                                         Firmware, Spannungsgrenzen, die die Versorgung verletzt; ROBOT
                                         (so101-follower, ... oder eine Vorlagendatei) fügt seine
                                         Einstellungen hinzu; --fix schreibt die erwarteten Werte und liest
                                         sie zurück (Grenzen, Offset, Modus, Drehmomentgrenze und Phase
                                         nur bei Drehmoment aus); Exit 1, wenn etwas übrig bleibt
  feetech monitor --ids LIST [--rate HZ|max] [--duration S] [--csv]
                                         Position, Geschwindigkeit, Last, Spannung, Temperatur
                                         und Strom fortlaufend ausgeben (SYNC READ)
  feetech calibrate --ids LIST [--names LIST] [--full-turn LIST] [--duration S]
                    [--dry-run] --out FILE | --update FILE
                                         Drehmoment aus, Bereich jedes Gelenks von Hand aufzeichnen
                                         (Enter beendet), auf dem Encoder zentrieren: Offset und
                                         Grenzen geschrieben, LeRobot-Kalibrierung gespeichert
                                         (--update: in FILE, dessen andere Gelenke erhalten bleiben)
  feetech calibration save --ids LIST [--names LIST] FILE
                                         Offsets und Grenzen der Servos in eine LeRobot-Datei
  feetech calibration load FILE          eine LeRobot-Kalibrierdatei schreiben, überprüft
  feetech record --ids LIST --out FILE [--names LIST] [--rate HZ] [--duration S]
                                         die von Hand bewegten Positionen aufzeichnen (Drehmoment bleibt,
                                         wie es ist) bis --duration oder Ctrl-C: CSV mit
                                         time_s und einer Spalte pro Gelenk (id_N oder NAME@N),
                                         in Schritten; --rate Frames pro Sekunde (Standard 50)
  feetech replay FILE [--speed X] [--ease S] [--loop N] [--release]
                                         eine Aufzeichnung abspielen: abgelehnt, wenn ein Frame außerhalb
                                         der Winkelgrenzen eines Servos liegt; Drehmoment an, wo der Arm
                                         steht, eine sanfte Fahrt zum ersten Frame (über S
                                         Sekunden; Standard nach der Entfernung), die Frames
                                         zu ihren Zeiten (--speed 2: doppelt so schnell), N
                                         Mal, dann halten (--release: Drehmoment aus). Ctrl-C
                                         hält den Arm, wo er ist
  feetech teleop --leader PORT --calibration FILE --leader-calibration FILE
                 [--rate HZ] [--duration S] [--max-speed DEG_PER_S] [--record FILE]
                 [--release] [--norm-mode degrees|range_m100_100]
                                         der Führungsarm an PORT steuert diesen Folgearm,
                                         Gelenke nach Namen zugeordnet; Ctrl-C hält;
                                         --record: die Ziele des Folgearms, zur Wiedergabe;
                                         --norm-mode: wie LeRobot Gelenke zuordnet
                                         (degrees, sein use_degrees: der Standard)
  share --link PATH [--record FILE] [--watch] [--duration S]
                                         zwischen einem anderen Programm und den Servos:
                                         es öffnet PATH, jedes Byte wird weitergeleitet;
                                         --json gibt jede Transaktion aus, --watch liest
                                         die Servos in seinen Pausen; Warnungen auf stderr
  decode [--family ptk|feetech] HEX...   Bytes in Frames zerlegen und jeden erklären
  decode --family feetech --log FILE     eine Aufzeichnung von share Frame für Frame erklären
  packet ptk query CMD                   einen PTK-Abfrage-Frame ausgeben (CMD: 0x38, 56 oder N1..N8)
  packet ptk write NAME=VALUE...         die PTK-Schreib-Frames mit diesen Werten ausgeben
  packet feetech INSTRUCTION [--id N] [--addr A] [--data HEX] [--len N] [--ids LIST]
      INSTRUCTION: ping read write reg-write action sync-write sync-read
                   recovery reboot reset calibrate

Optionen: --port PATH (Gerätebefehle), --baud N (PTK: 115200; Feetech: die Rate
          des Servos, 1000000),
          --echo auto|on|off (Echo eines Eindraht-Adapters; Standard auto)

Der Überlast- und Temperaturschutz überwacht jedes Servo, das ein Befehl ansteuert
(identify, sowie set, solange es läuft); Warnungen und Aktionen erscheinen auf stderr.

Exit-Status: 0 erledigt, 1 Geräte- oder Verbindungsfehler, 2 Aufruffehler (nichts gesendet)
</translation>
    </message>
    <message>
        <source>ID %1: %2</source>
        <translation>ID %1: %2</translation>
    </message>
</context>
<context>
    <name>servosim</name>
    <message>
        <source>name a protocol: ptk or feetech</source>
        <translation>nennen Sie ein Protokoll: ptk oder feetech</translation>
    </message>
    <message>
        <source>unknown protocol &quot;%1&quot;: use ptk or feetech</source>
        <translation>unbekanntes Protokoll &quot;%1&quot;: verwenden Sie ptk oder feetech</translation>
    </message>
    <message>
        <source>unknown option &quot;%1&quot;</source>
        <translation>unbekannte Option &quot;%1&quot;</translation>
    </message>
    <message>
        <source>%1 needs a value</source>
        <translation>%1 braucht einen Wert</translation>
    </message>
    <message>
        <source>--seed must be a whole number from 0 to 4294967295</source>
        <translation>--seed muss eine ganze Zahl von 0 bis 4294967295 sein</translation>
    </message>
    <message>
        <source>--reply-delay-us must be 0 to 10000000</source>
        <translation>--reply-delay-us muss zwischen 0 und 10000000 liegen</translation>
    </message>
    <message>
        <source>--values is for the PTK servo</source>
        <translation>--values gilt nur für das PTK-Servo</translation>
    </message>
    <message>
        <source>--state is for a Feetech bus</source>
        <translation>--state gilt nur für einen Feetech-Bus</translation>
    </message>
    <message>
        <source>--servo is for a Feetech bus</source>
        <translation>--servo gilt nur für einen Feetech-Bus</translation>
    </message>
    <message>
        <source>--link PATH is required</source>
        <translation>--link PATH ist erforderlich</translation>
    </message>
    <message>
        <source>#%1 (ID %2)</source>
        <translation>#%1 (ID %2)</translation>
    </message>
    <message>
        <source>no servos</source>
        <translation>keine Servos</translation>
    </message>
    <message>
        <source>%1 takes: %2</source>
        <translation>%1 erwartet: %2</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a supply from 0 to 30 V</source>
        <translation>&quot;%1&quot; ist keine Versorgungsspannung von 0 bis 30 V</translation>
    </message>
    <message>
        <source>the supply is %1 V</source>
        <translation>die Versorgung beträgt %1 V</translation>
    </message>
    <message>
        <source>the daisy chain is whole</source>
        <translation>die Daisy-Chain ist intakt</translation>
    </message>
    <message>
        <source>%1 has power</source>
        <translation>%1 hat Strom</translation>
    </message>
    <message>
        <source>%1 has no power</source>
        <translation>%1 hat keinen Strom</translation>
    </message>
    <message>
        <source>%1 loses power once its EEPROM lock is opened</source>
        <translation>%1 verliert den Strom, sobald seine EEPROM-Sperre geöffnet wird</translation>
    </message>
    <message>
        <source>%1 loses power after its next EEPROM write</source>
        <translation>%1 verliert den Strom nach seinem nächsten EEPROM-Schreibvorgang</translation>
    </message>
    <message>
        <source>the daisy chain is broken after %1</source>
        <translation>die Daisy-Chain ist nach %1 unterbrochen</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a rate from -10 to 10 °C/s</source>
        <translation>&quot;%1&quot; ist keine Rate von -10 bis 10 °C/s</translation>
    </message>
    <message>
        <source>%1 warms by %2 °C/s</source>
        <translation>%1 erwärmt sich um %2 °C/s</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a temperature from -20 to 120 °C</source>
        <translation>&quot;%1&quot; ist keine Temperatur von -20 bis 120 °C</translation>
    </message>
    <message>
        <source>%1 is at %2 °C</source>
        <translation>%1 hat %2 °C</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a load from -1000 to 1000 ‰</source>
        <translation>&quot;%1&quot; ist keine Last von -1000 bis 1000 ‰</translation>
    </message>
    <message>
        <source>%1&apos;s horn is held with a load of %2 ‰</source>
        <translation>das Servohorn von %1 wird mit einer Last von %2 ‰ gehalten</translation>
    </message>
    <message>
        <source>%1&apos;s horn is free</source>
        <translation>das Servohorn von %1 ist frei</translation>
    </message>
    <message>
        <source>%1&apos;s overload is latched until a power cycle</source>
        <translation>die Überlastabschaltung von %1 bleibt bis zum Aus- und Einschalten eingerastet</translation>
    </message>
    <message>
        <source>no power</source>
        <translation>kein Strom</translation>
    </message>
    <message>
        <source>horn blocked</source>
        <translation>Servohorn blockiert</translation>
    </message>
    <message>
        <source>overload latched</source>
        <translation>Überlast eingerastet</translation>
    </message>
    <message>
        <source>heating %1 °C/s</source>
        <translation>erwärmt sich mit %1 °C/s</translation>
    </message>
    <message>
        <source>cooling %1 °C/s</source>
        <translation>kühlt ab mit %1 °C/s</translation>
    </message>
    <message>
        <source>there is no servo %1: the bus has #1 to #%2</source>
        <translation>es gibt kein Servo %1: der Bus hat #1 bis #%2</translation>
    </message>
    <message>
        <source>&quot;%1&quot; names no servo: give an ID (0 to %2) or a place as #N</source>
        <translation>&quot;%1&quot; nennt kein Servo: geben Sie eine ID (0 bis %2) oder einen Platz als #N an</translation>
    </message>
    <message>
        <source>commands: turn SERVO POS | sweep SERVO FROM TO SECONDS [CYCLES] [up|down] | release | plug ID:MODEL[@BAUD] | unplug SERVO | set-id SERVO ID | list | power-cycle | power SERVO on|off | break-chain SERVO|none | supply VOLTS | heat SERVO C_PER_S | temperature SERVO C | block SERVO [PERMILLE] | unblock SERVO | latch SERVO | power-cut SERVO after-unlock|after-write | help; SERVO is an ID or a place #N from list</source>
        <translation>Befehle: turn SERVO POS | sweep SERVO FROM TO SECONDS [CYCLES] [up|down] | release | plug ID:MODEL[@BAUD] | unplug SERVO | set-id SERVO ID | list | power-cycle | power SERVO on|off | break-chain SERVO|none | supply VOLTS | heat SERVO C_PER_S | temperature SERVO C | block SERVO [PERMILLE] | unblock SERVO | latch SERVO | power-cut SERVO after-unlock|after-write | help; SERVO ist eine ID oder ein Platz #N aus list</translation>
    </message>
    <message>
        <source>unknown command &quot;%1&quot;: try help</source>
        <translation>unbekannter Befehl &quot;%1&quot;: versuchen Sie help</translation>
    </message>
    <message>
        <source>power-cycled</source>
        <translation>aus- und wieder eingeschaltet</translation>
    </message>
    <message>
        <source>%1 is for a Feetech bus; this is a PTK servo</source>
        <translation>%1 ist für einen Feetech-Bus; dies ist ein PTK-Servo</translation>
    </message>
    <message numerus="yes">
        <source>the hand let go of %n sweep(s)</source>
        <translation>
            <numerusform>die Hand hat %n Schwenk losgelassen</numerusform>
            <numerusform>die Hand hat %n Schwenks losgelassen</numerusform>
        </translation>
    </message>
    <message>
        <source>plugged %1: %2 at %3 bps</source>
        <translation>%1 angeschlossen: %2 bei %3 bps</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a position from 0 to 4095</source>
        <translation>&quot;%1&quot; ist keine Position von 0 bis 4095</translation>
    </message>
    <message>
        <source>turned %1 to %2</source>
        <translation>%1 auf %2 gedreht</translation>
    </message>
    <message>
        <source>until released</source>
        <translation>bis losgelassen</translation>
    </message>
    <message numerus="yes">
        <source>%n time(s)</source>
        <translation>
            <numerusform>einmal</numerusform>
            <numerusform>%n Mal</numerusform>
        </translation>
    </message>
    <message>
        <source>sweeping %1 from %2 to %3 and back every %4 s, %5</source>
        <translation>schwenkt %1 von %2 nach %3 und zurück, alle %4 s, %5</translation>
    </message>
    <message>
        <source>unplugged %1</source>
        <translation>%1 abgezogen</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not an ID from 0 to %2</source>
        <translation>&quot;%1&quot; ist keine ID von 0 bis %2</translation>
    </message>
    <message>
        <source>servo #%1 is now at ID %2</source>
        <translation>Servo #%1 hat jetzt ID %2</translation>
    </message>
    <message>
        <source>--allow-shared-ids is for a Feetech bus</source>
        <translation>--allow-shared-ids gilt nur für einen Feetech-Bus</translation>
    </message>
    <message>
        <source>unknown adapter &quot;%1&quot;: use %2</source>
        <translation>unbekannter Adapter &quot;%1&quot;: verwenden Sie %2</translation>
    </message>
    <message>
        <source>--robot is for a Feetech bus</source>
        <translation>--robot gilt nur für einen Feetech-Bus</translation>
    </message>
    <message>
        <source>--robot may be given once</source>
        <translation>--robot darf nur einmal angegeben werden</translation>
    </message>
    <message>
        <source>--hand is for a Feetech bus</source>
        <translation>--hand gilt nur für einen Feetech-Bus</translation>
    </message>
    <message>
        <source>a Feetech bus needs at least one --servo ID:MODEL[@BAUD] or a --robot</source>
        <translation>ein Feetech-Bus braucht mindestens ein --servo ID:MODEL[@BAUD] oder ein --robot</translation>
    </message>
    <message>
        <source>%1 &quot;%2&quot; is not ID:MODEL[@BAUD]</source>
        <translation>%1 &quot;%2&quot; ist nicht ID:MODEL[@BAUD]</translation>
    </message>
    <message>
        <source>%1 &quot;%2&quot;: ID %3 is over %4</source>
        <translation>%1 &quot;%2&quot;: ID %3 ist größer als %4</translation>
    </message>
    <message>
        <source>%1 &quot;%2&quot; names no model</source>
        <translation>%1 &quot;%2&quot; nennt kein Modell</translation>
    </message>
    <message>
        <source>%1 &quot;%2&quot;: bad baud rate</source>
        <translation>%1 &quot;%2&quot;: ungültige Baudrate</translation>
    </message>
    <message>
        <source>expected ID FROM TO SECONDS [CYCLES] [up|down]</source>
        <translation>erwartet: ID FROM TO SECONDS [CYCLES] [up|down]</translation>
    </message>
    <message>
        <source>the ID must be 0 to %1, not &quot;%2&quot;</source>
        <translation>die ID muss 0 bis %1 sein, nicht &quot;%2&quot;</translation>
    </message>
    <message>
        <source>FROM and TO must be positions from 0 to 4095</source>
        <translation>FROM und TO müssen Positionen von 0 bis 4095 sein</translation>
    </message>
    <message>
        <source>SECONDS must be a number above 0 and at most %1, not &quot;%2&quot;</source>
        <translation>SECONDS muss eine Zahl über 0 und höchstens %1 sein, nicht &quot;%2&quot;</translation>
    </message>
    <message>
        <source>CYCLES must be a whole number from 0 (until released) to %1, not &quot;%2&quot;</source>
        <translation>CYCLES muss eine ganze Zahl von 0 (bis losgelassen) bis %1 sein, nicht &quot;%2&quot;</translation>
    </message>
    <message>
        <source>unknown robot &quot;%1&quot;: use %2</source>
        <translation>unbekannter Roboter &quot;%1&quot;: verwenden Sie %2</translation>
    </message>
    <message>
        <source> (--allow-shared-ids lets them share it, their replies colliding)</source>
        <translation> (mit --allow-shared-ids dürfen sie sie teilen; ihre Antworten kollidieren dann)</translation>
    </message>
    <message>
        <source>--hand for ID %1: %2</source>
        <translation>--hand für ID %1: %2</translation>
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
        <translation>Aufruf: servosim ptk --link PATH [--values KEY=V,...] [Optionen]
        servosim feetech --link PATH --servo ID:MODEL[@BAUD] [--servo ...] [--state FILE] [Optionen]
        servosim feetech --link PATH --robot so101 [--servo ...] [Optionen]

Feetech-Optionen:
  --servo ID:MODEL[@BAUD]  ein Servo am Bus (BAUD: die Standardrate der Familie)
  --allow-shared-ids       zwei --servo eine ID bei einer Rate teilen lassen (Antworten kollidieren)
  --robot NAME             ein eingerichteter Arm aus einer eingebauten Vorlage, Servohörner in Ruhe:
                           so101, so100 (Folgearme), so101-leader, so100-leader
  --hand ID:FROM:TO:SECONDS[:CYCLES][:up|down]
                           die Hand schwenkt ein Gelenk mit abgeschaltetem Drehmoment von FROM
                           nach TO und zurück in SECONDS, CYCLES-mal (0 oder none: bis
                           losgelassen); up oder down überquert bei Bedarf die Naht 4095/0
  --state FILE             das EEPROM der Servos über mehrere Läufe in FILE aufbewahren
  --command LINE           ein Befehl wie auf der Standardeingabe, ausgeführt vor &quot;ready&quot;, z. B.
                           &quot;break-chain 2&quot;, &quot;supply 12.6&quot;, &quot;block 3&quot; (wiederholbar)

Optionen:
  --echo                 jedes Host-Byte zuerst zurücksenden (Eindraht-Adapter)
  --faults SPEC          drop=P,corrupt=P,truncate=P,noise=P,delay=MS,lost=P (P: 0-1;
                         lost: ein Host-Frame erreicht die Servos nie)
  --seed N               Startwert des Fehlergenerators (Standard 1)
  --log FILE             jeden Frame ein und aus protokollieren, hex, mit Zeitstempel
  --reply-delay-us N     zusätzliche Verzögerung vor jeder Antwort
  --adapter PROFILE      Antworten wie ein USB-Adapter liefern: ideal (das eigene Timing
                         des pty, Standard), instant (sobald ein Frame vollständig ist,
                         ohne Leitungszeit), ftdi (16-ms-Latenz-Timer), ftdi-1ms,
                         ch340, ch343, cp2102

Gibt &quot;ready PATH&quot; aus, sobald ein Client PATH öffnen kann; läuft bis SIGINT oder SIGTERM;
SIGHUP schaltet die Servos aus und wieder ein. Liest Befehle von der Standardeingabe,
einen pro Zeile, und beantwortet jeden mit einer Zeile, &quot;ok ...&quot; oder &quot;error ...&quot; (&quot;help&quot;
listet sie auf); das Ende der Standardeingabe beendet es nicht.
</translation>
    </message>
</context>
<context>
    <name>util</name>
    <message>
        <source>odd number of hex digits in &quot;%1&quot;</source>
        <translation>ungerade Anzahl Hex-Ziffern in &quot;%1&quot;</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not hexadecimal</source>
        <translation>&quot;%1&quot; ist nicht hexadezimal</translation>
    </message>
    <message>
        <source>not valid JSON: %1 at offset %2</source>
        <translation>kein gültiges JSON: %1 bei Offset %2</translation>
    </message>
    <message>
        <source>the format version is missing or not a whole number</source>
        <translation>die Formatversion fehlt oder ist keine ganze Zahl</translation>
    </message>
    <message>
        <source>unknown format version %1</source>
        <translation>unbekannte Formatversion %1</translation>
    </message>
    <message>
        <source>unknown entry &quot;%1&quot;</source>
        <translation>unbekannter Eintrag &quot;%1&quot;</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>%1 was not saved: %2</source>
        <translation>%1 wurde nicht gespeichert: %2</translation>
    </message>
    <message>
        <source>%1; it was not saved</source>
        <translation>%1; sie wurde nicht gespeichert</translation>
    </message>
    <message>
        <source>Could not open %1 for writing: %2.</source>
        <translation>%1 konnte nicht zum Schreiben geöffnet werden: %2.</translation>
    </message>
</context>
</TS>
