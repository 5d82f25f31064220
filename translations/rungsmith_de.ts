<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de">
<context>
    <name>BlockDocumentation</name>
    <message>
        <source>Library %1, version %2. Block version %3.</source>
        <translation>Bibliothek %1, Version %2. Bausteinversion %3.</translation>
    </message>
    <message>
        <source>A system block: the simulator carries out its instruction %1, which the language cannot say.</source>
        <translation>Ein Systembaustein: Der Simulator führt seine Anweisung %1 aus, die die Sprache nicht ausdrücken kann.</translation>
    </message>
    <message>
        <source>Pins</source>
        <translation>Anschlüsse</translation>
    </message>
    <message>
        <source>Pin</source>
        <translation>Anschluss</translation>
    </message>
    <message>
        <source>Kind</source>
        <translation>Art</translation>
    </message>
    <message>
        <source>When not bound</source>
        <translation>Wenn nicht beschaltet</translation>
    </message>
    <message>
        <source>default %1</source>
        <translation>Vorgabe %1</translation>
    </message>
    <message>
        <source>must be bound</source>
        <translation>muss beschaltet werden</translation>
    </message>
    <message>
        <source>may stay open</source>
        <translation>darf offen bleiben</translation>
    </message>
    <message>
        <source>Timing diagram</source>
        <translation>Zeitdiagramm</translation>
    </message>
    <message>
        <source>No timing diagram: %1</source>
        <translation>Kein Zeitdiagramm: %1</translation>
    </message>
    <message>
        <source>The pins of the example project %1 while its scenario %2 runs, from power on.</source>
        <translation>Die Anschlüsse des Beispielprojekts %1, während sein Szenario %2 läuft, ab dem Einschalten.</translation>
    </message>
    <message numerus="yes">
        <source>All %n expectation(s) of the scenario held.</source>
        <translation>
            <numerusform>Die eine Erwartung des Szenarios traf zu.</numerusform>
            <numerusform>Alle %n Erwartungen des Szenarios trafen zu.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n expectation(s) of the scenario failed: the diagram shows what the block did, not what the example expects.</source>
        <translation>
            <numerusform>%n Erwartung des Szenarios traf nicht zu: Das Diagramm zeigt, was der Baustein tat, nicht was das Beispiel erwartet.</numerusform>
            <numerusform>%n Erwartungen des Szenarios trafen nicht zu: Das Diagramm zeigt, was der Baustein tat, nicht was das Beispiel erwartet.</numerusform>
        </translation>
    </message>
    <message>
        <source>States</source>
        <translation>Zustände</translation>
    </message>
    <message>
        <source>DiagCode holds the state as its 16-bit pattern (16#8000 reads -32768 in a register). The outputs each state switches on:</source>
        <translation>DiagCode enthält den Zustand als 16-Bit-Muster (16#8000 liest sich in einem Register als -32768). Die Ausgänge, die jeder Zustand einschaltet:</translation>
    </message>
    <message>
        <source>The outputs each state switches on:</source>
        <translation>Die Ausgänge, die jeder Zustand einschaltet:</translation>
    </message>
    <message>
        <source>State</source>
        <translation>Zustand</translation>
    </message>
    <message>
        <source>Meaning</source>
        <translation>Bedeutung</translation>
    </message>
    <message>
        <source>Transitions</source>
        <translation>Übergänge</translation>
    </message>
    <message>
        <source>Each scan takes at most one transition: the first of the state&apos;s list whose condition holds. The outputs then follow the new state. In the conditions * is AND, + is OR and / is NOT, as in the program.</source>
        <translation>Jeder Zyklus nimmt höchstens einen Übergang: den ersten der Liste des Zustands, dessen Bedingung erfüllt ist. Die Ausgänge folgen dann dem neuen Zustand. In den Bedingungen ist * UND, + ODER und / NICHT, wie im Programm.</translation>
    </message>
    <message>
        <source>In state</source>
        <translation>Im Zustand</translation>
    </message>
    <message>
        <source>Condition</source>
        <translation>Bedingung</translation>
    </message>
    <message>
        <source>Next state</source>
        <translation>Nächster Zustand</translation>
    </message>
    <message>
        <source>always</source>
        <translation>immer</translation>
    </message>
    <message>
        <source>any</source>
        <translation>jeder</translation>
    </message>
    <message>
        <source>The other lines of the block&apos;s body, which the conditions and outputs use:</source>
        <translation>Die übrigen Zeilen des Bausteins, die die Bedingungen und Ausgänge verwenden:</translation>
    </message>
</context>
<context>
    <name>BlockText</name>
    <message>
        <source>A system block: the simulator carries out its instruction %1.</source>
        <translation>Ein Systembaustein: der Simulator führt seinen Befehl %1 aus.</translation>
    </message>
    <message>
        <source>library %1, version %2</source>
        <translation>Bibliothek %1, Version %2</translation>
    </message>
    <message>
        <source>may stay open</source>
        <translation>darf offen bleiben</translation>
    </message>
    <message>
        <source>must be bound</source>
        <translation>muss beschaltet werden</translation>
    </message>
    <message>
        <source>default %1</source>
        <translation>Vorgabe %1</translation>
    </message>
    <message>
        <source>constant</source>
        <translation>Konstante</translation>
    </message>
    <message>
        <source>time</source>
        <translation>Zeit</translation>
    </message>
    <message>
        <source>double register</source>
        <translation>Doppelregister</translation>
    </message>
    <message>
        <source>register</source>
        <translation>Register</translation>
    </message>
    <message>
        <source>bit</source>
        <translation>Bit</translation>
    </message>
    <message>
        <source>output</source>
        <translation>Ausgang</translation>
    </message>
    <message>
        <source>input</source>
        <translation>Eingang</translation>
    </message>
</context>
<context>
    <name>CommandLine</name>
    <message>
        <source>IDE for Pluto safety PLCs.</source>
        <translation>Entwicklungsumgebung für Pluto-Sicherheitssteuerungen.</translation>
    </message>
    <message>
        <source>The project to open. Without it, the bundled example opens.</source>
        <translation>Das zu öffnende Projekt. Ohne Angabe öffnet sich das mitgelieferte Beispiel.</translation>
    </message>
    <message>
        <source>Save a picture of the main window to OUT.png and exit.</source>
        <translation>Ein Bild des Hauptfensters in OUT.png speichern und beenden.</translation>
    </message>
    <message>
        <source>give at most one project file</source>
        <translation>höchstens eine Projektdatei angeben</translation>
    </message>
    <message>
        <source>the example</source>
        <translation>das Beispiel</translation>
    </message>
    <message>
        <source>%1 has no unit %2</source>
        <translation>%1 hat keine Einheit %2</translation>
    </message>
    <message>
        <source>cannot write %1: %2</source>
        <translation>%1 kann nicht geschrieben werden: %2</translation>
    </message>
    <message>
        <source>Draw with the light or dark palette, or the system&apos;s, this time.</source>
        <translation>Dieses Mal mit heller oder dunkler Palette zeichnen oder mit der des Systems.</translation>
    </message>
    <message>
        <source>unknown theme &apos;%1&apos;; use light, dark or system</source>
        <translation>unbekanntes Design &apos;%1&apos;; verwenden Sie light, dark oder system</translation>
    </message>
    <message>
        <source>Run the scenario in the simulator first, so the window shows the live state it ends in.</source>
        <translation>Zuerst das Szenario im Simulator ausführen, damit das Fenster den Zustand zeigt, in dem es endet.</translation>
    </message>
    <message>
        <source>%1 has no sequence %2 in unit %3</source>
        <translation>%1 hat keine Sequenz %2 in Einheit %3</translation>
    </message>
    <message>
        <source>%1 has no gateway %2</source>
        <translation>%1 hat kein Gateway %2</translation>
    </message>
    <message>
        <source>The page to show: ladder:N (the code of unit N as ladder), text:N (as text), ladder:N.S or text:N.S (its sequence S), io:N (its I/O options), asi:N (its AS-i options), variables:N, unit:N, gateway:N (the gateway with node address N), project, or properties (the project&apos;s properties and their proofs).</source>
        <translation>Die anzuzeigende Seite: ladder:N (der Code der Einheit N als Kontaktplan), text:N (als Text), ladder:N.S oder text:N.S (ihre Sequenz S), io:N (ihre E/A-Optionen), asi:N (ihre AS-i-Optionen), variables:N, unit:N, gateway:N (das Gateway mit der Knotenadresse N), project oder properties (die Eigenschaften des Projekts und ihre Beweise).</translation>
    </message>
    <message>
        <source>Prove the project&apos;s properties first (Build &gt; Prove All), so the window shows their results.</source>
        <translation>Zuerst die Eigenschaften des Projekts beweisen (Erstellen &gt; Alle beweisen), damit das Fenster ihre Ergebnisse zeigt.</translation>
    </message>
    <message>
        <source>unknown page &apos;%1&apos;; the pages are ladder:N, text:N, io:N, asi:N, variables:N and unit:N for unit N, ladder:N.S and text:N.S for its sequence S, gateway:N for gateway N, project and properties</source>
        <translation>unbekannte Seite &apos;%1&apos;; die Seiten sind ladder:N, text:N, io:N, asi:N, variables:N und unit:N für die Einheit N, ladder:N.S und text:N.S für ihre Sequenz S, gateway:N für das Gateway N, project und properties</translation>
    </message>
    <message>
        <source>%1 does not read, so it has no properties page</source>
        <translation>%1 lässt sich nicht lesen und hat deshalb keine Eigenschaftsseite</translation>
    </message>
    <message>
        <source>%1 is a PL110 program: its pages are ladder:N (from rung N), text:N and variables:N</source>
        <translation>%1 ist ein PL110-Programm: seine Seiten sind ladder:N (ab Netzwerk N), text:N und variables:N</translation>
    </message>
    <message>
        <source>%1 has no rung %2</source>
        <translation>%1 hat kein Netzwerk %2</translation>
    </message>
    <message>
        <source>%1 is a PL110 program; proofs are for Pluto projects</source>
        <translation>%1 ist ein PL110-Programm; Beweise gibt es für Pluto-Projekte</translation>
    </message>
</context>
<context>
    <name>ElementKinds</name>
    <message>
        <source>Contact (NO)</source>
        <translation>Kontakt, Schließer (NO)</translation>
    </message>
    <message>
        <source>Contact (NC)</source>
        <translation>Kontakt, Öffner (NC)</translation>
    </message>
    <message>
        <source>Positive Edge (P)</source>
        <translation>Positive Flanke (P)</translation>
    </message>
    <message>
        <source>Negative Edge (N)</source>
        <translation>Negative Flanke (N)</translation>
    </message>
    <message>
        <source>Not Positive Edge (/P)</source>
        <translation>Nicht positive Flanke (/P)</translation>
    </message>
    <message>
        <source>Not Negative Edge (/N)</source>
        <translation>Nicht negative Flanke (/N)</translation>
    </message>
    <message>
        <source>On-Delay Timer (TON)</source>
        <translation>Einschaltverzögerter Timer (TON)</translation>
    </message>
    <message>
        <source>Pulse Timer (TPS)</source>
        <translation>Impulstimer (TPS)</translation>
    </message>
    <message>
        <source>Off-Delay Timer (TOF)</source>
        <translation>Ausschaltverzögerter Timer (TOF)</translation>
    </message>
    <message>
        <source>Comparison</source>
        <translation>Vergleich</translation>
    </message>
    <message>
        <source>Coil</source>
        <translation>Spule</translation>
    </message>
    <message>
        <source>Set Latch</source>
        <translation>Setzspule</translation>
    </message>
    <message>
        <source>Reset Latch</source>
        <translation>Rücksetzspule</translation>
    </message>
    <message>
        <source>Toggle Latch</source>
        <translation>Umschaltspule</translation>
    </message>
    <message>
        <source>Jump</source>
        <translation>Sprung</translation>
    </message>
    <message>
        <source>Sequence Reset</source>
        <translation>Sequenzrücksetzung</translation>
    </message>
    <message>
        <source>Arithmetic</source>
        <translation>Arithmetik</translation>
    </message>
    <message>
        <source>Preset (time such as 2s50, or a register):</source>
        <translation>Vorgabewert (eine Zeit wie 2s50 oder ein Register):</translation>
    </message>
    <message>
        <source>Register:</source>
        <translation>Register:</translation>
    </message>
    <message>
        <source>Target register:</source>
        <translation>Zielregister:</translation>
    </message>
    <message>
        <source>Step (number, or +n / -n relative):</source>
        <translation>Schritt (Nummer oder relativ +n / -n):</translation>
    </message>
    <message>
        <source>Sequence (such as S0.1):</source>
        <translation>Sequenz (z. B. S0.1):</translation>
    </message>
    <message>
        <source>Variable:</source>
        <translation>Variable:</translation>
    </message>
</context>
<context>
    <name>InstanceVariableText</name>
    <message>
        <source>Private variable #%1 of block %2 (line %3)</source>
        <translation>Private Variable #%1 des Bausteins %2 (Zeile %3)</translation>
    </message>
    <message>
        <source>Pin %1 of block %2 (line %3)</source>
        <translation>Anschluss %1 des Bausteins %2 (Zeile %3)</translation>
    </message>
</context>
<context>
    <name>LadderActions</name>
    <message>
        <source>&amp;Make Block...</source>
        <translation>Baustein &amp;erstellen...</translation>
    </message>
    <message>
        <source>&amp;Update Block</source>
        <translation>Baustein &amp;aktualisieren</translation>
    </message>
    <message>
        <source>F</source>
        <translation>F</translation>
    </message>
    <message>
        <source>A new network holding a function block of the libraries</source>
        <translation>Ein neues Netzwerk mit einem Funktionsbaustein der Bibliotheken</translation>
    </message>
    <message>
        <source>&amp;Function...</source>
        <translation>&amp;Funktion...</translation>
    </message>
    <message>
        <source>%1 (key %2)</source>
        <translation>%1 (Taste %2)</translation>
    </message>
    <message>
        <source>Text</source>
        <translation>Text</translation>
    </message>
    <message>
        <source>Show this code as text</source>
        <translation>Diesen Code als Text zeigen</translation>
    </message>
    <message>
        <source>After</source>
        <translation>Danach</translation>
    </message>
    <message>
        <source>Insert in series after the selection</source>
        <translation>In Reihe nach der Auswahl einfügen</translation>
    </message>
    <message>
        <source>Before</source>
        <translation>Davor</translation>
    </message>
    <message>
        <source>Insert in series before the selection</source>
        <translation>In Reihe vor der Auswahl einfügen</translation>
    </message>
    <message>
        <source>Parallel</source>
        <translation>Parallel</translation>
    </message>
    <message>
        <source>Insert in a parallel branch around the selection</source>
        <translation>In einem parallelen Zweig um die Auswahl einfügen</translation>
    </message>
    <message>
        <source>&amp;Delete</source>
        <translation>&amp;Löschen</translation>
    </message>
    <message>
        <source>Delete the selected element</source>
        <translation>Das ausgewählte Element löschen</translation>
    </message>
    <message>
        <source>&amp;New Network</source>
        <translation>&amp;Neues Netzwerk</translation>
    </message>
    <message>
        <source>A new network below the selected one</source>
        <translation>Ein neues Netzwerk unter dem ausgewählten</translation>
    </message>
    <message>
        <source>Expand All</source>
        <translation>Alle aufklappen</translation>
    </message>
    <message>
        <source>Show the rungs of every network</source>
        <translation>Die Strompfade aller Netzwerke zeigen</translation>
    </message>
    <message>
        <source>Collapse All</source>
        <translation>Alle zuklappen</translation>
    </message>
    <message>
        <source>Show only the comments of the networks</source>
        <translation>Nur die Kommentare der Netzwerke zeigen</translation>
    </message>
    <message>
        <source>&amp;Edit Network</source>
        <translation>Netzwerk &amp;bearbeiten</translation>
    </message>
    <message>
        <source>Gather the next edits of this network until Update</source>
        <translation>Die nächsten Änderungen an diesem Netzwerk bis Aktualisieren sammeln</translation>
    </message>
    <message>
        <source>Update</source>
        <translation>Aktualisieren</translation>
    </message>
    <message>
        <source>Keep the edits of the network as one step</source>
        <translation>Die Änderungen am Netzwerk als einen einzigen Bearbeitungsschritt übernehmen</translation>
    </message>
    <message>
        <source>Undo Network</source>
        <translation>Netzwerk rückgängig</translation>
    </message>
    <message>
        <source>Drop the edits of the network</source>
        <translation>Die Änderungen am Netzwerk verwerfen</translation>
    </message>
    <message>
        <source>Zoom In</source>
        <translation>Vergrößern</translation>
    </message>
    <message>
        <source>Zoom in</source>
        <translation>Vergrößern</translation>
    </message>
    <message>
        <source>Zoom Out</source>
        <translation>Verkleinern</translation>
    </message>
    <message>
        <source>Zoom out</source>
        <translation>Verkleinern</translation>
    </message>
    <message>
        <source>100%</source>
        <translation>100 %</translation>
    </message>
    <message>
        <source>Actual size</source>
        <translation>Originalgröße</translation>
    </message>
    <message>
        <source>Print...</source>
        <translation>Drucken …</translation>
    </message>
    <message>
        <source>Print the networks of this page</source>
        <translation>Die Netzwerke dieser Seite drucken</translation>
    </message>
    <message>
        <source>PDF...</source>
        <translation>PDF …</translation>
    </message>
    <message>
        <source>Export the networks of this page as PDF</source>
        <translation>Die Netzwerke dieser Seite als PDF exportieren</translation>
    </message>
    <message>
        <source>P&amp;roperties...</source>
        <translation>&amp;Eigenschaften …</translation>
    </message>
    <message>
        <source>&amp;Toggle</source>
        <translation>&amp;Umschalten</translation>
    </message>
    <message>
        <source>&amp;Force...</source>
        <translation>&amp;Forcen …</translation>
    </message>
    <message>
        <source>Move Left</source>
        <translation>Nach links</translation>
    </message>
    <message>
        <source>Move Right</source>
        <translation>Nach rechts</translation>
    </message>
    <message>
        <source>Move Up</source>
        <translation>Nach oben</translation>
    </message>
    <message>
        <source>Move Down</source>
        <translation>Nach unten</translation>
    </message>
    <message>
        <source>Select Enclosing Group</source>
        <translation>Umgebende Gruppe auswählen</translation>
    </message>
    <message>
        <source>Select Network</source>
        <translation>Netzwerk auswählen</translation>
    </message>
    <message>
        <source>New &amp;Config Option...</source>
        <translation>Neue &amp;Konfigurationsoption …</translation>
    </message>
    <message>
        <source>Cu&amp;t Network(s)</source>
        <translation>Netzwerk(e) &amp;ausschneiden</translation>
    </message>
    <message>
        <source>&amp;Copy Network(s)</source>
        <translation>Netzwerk(e) &amp;kopieren</translation>
    </message>
    <message>
        <source>&amp;Paste Network(s)</source>
        <translation>Netzwerk(e) ein&amp;fügen</translation>
    </message>
    <message>
        <source>&amp;Delete Network(s)</source>
        <translation>Netzwerk(e) &amp;löschen</translation>
    </message>
    <message>
        <source>Network Co&amp;mment...</source>
        <translation>Netzwerkkommen&amp;tar …</translation>
    </message>
    <message>
        <source>New &amp;Step</source>
        <translation>Neuer Sch&amp;ritt</translation>
    </message>
    <message>
        <source>New Se&amp;quence...</source>
        <translation>Neue Se&amp;quenz …</translation>
    </message>
    <message>
        <source>&amp;Block Documentation...</source>
        <translation>&amp;Bausteindokumentation...</translation>
    </message>
    <message>
        <source>Expand</source>
        <translation>Aufklappen</translation>
    </message>
    <message>
        <source>Collapse</source>
        <translation>Zuklappen</translation>
    </message>
    <message>
        <source>Edit Network</source>
        <comment>tool bar</comment>
        <translation>Bearbeiten</translation>
    </message>
    <message>
        <source>Undo Network</source>
        <comment>tool bar</comment>
        <translation>Verwerfen</translation>
    </message>
    <message>
        <source>New Network</source>
        <comment>tool bar</comment>
        <translation>+ Netzwerk</translation>
    </message>
</context>
<context>
    <name>ProjectComparison</name>
    <message numerus="yes">
        <source>%1 has %n error(s), so its behaviour cannot be compared. Build &gt; Compile lists them.</source>
        <translation>
            <numerusform>%1 hat %n Fehler, daher kann sein Verhalten nicht verglichen werden. Erstellen &gt; Kompilieren listet ihn auf.</numerusform>
            <numerusform>%1 hat %n Fehler, daher kann sein Verhalten nicht verglichen werden. Erstellen &gt; Kompilieren listet sie auf.</numerusform>
        </translation>
    </message>
    <message>
        <source>The project</source>
        <translation>Das Projekt</translation>
    </message>
</context>
<context>
    <name>ProjectMerging</name>
    <message>
        <source>Merge Project</source>
        <translation>Projekt zusammenführen</translation>
    </message>
    <message>
        <source>Open the project to merge first (File &gt; Open); its units are then added to %1.</source>
        <translation>Öffnen Sie zuerst das Projekt, das zusammengeführt werden soll (Datei &gt; Öffnen); seine Einheiten werden dann zu %1 hinzugefügt.</translation>
    </message>
    <message>
        <source>Add the units of this project to %1:</source>
        <translation>Die Einheiten dieses Projekts zu %1 hinzufügen:</translation>
    </message>
    <message>
        <source>%1 cannot be merged into %2: every unit must keep its station and every symbolic name must be one project&apos;s only.</source>
        <translation>%1 kann nicht mit %2 zusammengeführt werden: Jede Einheit muss ihre Station behalten, und jeder symbolische Name darf nur in einem der Projekte vorkommen.</translation>
    </message>
    <message>
        <source>%1 is merged into %2. Each name both used stays only in the units that define it; elsewhere its variable is written as its address.</source>
        <translation>%1 ist mit %2 zusammengeführt. Jeder Name, den beide verwendeten, bleibt nur in den Einheiten, die ihn definieren; anderswo wird seine Variable mit ihrer Adresse geschrieben.</translation>
    </message>
    <message>
        <source>%1 is merged into %2.</source>
        <translation>%1 ist mit %2 zusammengeführt.</translation>
    </message>
</context>
<context>
    <name>QObject</name>
    <message>
        <source>Option on</source>
        <translation>Option ein</translation>
    </message>
    <message>
        <source>Option off</source>
        <translation>Option aus</translation>
    </message>
    <message>
        <source>Added since validation on %1</source>
        <translation>Hinzugefügt seit der Validierung am %1</translation>
    </message>
    <message>
        <source>Changed since validation on %1</source>
        <translation>Geändert seit der Validierung am %1</translation>
    </message>
</context>
<context>
    <name>QPlatformTheme</name>
    <message>
        <source>OK</source>
        <translation>OK</translation>
    </message>
    <message>
        <source>Save</source>
        <translation>Speichern</translation>
    </message>
    <message>
        <source>Save All</source>
        <translation>Alle speichern</translation>
    </message>
    <message>
        <source>Open</source>
        <translation>Öffnen</translation>
    </message>
    <message>
        <source>&amp;Yes</source>
        <translation>&amp;Ja</translation>
    </message>
    <message>
        <source>Yes to &amp;All</source>
        <translation>Ja, &amp;alle</translation>
    </message>
    <message>
        <source>&amp;No</source>
        <translation>&amp;Nein</translation>
    </message>
    <message>
        <source>N&amp;o to All</source>
        <translation>N&amp;ein, keine</translation>
    </message>
    <message>
        <source>Abort</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <source>Retry</source>
        <translation>Wiederholen</translation>
    </message>
    <message>
        <source>Ignore</source>
        <translation>Ignorieren</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>Schließen</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <source>Discard</source>
        <translation>Verwerfen</translation>
    </message>
    <message>
        <source>Help</source>
        <translation>Hilfe</translation>
    </message>
    <message>
        <source>Apply</source>
        <translation>Anwenden</translation>
    </message>
    <message>
        <source>Reset</source>
        <translation>Zurücksetzen</translation>
    </message>
    <message>
        <source>Restore Defaults</source>
        <translation>Voreinstellungen</translation>
    </message>
</context>
<context>
    <name>UnitCaption</name>
    <message>
        <source>Pluto %1 — %2</source>
        <translation>Pluto %1 — %2</translation>
    </message>
    <message>
        <source>Pluto %1</source>
        <translation>Pluto %1</translation>
    </message>
</context>
<context>
    <name>rs::ladder::Layout</name>
    <message>
        <source>step %1</source>
        <translation>Schritt %1</translation>
    </message>
</context>
<context>
    <name>rs::pl110::Area</name>
    <message>
        <source>Digital inputs: I1-I8 on the terminals, the rest from expansion modules</source>
        <translation>Digitaleingänge: I1–I8 an den Klemmen, die übrigen von Erweiterungsmodulen</translation>
    </message>
    <message>
        <source>Digital outputs: Q1-Q8 are the relays, the rest go to expansion modules</source>
        <translation>Digitalausgänge: Q1–Q8 sind die Relais, die übrigen gehen an Erweiterungsmodule</translation>
    </message>
    <message>
        <source>Markers</source>
        <translation>Merker</translation>
    </message>
    <message>
        <source>Bistable relays: each energisation of the coil changes the contact</source>
        <translation>Bistabile Relais: jede Ansteuerung der Spule schaltet den Kontakt um</translation>
    </message>
    <message>
        <source>Timers: the contact and the value in units of the time base</source>
        <translation>Zeitglieder: der Kontakt und der Wert in Einheiten der Zeitbasis</translation>
    </message>
    <message>
        <source>Counters: the contact and the value</source>
        <translation>Zähler: der Kontakt und der Wert</translation>
    </message>
    <message>
        <source>Variables, kept by the battery</source>
        <translation>Variablen, von der Batterie gehalten</translation>
    </message>
    <message>
        <source>Special markers: status, clocks, scan times and settings</source>
        <translation>Sondermerker: Status, Takte, Zykluszeiten und Einstellungen</translation>
    </message>
    <message>
        <source>Analogue inputs, scaled by RANGE</source>
        <translation>Analogeingänge, skaliert durch RANGE</translation>
    </message>
    <message>
        <source>Analogue output, 0-10 V</source>
        <translation>Analogausgang, 0–10 V</translation>
    </message>
    <message>
        <source>Timer presets</source>
        <translation>Vorgabewerte der Zeitglieder</translation>
    </message>
    <message>
        <source>Counter presets</source>
        <translation>Vorgabewerte der Zähler</translation>
    </message>
    <message>
        <source>EEPROM words, kept without power</source>
        <translation>EEPROM-Wörter, ohne Versorgung gehalten</translation>
    </message>
</context>
<context>
    <name>rs::ui::AdvancedSettingsDialog</name>
    <message>
        <source>&amp;Set the CAN bus cycle time:</source>
        <translation>CAN-Bus-Zykluszeit &amp;setzen:</translation>
    </message>
    <message>
        <source>Advanced Settings of Pluto %1</source>
        <translation>Erweiterte Einstellungen von Pluto %1</translation>
    </message>
    <message>
        <source>These settings have influence on the system response time. Do not change these values without a good knowledge of the function of the system. The hardware manual describes them.</source>
        <translation>Diese Einstellungen beeinflussen die Reaktionszeit des Systems. Ändern Sie diese Werte nicht ohne gute Kenntnis der Funktion des Systems. Das Hardware-Handbuch beschreibt sie.</translation>
    </message>
    <message>
        <source> ms</source>
        <translation> ms</translation>
    </message>
    <message>
        <source>Unset, the unit keeps its default. The simulator sends a unit&apos;s variables to the other units after every scan by default, and with a cycle time set, once per cycle time.</source>
        <translation>Nicht gesetzt, behält die Einheit ihre Vorgabe. Der Simulator sendet die Variablen einer Einheit standardmäßig nach jedem Zyklus an die anderen Einheiten, mit gesetzter Zykluszeit einmal je Zykluszeit.</translation>
    </message>
</context>
<context>
    <name>rs::ui::AsiOptionsPage</name>
    <message>
        <source>Bus Master</source>
        <translation>Bus-Master</translation>
    </message>
    <message>
        <source>Monitor only</source>
        <translation>Nur Monitor</translation>
    </message>
    <message>
        <source>Monitor / Slave</source>
        <translation>Monitor / Slave</translation>
    </message>
    <message>
        <source>Monitor / Slave with 3 extra virtual slaves</source>
        <translation>Monitor / Slave mit 3 zusätzlichen virtuellen Slaves</translation>
    </message>
    <message>
        <source>AS-i bus not used</source>
        <translation>AS-i-Bus nicht benutzt</translation>
    </message>
    <message>
        <source>Undefined</source>
        <translation>Undefiniert</translation>
    </message>
    <message>
        <source>Safe Input</source>
        <translation>Sicherer Eingang</translation>
    </message>
    <message>
        <source>Nonsafe Std</source>
        <translation>Nicht sicher, Standard</translation>
    </message>
    <message>
        <source>Nonsafe B</source>
        <translation>Nicht sicher, B</translation>
    </message>
    <message>
        <source>Nonsafe A</source>
        <translation>Nicht sicher, A</translation>
    </message>
    <message>
        <source>Combined Transaction B</source>
        <translation>Combined Transaction B</translation>
    </message>
    <message>
        <source>Combined Transaction A</source>
        <translation>Combined Transaction A</translation>
    </message>
    <message>
        <source>Analog</source>
        <translation>Analog</translation>
    </message>
    <message>
        <source>Safe Output</source>
        <translation>Sicherer Ausgang</translation>
    </message>
    <message>
        <source>Pluto as Safe Input</source>
        <translation>Pluto als sicherer Eingang</translation>
    </message>
    <message>
        <source>No channel monitoring</source>
        <translation>Keine Kanalüberwachung</translation>
    </message>
    <message>
        <source>Channel monitoring</source>
        <translation>Kanalüberwachung</translation>
    </message>
    <message>
        <source>Chan mon &amp; debounce filter</source>
        <translation>Kanalüberw. &amp; Entprellfilter</translation>
    </message>
    <message>
        <source>Simultaneously</source>
        <translation>Gleichzeitig</translation>
    </message>
    <message>
        <source>Simultaneously &amp; debounce</source>
        <translation>Gleichzeitig &amp; Entprellung</translation>
    </message>
    <message>
        <source>AS-i general options</source>
        <translation>Allgemeine AS-i-Optionen</translation>
    </message>
    <message>
        <source>AS-i bus working mode</source>
        <translation>Betriebsart des AS-i-Busses</translation>
    </message>
    <message>
        <source>Set AS-i bus working mode</source>
        <translation>AS-i-Betriebsart setzen</translation>
    </message>
    <message>
        <source>ASi &amp;slave address:</source>
        <translation>ASi-&amp;Slave-Adresse:</translation>
    </message>
    <message>
        <source>Set AS-i slave address</source>
        <translation>AS-i-Slave-Adresse setzen</translation>
    </message>
    <message>
        <source>Optimize for</source>
        <translation>Optimieren für</translation>
    </message>
    <message>
        <source>Short stop time (worst case, when error)</source>
        <translation>Kurze Abschaltzeit (schlimmster Fall, bei Fehler)</translation>
    </message>
    <message>
        <source>Disturbance immunity</source>
        <translation>Störfestigkeit</translation>
    </message>
    <message>
        <source>Disturbance immunity is not recommended when fewer than 20 slaves are used: the worst case stop time grows by 10 ms.</source>
        <translation>Störfestigkeit wird bei weniger als 20 Slaves nicht empfohlen: Die Abschaltzeit im schlimmsten Fall wächst um 10 ms.</translation>
    </message>
    <message>
        <source>Set AS-i optimisation</source>
        <translation>AS-i-Optimierung setzen</translation>
    </message>
    <message>
        <source>AS-i slaves</source>
        <translation>AS-i-Slaves</translation>
    </message>
    <message>
        <source>Slave No</source>
        <translation>Slave-Nr.</translation>
    </message>
    <message>
        <source>Type of Slave</source>
        <translation>Art des Slaves</translation>
    </message>
    <message>
        <source>Model</source>
        <translation>Modell</translation>
    </message>
    <message>
        <source>Param</source>
        <translation>Param</translation>
    </message>
    <message>
        <source>Profile/ID1</source>
        <translation>Profil/ID1</translation>
    </message>
    <message>
        <source>Channel Monitoring</source>
        <translation>Kanalüberwachung</translation>
    </message>
    <message>
        <source>Time limit</source>
        <translation>Zeitgrenze</translation>
    </message>
    <message>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <source>Reading the slaves from the bus, teaching safety codes, the code tables and changing a slave&apos;s address need a Pluto on a real AS-i bus, and are not in Rungsmith. A slave the code uses but this table does not define is a warning when compiling; the simulator gives each safe input slave two channels that follow its channel monitoring.</source>
        <translation>Das Einlesen der Slaves vom Bus, das Einlernen der Sicherheitscodes, die Codetabellen und das Ändern der Adresse eines Slaves brauchen einen Pluto an einem echten AS-i-Bus und sind nicht in Rungsmith. Ein Slave, den der Code benutzt, den diese Tabelle aber nicht definiert, ist beim Kompilieren eine Warnung; der Simulator gibt jedem sicheren Eingangsslave zwei Kanäle, die seiner Kanalüberwachung folgen.</translation>
    </message>
    <message>
        <source>%1 — AS-i Options</source>
        <translation>%1 — AS-i-Optionen</translation>
    </message>
    <message>
        <source>How the unit works on its AS-i bus, and what each slave address holds (manual Part 1, 7.1).</source>
        <translation>Wie die Einheit an ihrem AS-i-Bus arbeitet und was jede Slave-Adresse enthält (Handbuch Teil 1, 7.1).</translation>
    </message>
    <message>
        <source>%1 of %2 slaves are Safe Output or Pluto as Safe Input, the most a Pluto takes.</source>
        <translation>%1 von %2 Slaves sind sichere Ausgänge oder Pluto als sicherer Eingang, die Höchstzahl, die ein Pluto nimmt.</translation>
    </message>
    <message>
        <source>%1 takes the whole address: a B slave only goes beside an A/B slave.</source>
        <translation>%1 belegt die ganze Adresse: Ein B-Slave steht nur neben einem A/B-Slave.</translation>
    </message>
    <message>
        <source>%1 monitors its channels itself.</source>
        <translation>%1 überwacht seine Kanäle selbst.</translation>
    </message>
    <message>
        <source>Set AS-i slave %1</source>
        <translation>AS-i-Slave %1 setzen</translation>
    </message>
</context>
<context>
    <name>rs::ui::AsiProfileDialog</name>
    <message>
        <source>%1 (Outputs)</source>
        <translation>%1 (Ausgänge)</translation>
    </message>
    <message>
        <source>%1 (Safe slave)</source>
        <translation>%1 (Sicherer Slave)</translation>
    </message>
    <message>
        <source>%1 (Standard slave)</source>
        <translation>%1 (Standard-Slave)</translation>
    </message>
    <message>
        <source>AS-i Profile</source>
        <translation>AS-i-Profil</translation>
    </message>
    <message>
        <source>&amp;I/O configuration:</source>
        <translation>&amp;E/A-Konfiguration:</translation>
    </message>
    <message>
        <source>I&amp;D code:</source>
        <translation>I&amp;D-Code:</translation>
    </message>
    <message>
        <source>ID&amp;2:</source>
        <translation>ID&amp;2:</translation>
    </message>
    <message>
        <source>ID&amp;1:</source>
        <translation>ID&amp;1:</translation>
    </message>
    <message>
        <source>Examples from the manual: S-0.B… a safe slave; S-7.B… a safe slave with outputs; S-7.0… a standard non-safe slave with 4 inputs and 4 outputs. The slave&apos;s own manual gives its profile.</source>
        <translation>Beispiele aus dem Handbuch: S-0.B… ein sicherer Slave; S-7.B… ein sicherer Slave mit Ausgängen; S-7.0… ein nicht sicherer Standard-Slave mit 4 Eingängen und 4 Ausgängen. Das Handbuch des Slaves nennt sein Profil.</translation>
    </message>
    <message>
        <source>Profile for %1 = %2</source>
        <translation>Profil für %1 = %2</translation>
    </message>
</context>
<context>
    <name>rs::ui::BlockChooserDialog</name>
    <message>
        <source>The project&apos;s libraries hold no blocks. Add a library on the project page (Function libraries).</source>
        <translation>Die Bibliotheken des Projekts enthalten keine Bausteine. Fügen Sie auf der Projektseite eine Bibliothek hinzu (Funktionsbibliotheken).</translation>
    </message>
    <message>
        <source>&amp;Find:</source>
        <translation>&amp;Suchen:</translation>
    </message>
    <message>
        <source>Type to filter by name or description</source>
        <translation>Tippen, um nach Name oder Beschreibung zu filtern</translation>
    </message>
    <message>
        <source>Insert Function Block</source>
        <translation>Funktionsbaustein einfügen</translation>
    </message>
    <message>
        <source>&amp;Documentation...</source>
        <translation>&amp;Dokumentation...</translation>
    </message>
    <message>
        <source>The block&apos;s documentation: states, transitions and a timing diagram</source>
        <translation>Die Dokumentation des Bausteins: Zustände, Übergänge und ein Zeitdiagramm</translation>
    </message>
</context>
<context>
    <name>rs::ui::BlockDocumentationDialog</name>
    <message>
        <source>%1 — Block Documentation</source>
        <translation>%1 — Bausteindokumentation</translation>
    </message>
</context>
<context>
    <name>rs::ui::BlockPinsDialog</name>
    <message>
        <source>%1 Pins</source>
        <translation>Anschlüsse von %1</translation>
    </message>
    <message>
        <source>&amp;Documentation...</source>
        <translation>&amp;Dokumentation...</translation>
    </message>
</context>
<context>
    <name>rs::ui::BusStatusView</name>
    <message>
        <source>Pluto %1: E0=No Error</source>
        <translation>Pluto %1: E0=Kein Fehler</translation>
    </message>
    <message>
        <source>Pluto %1: Er%2</source>
        <translation>Pluto %1: Er%2</translation>
    </message>
    <message>
        <source>Station</source>
        <translation>Station</translation>
    </message>
    <message>
        <source>Pluto</source>
        <translation>Pluto</translation>
    </message>
    <message>
        <source>State</source>
        <translation>Zustand</translation>
    </message>
    <message>
        <source>Code</source>
        <translation>Code</translation>
    </message>
    <message>
        <source>Missing</source>
        <translation>Fehlt</translation>
    </message>
    <message>
        <source>Ok, running</source>
        <translation>OK, läuft</translation>
    </message>
    <message>
        <source>Ok, stopped</source>
        <translation>OK, gestoppt</translation>
    </message>
    <message>
        <source>E0=No Error</source>
        <translation>E0=Kein Fehler</translation>
    </message>
    <message>
        <source>Er%1</source>
        <translation>Er%1</translation>
    </message>
    <message>
        <source>Signature</source>
        <translation>Signatur</translation>
    </message>
    <message>
        <source>The program signature of the unit&apos;s compiled code, as rungsmith-cli signature prints it; it changes exactly when what the unit does changes</source>
        <translation>Die Programmsignatur des kompilierten Codes der Einheit, wie rungsmith-cli signature sie ausgibt; sie ändert sich genau dann, wenn sich ändert, was die Einheit tut</translation>
    </message>
    <message>
        <source>G%1</source>
        <translation>G%1</translation>
    </message>
    <message>
        <source>Gateway %1 (%2)</source>
        <translation>Gateway %1 (%2)</translation>
    </message>
</context>
<context>
    <name>rs::ui::CompareDialog</name>
    <message>
        <source>unit added</source>
        <translation>Einheit hinzugefügt</translation>
    </message>
    <message>
        <source>unit removed</source>
        <translation>Einheit entfernt</translation>
    </message>
    <message>
        <source>type changed</source>
        <translation>Typ geändert</translation>
    </message>
    <message>
        <source>ID code changed</source>
        <translation>ID-Code geändert</translation>
    </message>
    <message>
        <source>I/O options changed</source>
        <translation>E/A-Optionen geändert</translation>
    </message>
    <message>
        <source>exported and remanent variables changed</source>
        <translation>exportierte und remanente Variablen geändert</translation>
    </message>
    <message>
        <source>names and descriptions changed</source>
        <translation>Namen und Beschreibungen geändert</translation>
    </message>
    <message>
        <source>comments changed</source>
        <translation>Kommentare geändert</translation>
    </message>
    <message>
        <source>Save Review as &amp;PDF...</source>
        <translation>Prüfbericht als &amp;PDF speichern …</translation>
    </message>
    <message>
        <source>Changes Since Validation</source>
        <translation>Änderungen seit der Validierung</translation>
    </message>
    <message>
        <source>Compare With</source>
        <translation>Vergleichen mit</translation>
    </message>
    <message>
        <source>%1 as it is now, against the version validated on %2 by %3</source>
        <translation>%1 im jetzigen Stand, verglichen mit der am %2 von %3 validierten Version</translation>
    </message>
    <message>
        <source>%1 as it is now (new), against %2 (old)</source>
        <translation>%1 im jetzigen Stand (neu), verglichen mit %2 (alt)</translation>
    </message>
    <message>
        <source>Enter or a double click opens a network in the ladder</source>
        <translation>Eingabetaste oder Doppelklick öffnet ein Netzwerk im Kontaktplan</translation>
    </message>
    <message>
        <source>Comparing...</source>
        <translation>Wird verglichen …</translation>
    </message>
    <message>
        <source>Pluto %1: %2</source>
        <translation>Pluto %1: %2</translation>
    </message>
    <message>
        <source>Pluto %1 %2 network %3: added</source>
        <translation>Pluto %1 %2 Netzwerk %3: hinzugefügt</translation>
    </message>
    <message>
        <source>Pluto %1 %2 network %3: removed</source>
        <translation>Pluto %1 %2 Netzwerk %3: entfernt</translation>
    </message>
    <message>
        <source>Pluto %1 %2 network %3: changed</source>
        <translation>Pluto %1 %2 Netzwerk %3: geändert</translation>
    </message>
    <message>
        <source>No network, unit or option differs.</source>
        <translation>Kein Netzwerk, keine Einheit und keine Option unterscheidet sich.</translation>
    </message>
    <message>
        <source>No change in behaviour; only the text changed.</source>
        <translation>Kein geändertes Verhalten; nur der Text hat sich geändert.</translation>
    </message>
    <message>
        <source>No change in behaviour.</source>
        <translation>Kein geändertes Verhalten.</translation>
    </message>
    <message>
        <source>Pluto %1</source>
        <translation>Pluto %1</translation>
    </message>
    <message>
        <source>Behaviour changed in %1 (project signature %2, was %3).</source>
        <translation>Verhalten geändert in %1 (Projektsignatur %2, war %3).</translation>
    </message>
    <message>
        <source>There is nothing to save yet.</source>
        <translation>Es gibt noch nichts zu speichern.</translation>
    </message>
    <message>
        <source>Save Review as PDF</source>
        <translation>Prüfbericht als PDF speichern</translation>
    </message>
    <message>
        <source>PDF files (*.pdf)</source>
        <translation>PDF-Dateien (*.pdf)</translation>
    </message>
</context>
<context>
    <name>rs::ui::CompileOutput</name>
    <message>
        <source>Compiling %1...</source>
        <translation>%1 wird kompiliert …</translation>
    </message>
    <message>
        <source>Compiling %1</source>
        <translation>%1 wird kompiliert</translation>
    </message>
    <message>
        <source>Wrote %1</source>
        <translation>%1 geschrieben</translation>
    </message>
    <message>
        <source>Build &gt; Compile (F7) checks the project and writes the compiled file.</source>
        <translation>Erstellen &gt; Kompilieren (F7) prüft das Projekt und schreibt die kompilierte Datei.</translation>
    </message>
    <message>
        <source>error: the compiled file was not written: %1</source>
        <translation>Fehler: die kompilierte Datei wurde nicht geschrieben: %1</translation>
    </message>
</context>
<context>
    <name>rs::ui::CompileOutputModel</name>
    <message>
        <source>Pluto %1, line %2:%3</source>
        <translation>Pluto %1, Zeile %2:%3</translation>
    </message>
    <message>
        <source>Pluto %1, settings</source>
        <translation>Pluto %1, Einstellungen</translation>
    </message>
    <message>
        <source>Pluto %1, %2</source>
        <translation>Pluto %1, %2</translation>
    </message>
    <message>
        <source>Project</source>
        <translation>Projekt</translation>
    </message>
    <message>
        <source>error: %1</source>
        <translation>Fehler: %1</translation>
    </message>
    <message>
        <source>warning: %1</source>
        <translation>Warnung: %1</translation>
    </message>
    <message>
        <source>Line %1 of the project file</source>
        <translation>Zeile %1 der Projektdatei</translation>
    </message>
    <message>
        <source>Place</source>
        <translation>Ort</translation>
    </message>
    <message>
        <source>Message</source>
        <translation>Meldung</translation>
    </message>
</context>
<context>
    <name>rs::ui::CompileRun</name>
    <message>
        <source>Compiling</source>
        <translation>Kompiliert</translation>
    </message>
    <message>
        <source>Compiling %1...</source>
        <translation>%1 wird kompiliert …</translation>
    </message>
    <message>
        <source>Compile</source>
        <translation>Kompilieren</translation>
    </message>
    <message>
        <source>Compiled without errors. Save the project to write the compiled file.</source>
        <translation>Fehlerfrei kompiliert. Speichern Sie das Projekt, um die kompilierte Datei zu schreiben.</translation>
    </message>
    <message>
        <source>Checked without errors. The compiled file is not written, as the project has unsaved changes.</source>
        <translation>Ohne Fehler geprüft. Die kompilierte Datei wird nicht geschrieben, da das Projekt ungespeicherte Änderungen hat.</translation>
    </message>
</context>
<context>
    <name>rs::ui::ConfigOptionDialog</name>
    <message>
        <source>&amp;Enabled</source>
        <translation>&amp;Aktiviert</translation>
    </message>
    <message>
        <source>Config Option</source>
        <translation>Konfigurationsoption</translation>
    </message>
    <message>
        <source>a memory, such as M%1.5</source>
        <translation>ein Merker, z. B. M%1.5</translation>
    </message>
    <message>
        <source>&amp;Description:</source>
        <translation>&amp;Beschreibung:</translation>
    </message>
    <message>
        <source>&amp;Memory:</source>
        <translation>&amp;Merker:</translation>
    </message>
    <message>
        <source>Describe the option: the description is what the check box says.</source>
        <translation>Beschreiben Sie die Option: Die Beschreibung ist der Text des Kontrollkästchens.</translation>
    </message>
    <message>
        <source>Only memories can be options (manual 11.6).</source>
        <translation>Nur Merker können Optionen sein (Handbuch 11.6).</translation>
    </message>
    <message>
        <source>A config option is a check box on its network: it sets the memory when checked and resets it when not, so that one program serves machines with and without an option (manual 11.6).</source>
        <translation>Eine Konfigurationsoption ist ein Kontrollkästchen auf ihrem Netzwerk: Sie setzt den Merker, wenn es angekreuzt ist, und setzt ihn sonst zurück, sodass ein Programm Maschinen mit und ohne eine Option bedient (Handbuch 11.6).</translation>
    </message>
</context>
<context>
    <name>rs::ui::CsvExportDialog</name>
    <message>
        <source>Export Variable Names from Pluto %1</source>
        <translation>Variablennamen aus Pluto %1 exportieren</translation>
    </message>
    <message>
        <source>none</source>
        <translation>keine</translation>
    </message>
    <message>
        <source>Semicolon (;)</source>
        <translation>Semikolon (;)</translation>
    </message>
    <message>
        <source>Comma (,)</source>
        <translation>Komma (,)</translation>
    </message>
    <message>
        <source>&amp;Browse...</source>
        <translation>&amp;Durchsuchen …</translation>
    </message>
    <message>
        <source>Variables:</source>
        <translation>Variablen:</translation>
    </message>
    <message>
        <source>&amp;Global and local</source>
        <translation>&amp;Globale und lokale</translation>
    </message>
    <message>
        <source>G&amp;lobal only</source>
        <translation>Nur g&amp;lobale</translation>
    </message>
    <message>
        <source>L&amp;ocal only</source>
        <translation>Nur l&amp;okale</translation>
    </message>
    <message>
        <source>&amp;Prefix for names:</source>
        <translation>&amp;Präfix für Namen:</translation>
    </message>
    <message>
        <source>Sort by:</source>
        <translation>Sortieren nach:</translation>
    </message>
    <message>
        <source>&amp;Variable</source>
        <translation>&amp;Variable</translation>
    </message>
    <message>
        <source>Symbolic &amp;name</source>
        <translation>Symbolischer &amp;Name</translation>
    </message>
    <message>
        <source>&amp;Separator:</source>
        <translation>&amp;Trennzeichen:</translation>
    </message>
    <message>
        <source>&amp;File:</source>
        <translation>&amp;Datei:</translation>
    </message>
    <message>
        <source>&amp;Export</source>
        <translation>&amp;Exportieren</translation>
    </message>
    <message>
        <source>CSV files (*.csv);;All files (*)</source>
        <translation>CSV-Dateien (*.csv);;Alle Dateien (*)</translation>
    </message>
</context>
<context>
    <name>rs::ui::CsvImportDialog</name>
    <message>
        <source>semicolons</source>
        <translation>Semikolons</translation>
    </message>
    <message>
        <source>tabs</source>
        <translation>Tabulatoren</translation>
    </message>
    <message>
        <source>commas</source>
        <translation>Kommas</translation>
    </message>
    <message>
        <source>Import Variable Names to Pluto %1</source>
        <translation>Variablennamen in Pluto %1 importieren</translation>
    </message>
    <message>
        <source>none</source>
        <translation>keine</translation>
    </message>
    <message>
        <source>&amp;Browse...</source>
        <translation>&amp;Durchsuchen …</translation>
    </message>
    <message>
        <source>&amp;File:</source>
        <translation>&amp;Datei:</translation>
    </message>
    <message>
        <source>&amp;Remove prefix from names:</source>
        <translation>Präfix von Namen &amp;entfernen:</translation>
    </message>
    <message>
        <source>Line</source>
        <translation>Zeile</translation>
    </message>
    <message>
        <source>Variable</source>
        <translation>Variable</translation>
    </message>
    <message>
        <source>Symbolic Name</source>
        <translation>Symbolischer Name</translation>
    </message>
    <message>
        <source>Description</source>
        <translation>Beschreibung</translation>
    </message>
    <message>
        <source>Left out because</source>
        <translation>Ausgelassen, weil</translation>
    </message>
    <message>
        <source>&amp;Import</source>
        <translation>&amp;Importieren</translation>
    </message>
    <message>
        <source>CSV files (*.csv *.txt);;All files (*)</source>
        <translation>CSV-Dateien (*.csv *.txt);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Choose a CSV file with the columns Variable, Symbolic Name and Description. Nothing changes before you press Import.</source>
        <translation>Wählen Sie eine CSV-Datei mit den Spalten Variable, Symbolic Name und Description. Nichts ändert sich, bevor Sie Importieren drücken.</translation>
    </message>
    <message>
        <source>Fields separated by %1. %2 to change, %3 unchanged, %4 left out.</source>
        <translation>Felder durch %1 getrennt. %2 zu ändern, %3 unverändert, %4 ausgelassen.</translation>
    </message>
    <message numerus="yes">
        <source>%n variable(s)</source>
        <translation>
            <numerusform>%n Variable</numerusform>
            <numerusform>%n Variablen</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n row(s)</source>
        <translation>
            <numerusform>%n Zeile</numerusform>
            <numerusform>%n Zeilen</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>rs::ui::ElementDialog</name>
    <message>
        <source>Value:</source>
        <translation>Wert:</translation>
    </message>
    <message>
        <source>&amp;Negated (passes power when false)</source>
        <translation>&amp;Negiert (leitet, wenn falsch)</translation>
    </message>
    <message>
        <source>Output Properties</source>
        <translation>Ausgangseigenschaften</translation>
    </message>
    <message>
        <source>Element Properties</source>
        <translation>Elementeigenschaften</translation>
    </message>
    <message>
        <source>such as &gt;= 5, = R0.2, += 2, ++</source>
        <translation>z. B. &gt;= 5, = R0.2, += 2, ++</translation>
    </message>
    <message>
        <source>&amp;Type:</source>
        <translation>&amp;Typ:</translation>
    </message>
    <message>
        <source>New &amp;Variable...</source>
        <translation>Neue &amp;Variable …</translation>
    </message>
    <message>
        <source>&amp;Comment:</source>
        <translation>&amp;Kommentar:</translation>
    </message>
    <message>
        <source>New Variable</source>
        <translation>Neue Variable</translation>
    </message>
    <message>
        <source>&amp;Address:</source>
        <translation>&amp;Adresse:</translation>
    </message>
    <message>
        <source>Symbolic &amp;name:</source>
        <translation>Symbolischer &amp;Name:</translation>
    </message>
    <message>
        <source>Write an address such as I%1.0, Q%1.2 or M%1.5.</source>
        <translation>Geben Sie eine Adresse wie I%1.0, Q%1.2 oder M%1.5 ein.</translation>
    </message>
    <message>
        <source>Give the variable a name.</source>
        <translation>Geben Sie der Variablen einen Namen.</translation>
    </message>
    <message>
        <source>Name %1 %2</source>
        <translation>%1 %2 nennen</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
</context>
<context>
    <name>rs::ui::ExternalCommDialog</name>
    <message>
        <source>External Communication of Pluto %1</source>
        <translation>Externe Kommunikation von Pluto %1</translation>
    </message>
    <message>
        <source>Which gateway data this unit receives: each External Comm Block takes one Data to Pluto packet of one gateway. A block that receives nothing for its timeout is cleared, and the Ext blocks of the code read it as not valid. The timeout must be greater than the gateway&apos;s cycle time (Gateway manual 4.5.1).</source>
        <translation>Welche Gateway-Daten diese Einheit empfängt: Jeder External Comm Block nimmt ein Data-to-Pluto-Paket eines Gateways. Ein Block, der während seiner Zeitüberwachung nichts empfängt, wird gelöscht, und die Ext-Bausteine des Codes lesen ihn als ungültig. Die Zeitüberwachung muss größer als die Zykluszeit des Gateways sein (Gateway-Handbuch 4.5.1).</translation>
    </message>
    <message>
        <source>Block</source>
        <translation>Block</translation>
    </message>
    <message>
        <source>Gateway</source>
        <translation>Gateway</translation>
    </message>
    <message>
        <source>Packet</source>
        <translation>Paket</translation>
    </message>
    <message>
        <source>Timeout</source>
        <translation>Zeitüberwachung</translation>
    </message>
    <message>
        <source>Block &amp;%1</source>
        <translation>Block &amp;%1</translation>
    </message>
    <message>
        <source>Gateway %1 (%2)</source>
        <translation>Gateway %1 (%2)</translation>
    </message>
    <message>
        <source> ms</source>
        <translation> ms</translation>
    </message>
    <message>
        <source>No timeout</source>
        <translation>Keine Zeitüberwachung</translation>
    </message>
    <message>
        <source>Gateway %1 (not in the project)</source>
        <translation>Gateway %1 (nicht im Projekt)</translation>
    </message>
    <message>
        <source>The project has no gateway: add one with Project &gt; New Gateway first.</source>
        <translation>Das Projekt hat kein Gateway: Fügen Sie zuerst eines mit Projekt &gt; Neues Gateway hinzu.</translation>
    </message>
</context>
<context>
    <name>rs::ui::ForcesView</name>
    <message>
        <source>&amp;Release</source>
        <translation>Auf&amp;heben</translation>
    </message>
    <message>
        <source>Release &amp;All</source>
        <translation>&amp;Alle aufheben</translation>
    </message>
    <message>
        <source>Variable</source>
        <translation>Variable</translation>
    </message>
    <message>
        <source>Symbolic Name</source>
        <translation>Symbolischer Name</translation>
    </message>
    <message>
        <source>Forced To</source>
        <translation>Geforct auf</translation>
    </message>
    <message>
        <source>Release the chosen force: the program writes the variable again</source>
        <translation>Das gewählte Forcen aufheben: Das Programm schreibt die Variable wieder</translation>
    </message>
</context>
<context>
    <name>rs::ui::GatewayCommands</name>
    <message>
        <source>New &amp;Gateway...</source>
        <translation>Neues &amp;Gateway...</translation>
    </message>
    <message>
        <source>Add a Pluto Gateway to the project&apos;s bus</source>
        <translation>Ein Pluto-Gateway zum Bus des Projekts hinzufügen</translation>
    </message>
    <message>
        <source>Remove Gate&amp;way...</source>
        <translation>Gate&amp;way entfernen...</translation>
    </message>
    <message>
        <source>New Gateway</source>
        <translation>Neues Gateway</translation>
    </message>
    <message>
        <source>Every gateway node address 0-15 is in use.</source>
        <translation>Jede Gateway-Knotenadresse 0-15 ist belegt.</translation>
    </message>
    <message>
        <source>A Pluto Gateway is a node of the Pluto bus that passes the Plutos&apos; data to a fieldbus. The Ethernet gateways (GATE-E1, GATE-E2) serve Modbus TCP while simulating.</source>
        <translation>Ein Pluto-Gateway ist ein Knoten des Pluto-Busses, der die Daten der Plutos an einen Feldbus weitergibt. Die Ethernet-Gateways (GATE-E1, GATE-E2) bedienen während der Simulation Modbus TCP.</translation>
    </message>
    <message>
        <source>&amp;Type:</source>
        <translation>&amp;Typ:</translation>
    </message>
    <message>
        <source>&amp;Node address:</source>
        <translation>&amp;Knotenadresse:</translation>
    </message>
    <message>
        <source>New Gateway %1</source>
        <translation>Neues Gateway %1</translation>
    </message>
    <message>
        <source>Remove Gateway</source>
        <translation>Gateway entfernen</translation>
    </message>
    <message>
        <source>Remove gateway %1 with its settings from the project? Units that receive its data keep their setting. Edit &gt; Undo brings it back.</source>
        <translation>Gateway %1 mit seinen Einstellungen aus dem Projekt entfernen? Einheiten, die seine Daten empfangen, behalten ihre Einstellung. Bearbeiten &gt; Rückgängig holt es zurück.</translation>
    </message>
    <message>
        <source>Remove Gateway %1</source>
        <translation>Gateway %1 entfernen</translation>
    </message>
</context>
<context>
    <name>rs::ui::GatewayPage</name>
    <message>
        <source>%1 (user block)</source>
        <translation>%1 (Anwenderbaustein)</translation>
    </message>
    <message>
        <source>%1 Global data</source>
        <translation>%1 Globale Daten</translation>
    </message>
    <message>
        <source>&amp;Remove Gateway...</source>
        <translation>Gateway &amp;entfernen...</translation>
    </message>
    <message>
        <source>Gateway</source>
        <translation>Gateway</translation>
    </message>
    <message>
        <source>&amp;Type:</source>
        <translation>&amp;Typ:</translation>
    </message>
    <message>
        <source>Node address:</source>
        <translation>Knotenadresse:</translation>
    </message>
    <message>
        <source>Set Gateway %1 Type</source>
        <translation>Typ von Gateway %1 setzen</translation>
    </message>
    <message>
        <source>Data to Pluto</source>
        <translation>Daten an Pluto</translation>
    </message>
    <message>
        <source>Packet &amp;%1</source>
        <translation>Paket &amp;%1</translation>
    </message>
    <message>
        <source>Enable Data to Pluto Packet %1</source>
        <translation>Daten-an-Pluto-Paket %1 freigeben</translation>
    </message>
    <message>
        <source>Disable Data to Pluto Packet %1</source>
        <translation>Daten-an-Pluto-Paket %1 sperren</translation>
    </message>
    <message>
        <source>Enabled:</source>
        <translation>Freigegeben:</translation>
    </message>
    <message>
        <source> ms</source>
        <translation> ms</translation>
    </message>
    <message>
        <source>&amp;Cycle time:</source>
        <translation>&amp;Zykluszeit:</translation>
    </message>
    <message>
        <source>Set Gateway %1 Cycle Time</source>
        <translation>Zykluszeit von Gateway %1 setzen</translation>
    </message>
    <message>
        <source>No timeout</source>
        <translation>Keine Zeitüberwachung</translation>
    </message>
    <message>
        <source>T&amp;imeout:</source>
        <translation>Zeitü&amp;berwachung:</translation>
    </message>
    <message>
        <source>Set Gateway %1 Timeout</source>
        <translation>Zeitüberwachung von Gateway %1 setzen</translation>
    </message>
    <message>
        <source>Expected nodes</source>
        <translation>Erwartete Knoten</translation>
    </message>
    <message>
        <source>Set Gateway %1 Expected Nodes</source>
        <translation>Erwartete Knoten von Gateway %1 setzen</translation>
    </message>
    <message>
        <source>Additional data areas</source>
        <translation>Zusatzdatenbereiche</translation>
    </message>
    <message>
        <source>Area</source>
        <translation>Bereich</translation>
    </message>
    <message>
        <source>Pluto</source>
        <translation>Pluto</translation>
    </message>
    <message>
        <source>IO-type</source>
        <translation>IO-Typ</translation>
    </message>
    <message>
        <source>Set Additional Data Area %1</source>
        <translation>Zusatzdatenbereich %1 setzen</translation>
    </message>
    <message>
        <source>Gateway %1 (%2)</source>
        <translation>Gateway %1 (%2)</translation>
    </message>
    <message>
        <source>A node of the Pluto bus that passes the Plutos&apos; data to a fieldbus and takes data to them back (Gateway manual). Project %1.</source>
        <translation>Ein Knoten des Pluto-Busses, der die Daten der Plutos an einen Feldbus weitergibt und Daten an sie zurücknimmt (Gateway-Handbuch). Projekt %1.</translation>
    </message>
    <message>
        <source>0 or %1-%2 ms on %3</source>
        <translation>0 oder %1-%2 ms beim %3</translation>
    </message>
    <message>
        <source>0-%1 ms</source>
        <translation>0-%1 ms</translation>
    </message>
    <message>
        <source>Not used</source>
        <translation>Nicht benutzt</translation>
    </message>
    <message>
        <source>Pluto %1</source>
        <translation>Pluto %1</translation>
    </message>
</context>
<context>
    <name>rs::ui::GatewayView</name>
    <message>
        <source>Data</source>
        <translation>Daten</translation>
    </message>
    <message>
        <source>Hex</source>
        <translation>Hex</translation>
    </message>
    <message>
        <source>Bits 31..0</source>
        <translation>Bits 31..0</translation>
    </message>
    <message>
        <source>Modbus TCP is not served.</source>
        <translation>Modbus TCP wird nicht bedient.</translation>
    </message>
    <message>
        <source>Serving Modbus TCP on %1; no client is connected.</source>
        <translation>Modbus TCP wird auf %1 bedient; kein Client ist verbunden.</translation>
    </message>
    <message>
        <source>Serving Modbus TCP on %1; clients: %2.</source>
        <translation>Modbus TCP wird auf %1 bedient; Clients: %2.</translation>
    </message>
    <message>
        <source>Gateway %1 (%2)</source>
        <translation>Gateway %1 (%2)</translation>
    </message>
    <message>
        <source>Node status</source>
        <translation>Knotenstatus</translation>
    </message>
    <message>
        <source>Additional data %1 (Pluto %2, IO-type %3)</source>
        <translation>Zusatzdaten %1 (Pluto %2, IO-Typ %3)</translation>
    </message>
    <message>
        <source>Data to Pluto %1</source>
        <translation>Daten an Pluto %1</translation>
    </message>
    <message>
        <source>valid; register 0 = %1, register 1 = %2</source>
        <translation>gültig; Register 0 = %1, Register 1 = %2</translation>
    </message>
    <message>
        <source>not valid</source>
        <translation>ungültig</translation>
    </message>
</context>
<context>
    <name>rs::ui::IoOptionsPage</name>
    <message>
        <source>Failsafe inputs</source>
        <translation>Fehlersichere Eingänge</translation>
    </message>
    <message>
        <source>Failsafe inputs / non-failsafe outputs</source>
        <translation>Fehlersichere Eingänge / nicht fehlersichere Ausgänge</translation>
    </message>
    <message>
        <source>Analogue inputs</source>
        <translation>Analoge Eingänge</translation>
    </message>
    <message>
        <source>Safety outputs: test pulses</source>
        <translation>Sicherheitsausgänge: Testpulse</translation>
    </message>
    <message>
        <source>Undefined</source>
        <translation>Undefiniert</translation>
    </message>
    <message>
        <source>Input</source>
        <translation>Eingang</translation>
    </message>
    <message>
        <source>Output</source>
        <translation>Ausgang</translation>
    </message>
    <message>
        <source>Light button</source>
        <translation>Leuchttaster</translation>
    </message>
    <message>
        <source>Analogue 0-10 V</source>
        <translation>Analog 0-10 V</translation>
    </message>
    <message>
        <source>Analogue 4-20 mA</source>
        <translation>Analog 4-20 mA</translation>
    </message>
    <message>
        <source>Counter, up</source>
        <translation>Zähler, aufwärts</translation>
    </message>
    <message>
        <source>Counter, up/down</source>
        <translation>Zähler, auf/ab</translation>
    </message>
    <message>
        <source>Static</source>
        <translation>Statisch</translation>
    </message>
    <message>
        <source>A_Pulse</source>
        <translation>A_Pulse</translation>
    </message>
    <message>
        <source>B_Pulse</source>
        <translation>B_Pulse</translation>
    </message>
    <message>
        <source>C_Pulse</source>
        <translation>C_Pulse</translation>
    </message>
    <message>
        <source>Signal</source>
        <translation>Signal</translation>
    </message>
    <message>
        <source>Options</source>
        <translation>Optionen</translation>
    </message>
    <message>
        <source>Type of signal</source>
        <translation>Signalart</translation>
    </message>
    <message>
        <source>Signal shape</source>
        <translation>Signalform</translation>
    </message>
    <message>
        <source>No_Test_Pulse</source>
        <translation>No_Test_Pulse</translation>
    </message>
    <message>
        <source>Non_Inv</source>
        <translation>Non_Inv</translation>
    </message>
    <message>
        <source>No_Filt</source>
        <translation>No_Filt</translation>
    </message>
    <message>
        <source>X_Talk</source>
        <translation>X_Talk</translation>
    </message>
    <message>
        <source>The configuration must match the wiring. Q0..Q3 are not listed: they can be used in one way only.</source>
        <translation>Die Konfiguration muss zur Verdrahtung passen. Q0..Q3 fehlen in der Liste: Sie lassen sich nur auf eine Weise verwenden.</translation>
    </message>
    <message>
        <source>%1 — I/O Options</source>
        <translation>%1 — E/A-Optionen</translation>
    </message>
    <message>
        <source>Choose from the lists what each terminal is wired for; combinations the unit cannot take are not offered.</source>
        <translation>Wählen Sie aus den Listen, wofür jede Klemme verdrahtet ist; Kombinationen, die die Einheit nicht kann, werden nicht angeboten.</translation>
    </message>
    <message>
        <source>Set I/O Options of %1</source>
        <translation>E/A-Optionen von %1 setzen</translation>
    </message>
    <message>
        <source>Used by block</source>
        <translation>Verwendet von Baustein</translation>
    </message>
</context>
<context>
    <name>rs::ui::LadderPage</name>
    <message>
        <source>Block %1 is in %2; the F list offers it.</source>
        <translation>Baustein %1 ist in %2; die F-Liste bietet ihn an.</translation>
    </message>
    <message>
        <source>Make Block %1</source>
        <translation>Baustein %1 erstellen</translation>
    </message>
    <message>
        <source>The library %1 is not among the project&apos;s libraries.</source>
        <translation>Die Bibliothek %1 gehört nicht zu den Bibliotheken des Projekts.</translation>
    </message>
    <message>
        <source>The block could not be written: %1</source>
        <translation>Der Baustein konnte nicht geschrieben werden: %1</translation>
    </message>
    <message>
        <source>Make Block</source>
        <translation>Baustein erstellen</translation>
    </message>
    <message>
        <source>Save the project first: its blocks go to a library beside it.</source>
        <translation>Speichern Sie zuerst das Projekt: seine Bausteine kommen in eine Bibliothek daneben.</translation>
    </message>
    <message>
        <source>A block cannot hold a block: leave block networks out of the selection.</source>
        <translation>Ein Baustein kann keinen Baustein enthalten: lassen Sie Bausteinnetzwerke aus der Auswahl.</translation>
    </message>
    <message>
        <source>Make Block takes networks of one step.</source>
        <translation>Baustein erstellen nimmt Netzwerke eines Schritts.</translation>
    </message>
    <message>
        <source>Update Block %1</source>
        <translation>Baustein %1 aktualisieren</translation>
    </message>
    <message>
        <source>Select a block made by another version of its block to update it.</source>
        <translation>Wählen Sie einen Baustein aus, der mit einer anderen Version erstellt wurde, um ihn zu aktualisieren.</translation>
    </message>
    <message>
        <source>Change Block Pins</source>
        <translation>Anschlüsse des Bausteins ändern</translation>
    </message>
    <message>
        <source>No library of the project has this block: add its library on the project page to bind its pins.</source>
        <translation>Keine Bibliothek des Projekts hat diesen Baustein: fügen Sie seine Bibliothek auf der Projektseite hinzu, um seine Anschlüsse zu beschalten.</translation>
    </message>
    <message>
        <source>Insert Block %1</source>
        <translation>Baustein %1 einfügen</translation>
    </message>
    <message>
        <source>Made by %1 version %2; the library has version %3 (Update Block).</source>
        <translation>Erstellt mit %1 Version %2; die Bibliothek hat Version %3 (Baustein aktualisieren).</translation>
    </message>
    <message>
        <source>%1 — PLC Code</source>
        <translation>%1 — SPS-Code</translation>
    </message>
    <message>
        <source>%1 — Sequence %2</source>
        <translation>%1 — Sequenz %2</translation>
    </message>
    <message>
        <source>The project changed, so the network&apos;s edits were dropped.</source>
        <translation>Das Projekt hat sich geändert, deshalb wurden die Änderungen am Netzwerk verworfen.</translation>
    </message>
    <message>
        <source>Step %1</source>
        <translation>Schritt %1</translation>
    </message>
    <message>
        <source>Not done: %1</source>
        <translation>Nicht ausgeführt: %1</translation>
    </message>
    <message>
        <source>Insert %1</source>
        <translation>%1 einfügen</translation>
    </message>
    <message>
        <source>A network starts with its output: insert a coil, latch, jump or arithmetic box first, then its contacts.</source>
        <translation>Ein Netzwerk beginnt mit seinem Ausgang: Fügen Sie zuerst eine Spule, Setz-/Rücksetzspule, einen Sprung oder eine Arithmetikbox ein, dann seine Kontakte.</translation>
    </message>
    <message>
        <source>Change Element</source>
        <translation>Element ändern</translation>
    </message>
    <message>
        <source>Change Output</source>
        <translation>Ausgang ändern</translation>
    </message>
    <message>
        <source>Delete Element</source>
        <translation>Element löschen</translation>
    </message>
    <message>
        <source>Delete Output</source>
        <translation>Ausgang löschen</translation>
    </message>
    <message>
        <source>This sequence has no step yet.</source>
        <translation>Diese Sequenz hat noch keinen Schritt.</translation>
    </message>
    <message>
        <source>New network: insert its output first (L coil, S set, R reset, J jump ...).</source>
        <translation>Neues Netzwerk: Fügen Sie zuerst seinen Ausgang ein (L Spule, S Setzen, R Rücksetzen, J Sprung …).</translation>
    </message>
    <message>
        <source>Options stand at the start of the PLC code: open the PLC Code page.</source>
        <translation>Optionen stehen am Anfang des SPS-Codes: Öffnen Sie die Seite SPS-Code.</translation>
    </message>
    <message>
        <source>New Config Option</source>
        <translation>Neue Konfigurationsoption</translation>
    </message>
    <message>
        <source>Change Config Option</source>
        <translation>Konfigurationsoption ändern</translation>
    </message>
    <message>
        <source>Enable Option</source>
        <translation>Option aktivieren</translation>
    </message>
    <message>
        <source>Disable Option</source>
        <translation>Option deaktivieren</translation>
    </message>
    <message numerus="yes">
        <source>%n network(s) copied.</source>
        <translation>
            <numerusform>%n Netzwerk kopiert.</numerusform>
            <numerusform>%n Netzwerke kopiert.</numerusform>
        </translation>
    </message>
    <message>
        <source>The clipboard holds no networks.</source>
        <translation>Die Zwischenablage enthält keine Netzwerke.</translation>
    </message>
    <message>
        <source>The clipboard holds no networks: %1</source>
        <translation>Die Zwischenablage enthält keine Netzwerke: %1</translation>
    </message>
    <message numerus="yes">
        <source>Paste %n Network(s)</source>
        <translation>
            <numerusform>%n Netzwerk einfügen</numerusform>
            <numerusform>%n Netzwerke einfügen</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Delete %n Network(s)</source>
        <translation>
            <numerusform>%n Netzwerk löschen</numerusform>
            <numerusform>%n Netzwerke löschen</numerusform>
        </translation>
    </message>
    <message>
        <source>Insert the network&apos;s output before its comment.</source>
        <translation>Fügen Sie den Ausgang des Netzwerks vor seinem Kommentar ein.</translation>
    </message>
    <message>
        <source>Comment Network %1</source>
        <translation>Netzwerk %1 kommentieren</translation>
    </message>
    <message>
        <source>Step Comment</source>
        <translation>Schrittkommentar</translation>
    </message>
    <message>
        <source>Comment of step %1:</source>
        <translation>Kommentar zu Schritt %1:</translation>
    </message>
    <message>
        <source>Comment Step %1</source>
        <translation>Schritt %1 kommentieren</translation>
    </message>
    <message>
        <source>New Step of Sequence %1</source>
        <translation>Neuer Schritt in Sequenz %1</translation>
    </message>
    <message>
        <source>Step %1 added: insert the output of its first network.</source>
        <translation>Schritt %1 hinzugefügt: Fügen Sie den Ausgang seines ersten Netzwerks ein.</translation>
    </message>
    <message>
        <source>Edit Network %1</source>
        <translation>Netzwerk %1 bearbeiten</translation>
    </message>
    <message>
        <source>Network %1 updated.</source>
        <translation>Netzwerk %1 aktualisiert.</translation>
    </message>
    <message>
        <source>The edits of network %1 were dropped.</source>
        <translation>Die Änderungen an Netzwerk %1 wurden verworfen.</translation>
    </message>
    <message>
        <source>Not moved: %1</source>
        <translation>Nicht verschoben: %1</translation>
    </message>
    <message>
        <source>Move Element</source>
        <translation>Element verschieben</translation>
    </message>
    <message>
        <source>Export PDF</source>
        <translation>PDF exportieren</translation>
    </message>
    <message>
        <source>PDF documents (*.pdf)</source>
        <translation>PDF-Dokumente (*.pdf)</translation>
    </message>
    <message>
        <source>Exported to %1.</source>
        <translation>Nach %1 exportiert.</translation>
    </message>
    <message>
        <source>Network %1</source>
        <translation>Netzwerk %1</translation>
    </message>
    <message>
        <source>No networks in this code.</source>
        <translation>Keine Netzwerke in diesem Code.</translation>
    </message>
    <message>
        <source>This code has %1 lines, more than the ladder page draws (%2).
Its text page (F6) shows and edits it.</source>
        <translation>Dieser Code hat %1 Zeilen, mehr als die Kontaktplanseite zeichnet (%2).
Seine Textseite (F6) zeigt und bearbeitet ihn.</translation>
    </message>
    <message>
        <source>Could not export to %1.</source>
        <translation>Export nach %1 nicht möglich.</translation>
    </message>
    <message>
        <source>Could not export to %1: %2</source>
        <translation>Export nach %1 nicht möglich: %2</translation>
    </message>
    <message>
        <source>Network %1 is in edit mode: Update (%2) keeps its edits as one step, Undo (%3) drops them.</source>
        <translation>Netzwerk %1 ist im Bearbeitungsmodus: Aktualisieren (%2) übernimmt die Änderungen als einen einzigen Bearbeitungsschritt, Rückgängig (%3) verwirft sie.</translation>
    </message>
    <message>
        <source>No networks yet. Press %1, or right-click &gt; New Network, then insert the network&apos;s output (L coil, S set, R reset, J jump ...) and its contacts.</source>
        <translation>Noch keine Netzwerke. Drücken Sie %1 oder klicken Sie mit der rechten Maustaste &gt; Neues Netzwerk, und fügen Sie dann den Ausgang des Netzwerks (L Spule, S Setzen, R Rücksetzen, J Sprung …) und seine Kontakte ein.</translation>
    </message>
    <message>
        <source>Simulating: a click or %1 on an input toggles it; a right click or %2 forces any element&apos;s variable. Editing ends the simulation.</source>
        <translation>Simulation: Ein Klick oder %1 auf einem Eingang schaltet ihn um; Rechtsklick oder %2 forcen die Variable eines Elements. Bearbeiten beendet die Simulation.</translation>
    </message>
    <message>
        <source>Keys: %1 insert the toolbar&apos;s elements; %2 %3 %4 before, after, parallel; %5 properties; %6 delete; %7 new network; %8 edit mode.</source>
        <translation>Tasten: %1 fügen die Elemente der Werkzeugleiste ein; %2 %3 %4 davor, danach, parallel; %5 Eigenschaften; %6 löschen; %7 neues Netzwerk; %8 Bearbeitungsmodus.</translation>
    </message>
    <message>
        <source>Select a block network whose block a library of the project has.</source>
        <translation>Wählen Sie ein Bausteinnetzwerk, dessen Baustein eine Bibliothek des Projekts enthält.</translation>
    </message>
    <message>
        <source>%1 did not run: its step is not active</source>
        <translation>%1 lief nicht: sein Schritt ist nicht aktiv</translation>
    </message>
    <message>
        <source>%1 is true</source>
        <translation>%1 ist wahr</translation>
    </message>
    <message>
        <source>%1 is false</source>
        <translation>%1 ist falsch</translation>
    </message>
    <message>
        <source>%1 is on</source>
        <translation>%1 ist ein</translation>
    </message>
    <message>
        <source>%1 is off</source>
        <translation>%1 ist aus</translation>
    </message>
    <message>
        <source>%1 is open</source>
        <translation>%1 ist offen</translation>
    </message>
    <message>
        <source>%1 is on through %2</source>
        <translation>%1 ist ein über %2</translation>
    </message>
    <message>
        <source>%1 is off: %2</source>
        <translation>%1 ist aus: %2</translation>
    </message>
    <message>
        <source>%1 is forced on; its rung is off: %2</source>
        <translation>%1 ist auf Ein forciert; sein Strompfad ist aus: %2</translation>
    </message>
    <message>
        <source>%1 is on; its rung is off: %2</source>
        <translation>%1 ist ein; sein Strompfad ist aus: %2</translation>
    </message>
    <message>
        <source>%1 is forced off; its rung is on</source>
        <translation>%1 ist auf Aus forciert; sein Strompfad ist ein</translation>
    </message>
    <message>
        <source>%1 is off; its rung is on</source>
        <translation>%1 ist aus; sein Strompfad ist ein</translation>
    </message>
    <message>
        <source>%1 is forced off; its rung is on through %2</source>
        <translation>%1 ist auf Aus forciert; sein Strompfad ist ein über %2</translation>
    </message>
    <message>
        <source>%1 is off; its rung is on through %2</source>
        <translation>%1 ist aus; sein Strompfad ist ein über %2</translation>
    </message>
    <message>
        <source>&amp;Comment of network %1:</source>
        <translation>&amp;Kommentar zu Netzwerk %1:</translation>
    </message>
    <message>
        <source>Not copied: %1</source>
        <translation>Nicht kopiert: %1</translation>
    </message>
    <message>
        <source>Copy Element</source>
        <translation>Element kopieren</translation>
    </message>
    <message>
        <source>Moving: drop it before or after an element. Release Shift to copy.</source>
        <translation>Verschieben: vor oder nach einem Element ablegen. Umschalt loslassen zum Kopieren.</translation>
    </message>
    <message>
        <source>Copying: drop it before or after an element. Hold Shift to move.</source>
        <translation>Kopieren: vor oder nach einem Element ablegen. Umschalt halten zum Verschieben.</translation>
    </message>
    <message>
        <source>Password protected, open with permission to configure: a click or %1 on a Config Option&apos;s box checks or unchecks it; nothing else can change.</source>
        <translation>Passwortgeschützt, mit Berechtigung zum Konfigurieren geöffnet: Ein Klick oder %1 auf das Kästchen einer Konfigurationsoption setzt oder löscht es; sonst kann sich nichts ändern.</translation>
    </message>
</context>
<context>
    <name>rs::ui::MainWindow</name>
    <message>
        <source>&amp;Undo</source>
        <translation>&amp;Rückgängig</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>&amp;Wiederholen</translation>
    </message>
    <message>
        <source>Cu&amp;t</source>
        <translation>&amp;Ausschneiden</translation>
    </message>
    <message>
        <source>&amp;Copy</source>
        <translation>&amp;Kopieren</translation>
    </message>
    <message>
        <source>&amp;Paste</source>
        <translation>&amp;Einfügen</translation>
    </message>
    <message>
        <source>Select &amp;All</source>
        <translation>Alles aus&amp;wählen</translation>
    </message>
    <message>
        <source>&amp;Format Document</source>
        <translation>Dokument &amp;formatieren</translation>
    </message>
    <message>
        <source>Rewrite the text in the canonical layout</source>
        <translation>Den Text in die kanonische Form bringen</translation>
    </message>
    <message>
        <source>&amp;About Rungsmith</source>
        <translation>&amp;Über Rungsmith</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <source>Open &amp;Recent</source>
        <translation>&amp;Zuletzt geöffnet</translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation>&amp;Bearbeiten</translation>
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
        <source>Problems</source>
        <translation>Probleme</translation>
    </message>
    <message>
        <source>Line %1, Column %2</source>
        <translation>Zeile %1, Spalte %2</translation>
    </message>
    <message numerus="yes">
        <source>%n error(s)</source>
        <translation>
            <numerusform>%n Fehler</numerusform>
            <numerusform>%n Fehler</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n warning(s)</source>
        <translation>
            <numerusform>%n Warnung</numerusform>
            <numerusform>%n Warnungen</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Not formatted: the text has %n error(s).</source>
        <translation>
            <numerusform>Nicht formatiert: Der Text enthält %n Fehler.</numerusform>
            <numerusform>Nicht formatiert: Der Text enthält %n Fehler.</numerusform>
        </translation>
    </message>
    <message>
        <source>Formatted.</source>
        <translation>Formatiert.</translation>
    </message>
    <message>
        <source>About Rungsmith</source>
        <translation>Über Rungsmith</translation>
    </message>
    <message>
        <source>The project reads without errors now; its pages are back.</source>
        <translation>Das Projekt lässt sich jetzt fehlerfrei lesen; seine Seiten sind wieder da.</translation>
    </message>
    <message>
        <source>&amp;Save Project</source>
        <translation>Projekt &amp;speichern</translation>
    </message>
    <message>
        <source>Save Project &amp;As...</source>
        <translation>Projekt speichern &amp;unter …</translation>
    </message>
    <message>
        <source>&amp;Close Project</source>
        <translation>Projekt s&amp;chließen</translation>
    </message>
    <message>
        <source>Pr&amp;eferences...</source>
        <translation>&amp;Einstellungen …</translation>
    </message>
    <message>
        <source>New &amp;Pluto...</source>
        <translation>Neuer &amp;Pluto …</translation>
    </message>
    <message>
        <source>New &amp;Sequence...</source>
        <translation>Neue &amp;Sequenz …</translation>
    </message>
    <message>
        <source>&amp;Remove Pluto...</source>
        <translation>Pluto &amp;entfernen …</translation>
    </message>
    <message>
        <source>&amp;Compile</source>
        <translation>&amp;Kompilieren</translation>
    </message>
    <message>
        <source>Check the project and write the compiled file (.hps)</source>
        <translation>Das Projekt prüfen und die kompilierte Datei (.hps) schreiben</translation>
    </message>
    <message>
        <source>&amp;Export</source>
        <translation>&amp;Exportieren</translation>
    </message>
    <message>
        <source>&amp;Project</source>
        <translation>&amp;Projekt</translation>
    </message>
    <message>
        <source>&amp;Build</source>
        <translation>E&amp;rstellen</translation>
    </message>
    <message>
        <source>Main</source>
        <translation>Haupt</translation>
    </message>
    <message>
        <source>Projects</source>
        <translation>Projekte</translation>
    </message>
    <message>
        <source>Output</source>
        <translation>Ausgabe</translation>
    </message>
    <message>
        <source>Code With Errors</source>
        <translation>Code mit Fehlern</translation>
    </message>
    <message>
        <source>The code of Pluto %1 has errors, so it cannot be read into the project.</source>
        <translation>Der Code von Pluto %1 hat Fehler und kann deshalb nicht in das Projekt gelesen werden.</translation>
    </message>
    <message>
        <source>Keep editing to fix them, or discard the changes since the code last read without errors.</source>
        <translation>Bearbeiten Sie weiter, um sie zu beheben, oder verwerfen Sie die Änderungen seit dem letzten fehlerfreien Stand.</translation>
    </message>
    <message>
        <source>&amp;Keep Editing</source>
        <translation>&amp;Weiter bearbeiten</translation>
    </message>
    <message>
        <source>&amp;Undo %1</source>
        <translation>&amp;Rückgängig: %1</translation>
    </message>
    <message>
        <source>&amp;Redo %1</source>
        <translation>&amp;Wiederholen: %1</translation>
    </message>
    <message>
        <source>Export Program &amp;Text...</source>
        <translation>Programm&amp;text exportieren …</translation>
    </message>
    <message>
        <source>&amp;Import Variable Names to Pluto...</source>
        <translation>Variablennamen in Pluto &amp;importieren …</translation>
    </message>
    <message>
        <source>E&amp;xport Variable Names from Pluto...</source>
        <translation>Variablennamen aus Pluto e&amp;xportieren …</translation>
    </message>
    <message>
        <source>&amp;Remanent Variables...</source>
        <translation>&amp;Remanente Variablen …</translation>
    </message>
    <message>
        <source>&amp;Ladder or Text</source>
        <translation>&amp;Kontaktplan oder Text</translation>
    </message>
    <message>
        <source>Show the code as ladder networks or as text</source>
        <translation>Den Code als Kontaktplan-Netzwerke oder als Text zeigen</translation>
    </message>
    <message>
        <source>&lt;h3&gt;Rungsmith %1&lt;/h3&gt;&lt;p&gt;An IDE for Pluto safety PLCs: projects, units, I/O options, variables and the program as ladder and as text, checked, compiled and simulated.&lt;/p&gt;&lt;p&gt;Built with Qt %2 and QScintilla %3.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;Rungsmith %1&lt;/h3&gt;&lt;p&gt;Eine Entwicklungsumgebung für Pluto-Sicherheitssteuerungen: Projekte, Einheiten, E/A-Optionen, Variablen und das Programm als Kontaktplan und als Text, geprüft, übersetzt und simuliert.&lt;/p&gt;&lt;p&gt;Erstellt mit Qt %2 und QScintilla %3.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <source>Compile</source>
        <translation>Kompilieren</translation>
    </message>
    <message>
        <source>%1 has changes that are not saved.</source>
        <translation>%1 hat Änderungen, die nicht gespeichert sind.</translation>
    </message>
    <message>
        <source>The compiled file (.hps) is written beside the project and must come from the saved file. Save first, or only check the changes without writing the compiled file.</source>
        <translation>Die kompilierte Datei (.hps) wird neben das Projekt geschrieben und muss aus der gespeicherten Datei stammen. Speichern Sie zuerst, oder prüfen Sie nur die Änderungen, ohne die kompilierte Datei zu schreiben.</translation>
    </message>
    <message>
        <source>&amp;Save and Compile</source>
        <translation>&amp;Speichern und kompilieren</translation>
    </message>
    <message>
        <source>C&amp;heck Only</source>
        <translation>Nur &amp;prüfen</translation>
    </message>
    <message>
        <source>Mark as &amp;Validated...</source>
        <translation>Als &amp;validiert markieren …</translation>
    </message>
    <message>
        <source>Record this version&apos;s program signatures as the validated baseline</source>
        <translation>Die Programmsignaturen dieser Version als validierte Basislinie festhalten</translation>
    </message>
    <message>
        <source>%1 is marked as validated.</source>
        <translation>%1 ist als validiert markiert.</translation>
    </message>
    <message>
        <source>Compare &amp;With...</source>
        <translation>Ver&amp;gleichen mit …</translation>
    </message>
    <message>
        <source>What differs between another version of the project and this one, network by network</source>
        <translation>Was eine andere Version des Projekts von dieser unterscheidet, Netzwerk für Netzwerk</translation>
    </message>
    <message>
        <source>Compare With</source>
        <translation>Vergleichen mit</translation>
    </message>
    <message>
        <source>Rungsmith projects (*.sps)</source>
        <translation>Rungsmith-Projekte (*.sps)</translation>
    </message>
    <message>
        <source>Compare With Va&amp;lidated</source>
        <translation>Mit va&amp;lidierter Version vergleichen</translation>
    </message>
    <message>
        <source>What changed since the project was marked as validated</source>
        <translation>Was sich geändert hat, seit das Projekt als validiert markiert wurde</translation>
    </message>
    <message>
        <source>Merge Project (&amp;ignore conflicts)...</source>
        <translation>Projekt zusammenführen (Konflikte &amp;ignorieren) …</translation>
    </message>
    <message>
        <source>&amp;Merge Project...</source>
        <translation>Projekt &amp;zusammenführen …</translation>
    </message>
    <message>
        <source>%1 (read only)</source>
        <translation>%1 (schreibgeschützt)</translation>
    </message>
    <message>
        <source>%1 (config options only)</source>
        <translation>%1 (nur Konfigurationsoptionen)</translation>
    </message>
    <message>
        <source>New &amp;Gateway...</source>
        <translation>Neues &amp;Gateway...</translation>
    </message>
    <message>
        <source>Remove Gate&amp;way...</source>
        <translation>Gate&amp;way entfernen...</translation>
    </message>
    <message>
        <source>Running %1 in the simulator.</source>
        <translation>%1 läuft im Simulator.</translation>
    </message>
    <message>
        <source>&amp;Prove All</source>
        <translation>Alle &amp;beweisen</translation>
    </message>
    <message>
        <source>Prove every property of the project for every input sequence, or find one that breaks it</source>
        <translation>Jede Eigenschaft des Projekts für jede Eingangsfolge beweisen oder eine Folge finden, die sie verletzt</translation>
    </message>
</context>
<context>
    <name>rs::ui::MakeBlockDialog</name>
    <message>
        <source>The library file is a name of letters, digits and &apos;_&apos; in the project&apos;s folder, such as My_Blocks.rslib.</source>
        <translation>Die Bibliotheksdatei ist ein Name aus Buchstaben, Ziffern und &apos;_&apos; im Ordner des Projekts, etwa Meine_Bausteine.rslib.</translation>
    </message>
    <message>
        <source>private memory</source>
        <translation>privater Merker</translation>
    </message>
    <message>
        <source>Stands for</source>
        <translation>Steht für</translation>
    </message>
    <message>
        <source>Pin or private variable</source>
        <translation>Anschluss oder private Variable</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>What the networks read becomes an input, what they write an output; a memory only they use becomes the block&apos;s own. Name the pins as the block&apos;s users will see them. Comments on the statements do not go into the block.</source>
        <translation>Was die Netzwerke lesen, wird ein Eingang, was sie schreiben, ein Ausgang; ein Merker, den nur sie verwenden, wird der eigene des Bausteins. Benennen Sie die Anschlüsse so, wie die Anwender des Bausteins sie sehen sollen. Kommentare an den Anweisungen kommen nicht in den Baustein.</translation>
    </message>
    <message>
        <source>&amp;Description:</source>
        <translation>Beschrei&amp;bung:</translation>
    </message>
    <message>
        <source>&amp;Library file:</source>
        <translation>&amp;Bibliotheksdatei:</translation>
    </message>
    <message>
        <source>Block &amp;name:</source>
        <translation>Baustein&amp;name:</translation>
    </message>
    <message>
        <source>What the block does, for its users</source>
        <translation>Was der Baustein tut, für seine Anwender</translation>
    </message>
    <message>
        <source>Make Block</source>
        <translation>Baustein erstellen</translation>
    </message>
</context>
<context>
    <name>rs::ui::MarkValidatedDialog</name>
    <message>
        <source>Mark as Validated</source>
        <translation>Als validiert markieren</translation>
    </message>
    <message>
        <source>Records this version&apos;s program signatures as the validated baseline: from now on the review says what changed since. It changes nothing the units do.</source>
        <translation>Hält die Programmsignaturen dieser Version als validierte Basislinie fest: Von nun an sagt die Prüfung, was sich seitdem geändert hat. Es ändert nichts an dem, was die Einheiten tun.</translation>
    </message>
    <message>
        <source>Validated &amp;by:</source>
        <translation>Validiert &amp;von:</translation>
    </message>
    <message>
        <source>&amp;Comment:</source>
        <translation>&amp;Kommentar:</translation>
    </message>
    <message>
        <source>&amp;Mark as Validated</source>
        <translation>Als validiert &amp;markieren</translation>
    </message>
    <message numerus="yes">
        <source>The project has %n error(s) and cannot be validated. Build &gt; Compile (F7) lists them.</source>
        <translation>
            <numerusform>Das Projekt hat %n Fehler und kann nicht validiert werden. Erstellen &gt; Kompilieren (F7) zeigt ihn.</numerusform>
            <numerusform>Das Projekt hat %n Fehler und kann nicht validiert werden. Erstellen &gt; Kompilieren (F7) zeigt sie.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>rs::ui::NetworkCommentDialog</name>
    <message>
        <source>Network Comment</source>
        <translation>Netzwerkkommentar</translation>
    </message>
    <message>
        <source>Return starts a new line; Ctrl+Return confirms.</source>
        <translation>Eingabe beginnt eine neue Zeile; Strg+Eingabe bestätigt.</translation>
    </message>
</context>
<context>
    <name>rs::ui::NewProjectDialog</name>
    <message>
        <source>New project</source>
        <translation>Neues Projekt</translation>
    </message>
    <message>
        <source>&amp;Include source code in compiled file</source>
        <translation>&amp;Quellcode in die kompilierte Datei aufnehmen</translation>
    </message>
    <message>
        <source>New Project</source>
        <translation>Neues Projekt</translation>
    </message>
    <message>
        <source>For your own notes</source>
        <translation>Für Ihre eigenen Notizen</translation>
    </message>
    <message>
        <source>The project name is downloaded to the units and checked when going online. With the source code included, a program uploaded from a unit can be opened again; the file grows and anyone with the password can change the program.</source>
        <translation>Der Projektname wird in die Einheiten geladen und beim Online-Gehen geprüft. Mit eingeschlossenem Quellcode lässt sich ein aus einer Einheit hochgeladenes Programm wieder öffnen; die Datei wird größer, und jeder mit dem Passwort kann das Programm ändern.</translation>
    </message>
    <message>
        <source>Project &amp;name:</source>
        <translation>Projekt&amp;name:</translation>
    </message>
    <message>
        <source>Project &amp;description:</source>
        <translation>Projekt&amp;beschreibung:</translation>
    </message>
    <message>
        <source>Pluto safety PLCs (1 to 32 units on one bus)</source>
        <translation>Pluto-Sicherheitssteuerungen (1 bis 32 Einheiten an einem Bus)</translation>
    </message>
    <message>
        <source>Pixsys PL110 (one ladder PLC)</source>
        <translation>Pixsys PL110 (eine SPS mit Kontaktplan)</translation>
    </message>
    <message>
        <source>&amp;Target:</source>
        <translation>&amp;Ziel:</translation>
    </message>
</context>
<context>
    <name>rs::ui::NewUnitDialog</name>
    <message>
        <source>New Pluto</source>
        <translation>Neuer Pluto</translation>
    </message>
    <message>
        <source>Choose the Pluto type and a station number that no other unit of the project has. The station number is part of every address of the unit: inputs of Pluto 1 are I1.0, I1.1, ...</source>
        <translation>Wählen Sie den Pluto-Typ und eine Stationsnummer, die keine andere Einheit des Projekts hat. Die Stationsnummer ist Teil jeder Adresse der Einheit: Die Eingänge von Pluto 1 sind I1.0, I1.1, …</translation>
    </message>
</context>
<context>
    <name>rs::ui::OpenProjects</name>
    <message>
        <source>Pluto projects (*.sps);;All files (*)</source>
        <translation>Pluto-Projekte (*.sps);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>&amp;New Project...</source>
        <translation>&amp;Neues Projekt …</translation>
    </message>
    <message>
        <source>Start a new project</source>
        <translation>Ein neues Projekt beginnen</translation>
    </message>
    <message>
        <source>&amp;Open Project...</source>
        <translation>Projekt ö&amp;ffnen …</translation>
    </message>
    <message>
        <source>Open a project file</source>
        <translation>Eine Projektdatei öffnen</translation>
    </message>
    <message>
        <source>&amp;Save Project</source>
        <translation>Projekt &amp;speichern</translation>
    </message>
    <message>
        <source>Save the project</source>
        <translation>Das Projekt speichern</translation>
    </message>
    <message>
        <source>Save Project &amp;As...</source>
        <translation>Projekt speichern &amp;unter …</translation>
    </message>
    <message>
        <source>Save the project under a new name</source>
        <translation>Das Projekt unter einem neuen Namen speichern</translation>
    </message>
    <message>
        <source>Save A&amp;ll</source>
        <translation>A&amp;lle speichern</translation>
    </message>
    <message>
        <source>Save every open project</source>
        <translation>Alle offenen Projekte speichern</translation>
    </message>
    <message>
        <source>&amp;Close Project</source>
        <translation>Projekt s&amp;chließen</translation>
    </message>
    <message>
        <source>Close the project</source>
        <translation>Das Projekt schließen</translation>
    </message>
    <message>
        <source>&amp;Program Text...</source>
        <translation>&amp;Programmtext …</translation>
    </message>
    <message>
        <source>Write the program in the language alone, for a text editor or the original compiler</source>
        <translation>Das Programm nur in der Sprache schreiben, für einen Texteditor oder den Originalcompiler</translation>
    </message>
    <message>
        <source>Open &amp;Example Project</source>
        <translation>&amp;Beispielprojekt öffnen</translation>
    </message>
    <message>
        <source>&amp;Clear Menu</source>
        <translation>Menü &amp;leeren</translation>
    </message>
    <message>
        <source>Opened %1. It has errors: fix them in its text.</source>
        <translation>%1 geöffnet. Die Datei hat Fehler: Beheben Sie sie in ihrem Text.</translation>
    </message>
    <message>
        <source>Opened %1</source>
        <translation>%1 geöffnet</translation>
    </message>
    <message>
        <source>Open Project</source>
        <translation>Projekt öffnen</translation>
    </message>
    <message>
        <source>Could not open “%1”.</source>
        <translation>„%1“ konnte nicht geöffnet werden.</translation>
    </message>
    <message>
        <source>Save Project</source>
        <translation>Projekt speichern</translation>
    </message>
    <message>
        <source>The code of Pluto %1 has errors, so your last changes to it are not part of the project. Save the project without them?</source>
        <translation>Der Code von Pluto %1 hat Fehler, deshalb gehören Ihre letzten Änderungen daran nicht zum Projekt. Das Projekt ohne sie speichern?</translation>
    </message>
    <message>
        <source>Save Project As</source>
        <translation>Projekt speichern unter</translation>
    </message>
    <message>
        <source>Could not save “%1”.</source>
        <translation>„%1“ konnte nicht gespeichert werden.</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>%1 gespeichert</translation>
    </message>
    <message>
        <source>Unsaved Changes</source>
        <translation>Ungespeicherte Änderungen</translation>
    </message>
    <message>
        <source>“%1” has changes that are not saved. Save them?</source>
        <translation>„%1“ hat ungespeicherte Änderungen. Speichern?</translation>
    </message>
    <message>
        <source>Export Program Text</source>
        <translation>Programmtext exportieren</translation>
    </message>
    <message>
        <source>-program</source>
        <translation>-programm</translation>
    </message>
    <message>
        <source>Wrote the program text to %1</source>
        <translation>Programmtext nach %1 geschrieben</translation>
    </message>
    <message>
        <source>Autosave failed: %1</source>
        <translation>Automatisches Speichern fehlgeschlagen: %1</translation>
    </message>
    <message>
        <source>Recover Projects</source>
        <translation>Projekte wiederherstellen</translation>
    </message>
    <message>
        <source>Rungsmith was not closed properly. These projects have changes that were saved automatically:</source>
        <translation>Rungsmith wurde nicht ordnungsgemäß beendet. Diese Projekte haben Änderungen, die automatisch gesichert wurden:</translation>
    </message>
    <message>
        <source>&amp;Recover</source>
        <translation>&amp;Wiederherstellen</translation>
    </message>
    <message>
        <source>Pass&amp;word Protect...</source>
        <translation>Pass&amp;wortschutz …</translation>
    </message>
    <message>
        <source>Protect the project with a password, change its protection or take it off</source>
        <translation>Das Projekt mit einem Passwort schützen, den Schutz ändern oder aufheben</translation>
    </message>
    <message>
        <source>“%1” was changed outside Rungsmith after it was password protected.</source>
        <translation>„%1“ wurde außerhalb von Rungsmith geändert, nachdem es mit einem Passwort geschützt wurde.</translation>
    </message>
    <message>
        <source>Password Protect</source>
        <translation>Passwortschutz</translation>
    </message>
    <message>
        <source>Protected with a password: saving writes the protection.</source>
        <translation>Mit Passwort geschützt: Der Schutz wird beim Speichern geschrieben.</translation>
    </message>
    <message>
        <source>Remove Password Protection</source>
        <translation>Passwortschutz aufheben</translation>
    </message>
    <message>
        <source>The password protection is off once the project is saved.</source>
        <translation>Der Passwortschutz ist aufgehoben, sobald das Projekt gespeichert ist.</translation>
    </message>
    <message>
        <source>The first change is at line %1: the signature the password made does not cover it. The project opens read only; its protection is evidence of changes, not a lock, and the file stays readable text. The holder of the main password can accept the change once it is reviewed.</source>
        <translation>Die erste Änderung steht in Zeile %1: Die Signatur, die das Passwort erzeugt hat, deckt sie nicht. Das Projekt wird schreibgeschützt geöffnet; der Schutz macht Änderungen sichtbar, ist aber kein Schloss, und die Datei bleibt lesbarer Text. Wer das Hauptpasswort hat, kann die Änderung nach der Prüfung annehmen.</translation>
    </message>
    <message>
        <source>Open &amp;Read Only</source>
        <translation>&amp;Schreibgeschützt öffnen</translation>
    </message>
    <message>
        <source>&amp;Accept the Change...</source>
        <translation>Änderung &amp;annehmen …</translation>
    </message>
    <message>
        <source>Opened %1 in a PL110 window</source>
        <translation>%1 in einem PL110-Fenster geöffnet</translation>
    </message>
</context>
<context>
    <name>rs::ui::PasswordProtectDialog</name>
    <message>
        <source>&amp;Password protect source file</source>
        <translation>Quelldatei mit &amp;Passwort schützen</translation>
    </message>
    <message>
        <source>Change of config options</source>
        <translation>Ändern der Konfigurationsoptionen</translation>
    </message>
    <message>
        <source>Only possible with &amp;main password</source>
        <translation>Nur mit dem &amp;Hauptpasswort möglich</translation>
    </message>
    <message>
        <source>Possible &amp;without password</source>
        <translation>Ohne Passwort mö&amp;glich</translation>
    </message>
    <message>
        <source>Config &amp;options password required</source>
        <translation>Passwort für Konfigurations&amp;optionen erforderlich</translation>
    </message>
    <message>
        <source>Password Protect</source>
        <translation>Passwortschutz</translation>
    </message>
    <message>
        <source>The file keeps no password: it keeps a signature only the password can make, so a change made outside Rungsmith shows. Anybody can still open and read the file.</source>
        <translation>Die Datei speichert kein Passwort, nur eine Signatur, die nur das Passwort erzeugen kann, sodass eine Änderung außerhalb von Rungsmith sichtbar wird. Jeder kann die Datei weiterhin öffnen und lesen.</translation>
    </message>
    <message>
        <source>Ma&amp;in password:</source>
        <translation>Ha&amp;uptpasswort:</translation>
    </message>
    <message>
        <source>&amp;Repeat:</source>
        <translation>&amp;Wiederholen:</translation>
    </message>
    <message>
        <source>Config options pa&amp;ssword:</source>
        <translation>Pa&amp;sswort für Konfigurationsoptionen:</translation>
    </message>
    <message>
        <source>R&amp;epeat:</source>
        <translation>Wi&amp;ederholen:</translation>
    </message>
    <message>
        <source>Give the main password.</source>
        <translation>Geben Sie das Hauptpasswort ein.</translation>
    </message>
    <message>
        <source>The main password and its repetition differ.</source>
        <translation>Hauptpasswort und Wiederholung stimmen nicht überein.</translation>
    </message>
    <message>
        <source>Give the config options password.</source>
        <translation>Geben Sie das Passwort für die Konfigurationsoptionen ein.</translation>
    </message>
    <message>
        <source>The config options password and its repetition differ.</source>
        <translation>Passwort für die Konfigurationsoptionen und Wiederholung stimmen nicht überein.</translation>
    </message>
    <message>
        <source>The config options password must differ from the main password, or it would give full permission.</source>
        <translation>Das Passwort für die Konfigurationsoptionen muss sich vom Hauptpasswort unterscheiden, sonst gäbe es volle Berechtigung.</translation>
    </message>
</context>
<context>
    <name>rs::ui::PermissionNote</name>
    <message>
        <source>Password protected, open read only: nothing can change.</source>
        <translation>Passwortgeschützt, schreibgeschützt geöffnet: Nichts kann sich ändern.</translation>
    </message>
    <message>
        <source>Password protected, open with permission to configure: only Config Options can change, on the ladder.</source>
        <translation>Passwortgeschützt, mit Berechtigung zum Konfigurieren geöffnet: Nur Konfigurationsoptionen können sich ändern, im Kontaktplan.</translation>
    </message>
</context>
<context>
    <name>rs::ui::Pl110Document</name>
    <message>
        <source>It is not a PL110 program: its first line is not “$target PL110”.</source>
        <translation>Es ist kein PL110-Programm: seine erste Zeile ist nicht „$target PL110“.</translation>
    </message>
    <message>
        <source>Untitled</source>
        <translation>Unbenannt</translation>
    </message>
    <message>
        <source>The program has no file yet: use Save As.</source>
        <translation>Das Programm hat noch keine Datei: „Speichern unter“ verwenden.</translation>
    </message>
</context>
<context>
    <name>rs::ui::Pl110LadderView</name>
    <message>
        <source>INIT — runs once, before the first scan</source>
        <translation>INIT — läuft einmal, vor dem ersten Zyklus</translation>
    </message>
    <message>
        <source>MAIN — runs every scan</source>
        <translation>MAIN — läuft in jedem Zyklus</translation>
    </message>
    <message>
        <source>Rung %1</source>
        <translation>Netzwerk %1</translation>
    </message>
    <message>
        <source>The program has no rungs yet: write them on the Program page.</source>
        <translation>Das Programm hat noch keine Netzwerke: schreiben Sie sie auf der Seite „Programm“.</translation>
    </message>
</context>
<context>
    <name>rs::ui::Pl110NamesPage</name>
    <message>
        <source>&amp;Import CSV...</source>
        <translation>CSV &amp;importieren …</translation>
    </message>
    <message>
        <source>Name addresses from a CSV file: Variable, Symbolic Name, Description</source>
        <translation>Adressen aus einer CSV-Datei benennen: Variable, symbolischer Name, Beschreibung</translation>
    </message>
    <message>
        <source>E&amp;xport CSV...</source>
        <translation>CSV e&amp;xportieren …</translation>
    </message>
    <message>
        <source>Write the names and descriptions to a CSV file</source>
        <translation>Namen und Beschreibungen in eine CSV-Datei schreiben</translation>
    </message>
    <message>
        <source>Address</source>
        <translation>Adresse</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>Description</source>
        <translation>Beschreibung</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>Wert</translation>
    </message>
    <message>
        <source>Addresses</source>
        <translation>Adressen</translation>
    </message>
    <message>
        <source>Program writes</source>
        <translation>Programm schreibt</translation>
    </message>
    <message>
        <source>Modbus (word / bit)</source>
        <translation>Modbus (Wort / Bit)</translation>
    </message>
    <message>
        <source>What it holds</source>
        <translation>Inhalt</translation>
    </message>
    <message>
        <source>Names: double-click a cell to change it; the last row names another address.</source>
        <translation>Namen: Doppelklick auf eine Zelle ändert sie; die letzte Zeile benennt eine weitere Adresse.</translation>
    </message>
    <message>
        <source>Memory areas of the PL110 (datasheet, section 2)</source>
        <translation>Speicherbereiche der PL110 (Datenblatt, Abschnitt 2)</translation>
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
        <source>–</source>
        <translation>–</translation>
    </message>
    <message>
        <source> (read only)</source>
        <translation> (nur lesen)</translation>
    </message>
    <message>
        <source>Type an address such as I6, Q4, M10 or VW20</source>
        <translation>Eine Adresse eingeben, etwa I6, Q4, M10 oder VW20</translation>
    </message>
    <message>
        <source>%1 rewrites the program text; fix its errors on the Program page first, so that no line is lost.</source>
        <translation>%1 schreibt den Programmtext neu; beheben Sie zuerst seine Fehler auf der Seite „Programm“, damit keine Zeile verloren geht.</translation>
    </message>
    <message>
        <source>Naming</source>
        <translation>Das Benennen</translation>
    </message>
    <message>
        <source>“%1” is not a PL110 address</source>
        <translation>„%1“ ist keine PL110-Adresse</translation>
    </message>
    <message>
        <source>Name %1</source>
        <translation>%1 benennen</translation>
    </message>
    <message>
        <source>Import Names</source>
        <translation>Namen importieren</translation>
    </message>
    <message>
        <source>CSV files (*.csv *.txt);;All files (*)</source>
        <translation>CSV-Dateien (*.csv *.txt);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Importing names</source>
        <translation>Das Importieren von Namen</translation>
    </message>
    <message numerus="yes">
        <source>Nothing was imported: %n row(s) could not be read.
%1</source>
        <translation>
            <numerusform>Nichts wurde importiert: %n Zeile konnte nicht gelesen werden.
%1</numerusform>
            <numerusform>Nichts wurde importiert: %n Zeilen konnten nicht gelesen werden.
%1</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Imported %n name(s) from %1</source>
        <translation>
            <numerusform>%n Name aus %1 importiert</numerusform>
            <numerusform>%n Namen aus %1 importiert</numerusform>
        </translation>
    </message>
    <message>
        <source>CSV, comma-separated (*.csv)</source>
        <translation>CSV, durch Kommas getrennt (*.csv)</translation>
    </message>
    <message>
        <source>CSV, semicolon-separated, as spreadsheets in Swedish and German expect (*.csv)</source>
        <translation>CSV, durch Semikolons getrennt, wie deutsche und schwedische Tabellenkalkulationen es erwarten (*.csv)</translation>
    </message>
    <message>
        <source>Export Names</source>
        <translation>Namen exportieren</translation>
    </message>
    <message>
        <source>Exported the names to %1</source>
        <translation>Namen nach %1 exportiert</translation>
    </message>
    <message>
        <source>Type a value to set the input or force the variable</source>
        <translation>Einen Wert eingeben, um den Eingang zu setzen oder die Variable zu forcieren</translation>
    </message>
    <message>
        <source>Start the simulation to set values.</source>
        <translation>Starten Sie die Simulation, um Werte zu setzen.</translation>
    </message>
    <message>
        <source>“%1” is not a whole number</source>
        <translation>„%1“ ist keine ganze Zahl</translation>
    </message>
</context>
<context>
    <name>rs::ui::Pl110Simulation</name>
    <message>
        <source>The program changed: the simulation stopped. Start it again to run the new program.</source>
        <translation>Das Programm hat sich geändert: die Simulation wurde angehalten. Starten Sie sie erneut, um das neue Programm auszuführen.</translation>
    </message>
    <message>
        <source>The program has errors; fix them to simulate it.</source>
        <translation>Das Programm hat Fehler; beheben Sie sie, um es zu simulieren.</translation>
    </message>
</context>
<context>
    <name>rs::ui::Pl110WaveformPanel</name>
    <message>
        <source>Add a variable to plot: an address or a name</source>
        <translation>Eine Variable zum Darstellen hinzufügen: eine Adresse oder ein Name</translation>
    </message>
    <message>
        <source>Export VCD</source>
        <translation>VCD exportieren</translation>
    </message>
    <message>
        <source>%1 is plotted already</source>
        <translation>%1 wird schon dargestellt</translation>
    </message>
    <message>
        <source>Nothing is recorded yet: start the simulation or run a scenario.</source>
        <translation>Noch nichts aufgezeichnet: Starten Sie die Simulation oder führen Sie ein Szenario aus.</translation>
    </message>
    <message>
        <source>Value Change Dumps (*.vcd);;All files (*)</source>
        <translation>Value Change Dumps (*.vcd);;Alle Dateien (*)</translation>
    </message>
</context>
<context>
    <name>rs::ui::Pl110Window</name>
    <message>
        <source>error</source>
        <translation>Fehler</translation>
    </message>
    <message>
        <source>warning</source>
        <translation>Warnung</translation>
    </message>
    <message>
        <source>&amp;Ladder</source>
        <translation>&amp;Kontaktplan</translation>
    </message>
    <message>
        <source>&amp;Names and Areas</source>
        <translation>&amp;Namen und Bereiche</translation>
    </message>
    <message>
        <source>Problems</source>
        <translation>Probleme</translation>
    </message>
    <message>
        <source>Scenario Results</source>
        <translation>Szenarioergebnisse</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <source>&amp;New PL110 Program</source>
        <translation>&amp;Neues PL110-Programm</translation>
    </message>
    <message>
        <source>New program</source>
        <translation>Neues Programm</translation>
    </message>
    <message>
        <source>&amp;Open...</source>
        <translation>Ö&amp;ffnen …</translation>
    </message>
    <message>
        <source>&amp;Save</source>
        <translation>&amp;Speichern</translation>
    </message>
    <message>
        <source>Save &amp;As...</source>
        <translation>Speichern &amp;unter …</translation>
    </message>
    <message>
        <source>&amp;Close</source>
        <translation>S&amp;chließen</translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation>&amp;Bearbeiten</translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation>&amp;Rückgängig</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>&amp;Wiederholen</translation>
    </message>
    <message>
        <source>&amp;Undo %1</source>
        <translation>&amp;Rückgängig: %1</translation>
    </message>
    <message>
        <source>&amp;Redo %1</source>
        <translation>&amp;Wiederholen: %1</translation>
    </message>
    <message>
        <source>&amp;Format Text</source>
        <translation>Text &amp;formatieren</translation>
    </message>
    <message>
        <source>Write the program as the printer writes it: one space around operators, names as declared</source>
        <translation>Das Programm so schreiben, wie der Drucker es schreibt: ein Leerzeichen um Operatoren, Namen wie deklariert</translation>
    </message>
    <message>
        <source>Fix the errors first: formatting would drop the lines that do not read.</source>
        <translation>Beheben Sie zuerst die Fehler: das Formatieren ließe die unlesbaren Zeilen weg.</translation>
    </message>
    <message>
        <source>Format Text</source>
        <translation>Text formatieren</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Ansicht</translation>
    </message>
    <message>
        <source>&amp;Program Text</source>
        <translation>&amp;Programmtext</translation>
    </message>
    <message>
        <source>&amp;Simulation</source>
        <translation>&amp;Simulation</translation>
    </message>
    <message>
        <source>&amp;Start</source>
        <translation>&amp;Starten</translation>
    </message>
    <message>
        <source>Run the program on the simulated clock; click an input&apos;s contact to switch it</source>
        <translation>Das Programm auf der simulierten Uhr ausführen; ein Klick auf den Kontakt eines Eingangs schaltet ihn</translation>
    </message>
    <message>
        <source>S&amp;top</source>
        <translation>&amp;Anhalten</translation>
    </message>
    <message>
        <source>Hold the program and the clock; the state stays shown</source>
        <translation>Programm und Uhr anhalten; der Zustand bleibt sichtbar</translation>
    </message>
    <message>
        <source>Single S&amp;can</source>
        <translation>&amp;Einzelzyklus</translation>
    </message>
    <message>
        <source>&amp;Reset</source>
        <translation>&amp;Zurücksetzen</translation>
    </message>
    <message>
        <source>Power on again at time 0; inputs set and forces stay</source>
        <translation>Erneut einschalten bei Zeit 0; gesetzte Eingänge und Forcierungen bleiben</translation>
    </message>
    <message>
        <source>Run Sce&amp;nario...</source>
        <translation>Sze&amp;nario ausführen …</translation>
    </message>
    <message>
        <source>Run a scenario file (.scn) from power on and list its results</source>
        <translation>Eine Szenariodatei (.scn) ab dem Einschalten ausführen und ihre Ergebnisse auflisten</translation>
    </message>
    <message>
        <source>Simulation</source>
        <translation>Simulation</translation>
    </message>
    <message>
        <source>Typing</source>
        <translation>Tippen</translation>
    </message>
    <message numerus="yes">
        <source>%n rung(s), no errors</source>
        <translation>
            <numerusform>%n Netzwerk, keine Fehler</numerusform>
            <numerusform>%n Netzwerke, keine Fehler</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n error(s): the ladder shows the lines that read</source>
        <translation>
            <numerusform>%n Fehler: der Kontaktplan zeigt die lesbaren Zeilen</numerusform>
            <numerusform>%n Fehler: der Kontaktplan zeigt die lesbaren Zeilen</numerusform>
        </translation>
    </message>
    <message>
        <source>%1[*] — PL110 — Rungsmith</source>
        <translation>%1[*] — PL110 — Rungsmith</translation>
    </message>
    <message>
        <source>Simulating: %1 s, scan %2</source>
        <translation>Simulation läuft: %1 s, Zyklus %2</translation>
    </message>
    <message>
        <source>Stopped at %1 s, scan %2</source>
        <translation>Angehalten bei %1 s, Zyklus %2</translation>
    </message>
    <message>
        <source>Start the simulation (F5) to switch inputs from the ladder.</source>
        <translation>Starten Sie die Simulation (F5), um Eingänge im Kontaktplan zu schalten.</translation>
    </message>
    <message>
        <source>%1 set to %2</source>
        <translation>%1 auf %2 gesetzt</translation>
    </message>
    <message>
        <source>%1 forced to %2</source>
        <translation>%1 auf %2 forciert</translation>
    </message>
    <message>
        <source>Set %1 to 1</source>
        <translation>%1 auf 1 setzen</translation>
    </message>
    <message>
        <source>Force %1 to 1</source>
        <translation>%1 auf 1 forcieren</translation>
    </message>
    <message>
        <source>Set %1 to 0</source>
        <translation>%1 auf 0 setzen</translation>
    </message>
    <message>
        <source>Force %1 to 0</source>
        <translation>%1 auf 0 forcieren</translation>
    </message>
    <message>
        <source>Let go of %1</source>
        <translation>%1 loslassen</translation>
    </message>
    <message>
        <source>Release %1</source>
        <translation>Forcierung von %1 aufheben</translation>
    </message>
    <message>
        <source>Show in Program Text</source>
        <translation>Im Programmtext zeigen</translation>
    </message>
    <message>
        <source>Save</source>
        <translation>Speichern</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>%1 gespeichert</translation>
    </message>
    <message>
        <source>Save PL110 Program As</source>
        <translation>PL110-Programm speichern unter</translation>
    </message>
    <message>
        <source>PL110 programs (*.sps)</source>
        <translation>PL110-Programme (*.sps)</translation>
    </message>
    <message>
        <source>Save As</source>
        <translation>Speichern unter</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>Schließen</translation>
    </message>
    <message>
        <source>Save the changes to %1?</source>
        <translation>Die Änderungen an %1 speichern?</translation>
    </message>
    <message>
        <source>Open PL110 Program</source>
        <translation>PL110-Programm öffnen</translation>
    </message>
    <message>
        <source>PL110 programs (*.sps);;All files (*)</source>
        <translation>PL110-Programme (*.sps);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Open</source>
        <translation>Öffnen</translation>
    </message>
    <message>
        <source>Could not open “%1”.</source>
        <translation>„%1“ konnte nicht geöffnet werden.</translation>
    </message>
    <message>
        <source>Run Scenario</source>
        <translation>Szenario ausführen</translation>
    </message>
    <message>
        <source>Scenarios (*.scn);;All files (*)</source>
        <translation>Szenarien (*.scn);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>%1: %2 passed, %3 failed</source>
        <translation>%1: %2 bestanden, %3 fehlgeschlagen</translation>
    </message>
    <message>
        <source>%1 did not run: it has errors</source>
        <translation>%1 lief nicht: es hat Fehler</translation>
    </message>
    <message>
        <source>&amp;New Rung...</source>
        <translation>&amp;Neues Netzwerk …</translation>
    </message>
    <message>
        <source>Write a rung after the selected one: its output, &apos;=&apos; and its condition</source>
        <translation>Ein Netzwerk nach dem gewählten schreiben: sein Ausgang, „=“ und seine Bedingung</translation>
    </message>
    <message>
        <source>&amp;Edit...</source>
        <translation>&amp;Bearbeiten …</translation>
    </message>
    <message>
        <source>Change the selected contact, or the selected rung as its line</source>
        <translation>Den gewählten Kontakt ändern, oder das gewählte Netzwerk als seine Zeile</translation>
    </message>
    <message>
        <source>Contact &amp;After...</source>
        <translation>Kontakt &amp;danach …</translation>
    </message>
    <message>
        <source>Contact &amp;Before...</source>
        <translation>Kontakt da&amp;vor …</translation>
    </message>
    <message>
        <source>Contact in &amp;Parallel...</source>
        <translation>Kontakt &amp;parallel …</translation>
    </message>
    <message>
        <source>&amp;Delete</source>
        <translation>&amp;Löschen</translation>
    </message>
    <message>
        <source>Delete the selected element; with the output selected, the rung</source>
        <translation>Das gewählte Element löschen; ist der Ausgang gewählt, das Netzwerk</translation>
    </message>
    <message>
        <source>Move Rung &amp;Up</source>
        <translation>Netzwerk nach &amp;oben</translation>
    </message>
    <message>
        <source>Move Rung Do&amp;wn</source>
        <translation>Netzwerk nach &amp;unten</translation>
    </message>
    <message>
        <source>While simulating: switch the selected contact&apos;s input, or force its variable the other way</source>
        <translation>Während der Simulation: den Eingang des gewählten Kontakts umschalten oder seine Variable umgekehrt forcieren</translation>
    </message>
    <message>
        <source>Ladder or &amp;Text</source>
        <translation>Kontaktplan oder &amp;Text</translation>
    </message>
    <message>
        <source>Switch between the ladder and the program text at the same rung</source>
        <translation>Zwischen Kontaktplan und Programmtext am selben Netzwerk wechseln</translation>
    </message>
    <message>
        <source>Fix the errors on the Program page first: the ladder&apos;s edits rewrite the text, and lines with errors would be lost.</source>
        <translation>Beheben Sie zuerst die Fehler auf der Seite „Programm“: die Änderungen im Kontaktplan schreiben den Text neu, und fehlerhafte Zeilen gingen verloren.</translation>
    </message>
    <message>
        <source>%1 was not done: %2</source>
        <translation>%1 wurde nicht ausgeführt: %2</translation>
    </message>
    <message>
        <source>Column %1: %2</source>
        <translation>Spalte %1: %2</translation>
    </message>
    <message>
        <source>New Rung</source>
        <translation>Neues Netzwerk</translation>
    </message>
    <message>
        <source>The rung as its line is written: its output, &apos;=&apos; and its condition, for example Q1 = I1 * /I2</source>
        <translation>Das Netzwerk, wie seine Zeile geschrieben wird: sein Ausgang, „=“ und seine Bedingung, zum Beispiel Q1 = I1 * /I2</translation>
    </message>
    <message>
        <source>Edit Rung</source>
        <translation>Netzwerk bearbeiten</translation>
    </message>
    <message>
        <source>The rung as its line is written: its output, &apos;=&apos; and its condition, and a comment after &apos;;&apos;</source>
        <translation>Das Netzwerk, wie seine Zeile geschrieben wird: sein Ausgang, „=“ und seine Bedingung, und ein Kommentar nach „;“</translation>
    </message>
    <message>
        <source>Edit Element</source>
        <translation>Element bearbeiten</translation>
    </message>
    <message>
        <source>The element as a rung writes it: a contact such as I3 or /I3, a comparison such as (VW1 &gt;= 10), NOT, P or N; several joined by * and + take its place together</source>
        <translation>Das Element, wie ein Netzwerk es schreibt: ein Kontakt wie I3 oder /I3, ein Vergleich wie (VW1 &gt;= 10), NOT, P oder N; mehrere, verbunden durch * und +, treten gemeinsam an seine Stelle</translation>
    </message>
    <message>
        <source>Contact in Parallel</source>
        <translation>Kontakt parallel</translation>
    </message>
    <message>
        <source>Contact Before</source>
        <translation>Kontakt davor</translation>
    </message>
    <message>
        <source>Contact After</source>
        <translation>Kontakt danach</translation>
    </message>
    <message>
        <source>A contact such as I3 or /I3, a comparison such as (VW1 &gt;= 10), NOT, P or N, or several joined by * and +</source>
        <translation>Ein Kontakt wie I3 oder /I3, ein Vergleich wie (VW1 &gt;= 10), NOT, P oder N, oder mehrere, verbunden durch * und +</translation>
    </message>
    <message>
        <source>Delete Rung</source>
        <translation>Netzwerk löschen</translation>
    </message>
    <message>
        <source>Delete Element</source>
        <translation>Element löschen</translation>
    </message>
    <message>
        <source>Move Rung Up</source>
        <translation>Netzwerk nach oben</translation>
    </message>
    <message>
        <source>Move Rung Down</source>
        <translation>Netzwerk nach unten</translation>
    </message>
    <message>
        <source>Ladder</source>
        <translation>Kontaktplan</translation>
    </message>
    <message>
        <source>Program</source>
        <translation>Programm</translation>
    </message>
    <message>
        <source>Names and Areas</source>
        <translation>Namen und Bereiche</translation>
    </message>
    <message>
        <source>T&amp;oggle</source>
        <translation>Um&amp;schalten</translation>
    </message>
    <message>
        <source>Waveform</source>
        <translation>Signalverlauf</translation>
    </message>
    <message>
        <source>Serve &amp;Modbus RTU</source>
        <translation>&amp;Modbus RTU bereitstellen</translation>
    </message>
    <message>
        <source>Answer Modbus RTU requests on a pseudo-terminal, as the PL110&apos;s serial port, from the simulated memory (slave 1)</source>
        <translation>Modbus-RTU-Anfragen auf einem Pseudoterminal beantworten, als serielle Schnittstelle der PL110, aus dem simulierten Speicher (Slave 1)</translation>
    </message>
    <message>
        <source>Modbus RTU: %1, slave 1</source>
        <translation>Modbus RTU: %1, Slave 1</translation>
    </message>
    <message>
        <source>Plot in &amp;Waveform</source>
        <translation>Im Si&amp;gnalverlauf darstellen</translation>
    </message>
    <message>
        <source>Record the selected contact&apos;s or output&apos;s variable in the waveform</source>
        <translation>Die Variable des gewählten Kontakts oder Ausgangs im Signalverlauf aufzeichnen</translation>
    </message>
    <message>
        <source>%1 is plotted in the waveform</source>
        <translation>%1 wird im Signalverlauf dargestellt</translation>
    </message>
    <message>
        <source>Autosave failed: %1</source>
        <translation>Automatisches Speichern fehlgeschlagen: %1</translation>
    </message>
    <message>
        <source>New Rung in &amp;INIT...</source>
        <translation>Neues Netzwerk in &amp;INIT …</translation>
    </message>
    <message>
        <source>Write a rung at the end of INIT, which runs once before the first scan</source>
        <translation>Ein Netzwerk am Ende von INIT schreiben, das einmal vor dem ersten Zyklus läuft</translation>
    </message>
    <message>
        <source>New Rung in INIT</source>
        <translation>Neues Netzwerk in INIT</translation>
    </message>
</context>
<context>
    <name>rs::ui::PlutoLexer</name>
    <message>
        <source>Default</source>
        <translation>Standard</translation>
    </message>
    <message>
        <source>Comment</source>
        <translation>Kommentar</translation>
    </message>
    <message>
        <source>Structured record</source>
        <translation>Strukturierter Eintrag</translation>
    </message>
    <message>
        <source>Declaration</source>
        <translation>Deklaration</translation>
    </message>
    <message>
        <source>Declaration option</source>
        <translation>Deklarationsoption</translation>
    </message>
    <message>
        <source>Directive</source>
        <translation>Direktive</translation>
    </message>
    <message>
        <source>Directive text</source>
        <translation>Direktiventext</translation>
    </message>
    <message>
        <source>Step header</source>
        <translation>Schrittkopf</translation>
    </message>
    <message>
        <source>Address</source>
        <translation>Adresse</translation>
    </message>
    <message>
        <source>Instruction</source>
        <translation>Anweisung</translation>
    </message>
    <message>
        <source>Time constant</source>
        <translation>Zeitkonstante</translation>
    </message>
    <message>
        <source>Number</source>
        <translation>Zahl</translation>
    </message>
    <message>
        <source>Operator</source>
        <translation>Operator</translation>
    </message>
    <message>
        <source>Symbolic name</source>
        <translation>Symbolischer Name</translation>
    </message>
    <message>
        <source>Invalid text</source>
        <translation>Ungültiger Text</translation>
    </message>
</context>
<context>
    <name>rs::ui::PreferencesDialog</name>
    <message>
        <source>Start with ladder diagrams &amp;expanded</source>
        <translation>Kontaktpläne &amp;aufgeklappt öffnen</translation>
    </message>
    <message>
        <source>&amp;Unconfigured I/O warnings at compile time</source>
        <translation>Warnungen für &amp;nicht konfigurierte E/A beim Kompilieren</translation>
    </message>
    <message>
        <source>Preferences</source>
        <translation>Einstellungen</translation>
    </message>
    <message>
        <source>Ladder colours</source>
        <translation>Farben des Kontaktplans</translation>
    </message>
    <message>
        <source>Ladder background:</source>
        <translation>Hintergrund:</translation>
    </message>
    <message>
        <source>Focused ladder background:</source>
        <translation>Hintergrund mit Fokus:</translation>
    </message>
    <message>
        <source>Ladder component body:</source>
        <translation>Bauteilkörper:</translation>
    </message>
    <message>
        <source>Ladder lines:</source>
        <translation>Linien:</translation>
    </message>
    <message>
        <source>Ladder lines off:</source>
        <translation>Linien, aus:</translation>
    </message>
    <message>
        <source>Ladder lines on:</source>
        <translation>Linien, ein:</translation>
    </message>
    <message>
        <source>%1 ms</source>
        <translation>%1 ms</translation>
    </message>
    <message>
        <source>Update interval in online mode. A shorter interval makes the computer slower.</source>
        <translation>Aktualisierungsintervall im Online-Modus. Ein kürzeres Intervall macht den Rechner langsamer.</translation>
    </message>
    <message>
        <source>System language</source>
        <translation>Sprache des Systems</translation>
    </message>
    <message>
        <source>Follow the system</source>
        <translation>Wie das System</translation>
    </message>
    <message>
        <source>Light</source>
        <translation>Hell</translation>
    </message>
    <message>
        <source>Dark</source>
        <translation>Dunkel</translation>
    </message>
    <message>
        <source> min</source>
        <translation> min</translation>
    </message>
    <message>
        <source>A new language shows when Rungsmith starts again.</source>
        <translation>Eine neue Sprache erscheint beim nächsten Start von Rungsmith.</translation>
    </message>
    <message>
        <source>General</source>
        <translation>Allgemein</translation>
    </message>
    <message>
        <source>Screen update &amp;interval:</source>
        <translation>&amp;Aktualisierungsintervall:</translation>
    </message>
    <message>
        <source>&amp;Language:</source>
        <translation>&amp;Sprache:</translation>
    </message>
    <message>
        <source>&amp;Theme:</source>
        <translation>&amp;Design:</translation>
    </message>
    <message>
        <source>&amp;Autosave every:</source>
        <translation>&amp;Automatisch speichern alle:</translation>
    </message>
    <message>
        <source>From %1 to %2 minutes. A crash loses at most this much work.</source>
        <translation>Von %1 bis %2 Minuten. Ein Absturz kostet höchstens so viel Arbeit.</translation>
    </message>
    <message>
        <source>Theme &amp;Colours</source>
        <translation>&amp;Farben des Designs</translation>
    </message>
    <message>
        <source>Draw the ladder in the theme&apos;s colours again</source>
        <translation>Den Kontaktplan wieder in den Farben des Designs zeichnen</translation>
    </message>
    <message>
        <source>Theme</source>
        <translation>Design</translation>
    </message>
    <message>
        <source>As the theme draws it; click to choose a colour</source>
        <translation>Wie das Design es zeichnet; klicken, um eine Farbe zu wählen</translation>
    </message>
    <message>
        <source>Simulated gateway</source>
        <translation>Simuliertes Gateway</translation>
    </message>
    <message>
        <source>Modbus TCP &amp;address:</source>
        <translation>Modbus-TCP-&amp;Adresse:</translation>
    </message>
    <message>
        <source>Modbus TCP &amp;port:</source>
        <translation>Modbus-TCP-&amp;Port:</translation>
    </message>
    <message>
        <source>Where Serve Modbus TCP listens while simulating. 127.0.0.1 lets only this computer connect; 0.0.0.0 the network.</source>
        <translation>Wo Modbus TCP bedienen während der Simulation lauscht. 127.0.0.1 lässt nur diesen Rechner verbinden, 0.0.0.0 das Netz.</translation>
    </message>
</context>
<context>
    <name>rs::ui::ProblemsView</name>
    <message>
        <source>Location</source>
        <translation>Ort</translation>
    </message>
    <message>
        <source>Message</source>
        <translation>Meldung</translation>
    </message>
    <message>
        <source>Error</source>
        <translation>Fehler</translation>
    </message>
    <message>
        <source>Warning</source>
        <translation>Warnung</translation>
    </message>
    <message>
        <source>No problems found.</source>
        <translation>Keine Probleme gefunden.</translation>
    </message>
</context>
<context>
    <name>rs::ui::ProgramEditor</name>
    <message>
        <source>Error message</source>
        <translation>Fehlermeldung</translation>
    </message>
    <message>
        <source>Warning message</source>
        <translation>Warnmeldung</translation>
    </message>
</context>
<context>
    <name>rs::ui::ProjectDocument</name>
    <message>
        <source>Expand Block Instances</source>
        <translation>Bausteininstanzen expandieren</translation>
    </message>
    <message>
        <source>Untitled</source>
        <translation>Unbenannt</translation>
    </message>
    <message>
        <source>The project is open read only: nothing in it can change.</source>
        <translation>Das Projekt ist schreibgeschützt geöffnet: Nichts darin kann sich ändern.</translation>
    </message>
    <message>
        <source>The project is open with permission to configure: only its Config Options can change.</source>
        <translation>Das Projekt ist mit Berechtigung zum Konfigurieren geöffnet: Nur seine Konfigurationsoptionen können sich ändern.</translation>
    </message>
    <message>
        <source>It is a program for the Pixsys PL110, not a Pluto project: File &gt; Open opens it in a PL110 window.</source>
        <translation>Es ist ein Programm für die Pixsys PL110, kein Pluto-Projekt: Datei &gt; Öffnen öffnet es in einem PL110-Fenster.</translation>
    </message>
</context>
<context>
    <name>rs::ui::ProjectPage</name>
    <message>
        <source>Add &amp;Standard Library</source>
        <translation>&amp;Standardbibliothek hinzufügen</translation>
    </message>
    <message>
        <source>Add &amp;User Library...</source>
        <translation>Ben&amp;utzerbibliothek hinzufügen...</translation>
    </message>
    <message>
        <source>&amp;Remove Library</source>
        <translation>Bibliothek &amp;entfernen</translation>
    </message>
    <message>
        <source>No standard library is installed</source>
        <translation>Keine Standardbibliothek ist installiert</translation>
    </message>
    <message>
        <source>Function &amp;libraries:</source>
        <translation>Funktions&amp;bibliotheken:</translation>
    </message>
    <message>
        <source>Every library found: the standard ones and those in the project&apos;s folder</source>
        <translation>Alle gefundenen Bibliotheken: die Standardbibliotheken und die im Ordner des Projekts</translation>
    </message>
    <message>
        <source>A user library in the project&apos;s folder</source>
        <translation>Eine Benutzerbibliothek im Ordner des Projekts</translation>
    </message>
    <message>
        <source>A standard library</source>
        <translation>Eine Standardbibliothek</translation>
    </message>
    <message>
        <source>%1 (not found)</source>
        <translation>%1 (nicht gefunden)</translation>
    </message>
    <message>
        <source>Add Library %1</source>
        <translation>Bibliothek %1 hinzufügen</translation>
    </message>
    <message>
        <source>Add User Library</source>
        <translation>Benutzerbibliothek hinzufügen</translation>
    </message>
    <message>
        <source>Function block libraries (*.rslib)</source>
        <translation>Funktionsbausteinbibliotheken (*.rslib)</translation>
    </message>
    <message>
        <source>Remove Library %1</source>
        <translation>Bibliothek %1 entfernen</translation>
    </message>
    <message>
        <source>&amp;Include source code in compiled file</source>
        <translation>&amp;Quellcode in die kompilierte Datei aufnehmen</translation>
    </message>
    <message>
        <source>Project &amp;name:</source>
        <translation>Projekt&amp;name:</translation>
    </message>
    <message>
        <source>Project &amp;description:</source>
        <translation>Projekt&amp;beschreibung:</translation>
    </message>
    <message>
        <source>File:</source>
        <translation>Datei:</translation>
    </message>
    <message>
        <source>Units:</source>
        <translation>Einheiten:</translation>
    </message>
    <message>
        <source>Include Source Code</source>
        <translation>Quellcode aufnehmen</translation>
    </message>
    <message>
        <source>Leave Out Source Code</source>
        <translation>Quellcode weglassen</translation>
    </message>
    <message>
        <source>Project %1</source>
        <translation>Projekt %1</translation>
    </message>
    <message>
        <source>Not saved yet</source>
        <translation>Noch nicht gespeichert</translation>
    </message>
    <message>
        <source>None yet. Add one with Project &gt; New Pluto.</source>
        <translation>Noch keine. Fügen Sie eine mit Projekt &gt; Neuer Pluto hinzu.</translation>
    </message>
    <message>
        <source>Rename Project</source>
        <translation>Projekt umbenennen</translation>
    </message>
    <message>
        <source>Change Project Description</source>
        <translation>Projektbeschreibung ändern</translation>
    </message>
    <message>
        <source>Program signature:</source>
        <translation>Programmsignatur:</translation>
    </message>
    <message>
        <source>Validated:</source>
        <translation>Validiert:</translation>
    </message>
    <message>
        <source>on %1 by %2 (signature %3)</source>
        <translation>am %1 von %2 (Signatur %3)</translation>
    </message>
    <message>
        <source>not yet (Project &gt; Mark as Validated)</source>
        <translation>noch nicht (Projekt &gt; Als validiert markieren)</translation>
    </message>
    <message>
        <source>Since then:</source>
        <translation>Seitdem:</translation>
    </message>
    <message>
        <source>computing...</source>
        <translation>wird berechnet …</translation>
    </message>
    <message>
        <source>unknown while the project has errors (Build &gt; Compile shows them)</source>
        <translation>unbekannt, solange das Projekt Fehler hat (Erstellen &gt; Kompilieren zeigt sie)</translation>
    </message>
    <message>
        <source>no change in behaviour since validation on %1</source>
        <translation>kein geändertes Verhalten seit der Validierung am %1</translation>
    </message>
    <message>
        <source>changed since validation on %1 in %2</source>
        <translation>geändert seit der Validierung am %1 in %2</translation>
    </message>
    <message numerus="yes">
        <source>%n network(s) added, changed or removed</source>
        <translation>
            <numerusform>%n Netzwerk hinzugefügt, geändert oder entfernt</numerusform>
            <numerusform>%n Netzwerke hinzugefügt, geändert oder entfernt</numerusform>
        </translation>
    </message>
    <message>
        <source>Protection:</source>
        <translation>Schutz:</translation>
    </message>
    <message>
        <source>changed outside Rungsmith after it was password protected (first at line %1): open read only</source>
        <translation>außerhalb von Rungsmith geändert, nachdem es mit einem Passwort geschützt wurde (zuerst in Zeile %1): schreibgeschützt geöffnet</translation>
    </message>
    <message>
        <source>none (File &gt; Password Protect)</source>
        <translation>keiner (Datei &gt; Passwortschutz)</translation>
    </message>
    <message>
        <source>only with the main password</source>
        <translation>nur mit dem Hauptpasswort</translation>
    </message>
    <message>
        <source>without a password</source>
        <translation>ohne Passwort</translation>
    </message>
    <message>
        <source>with their own password</source>
        <translation>mit ihrem eigenen Passwort</translation>
    </message>
    <message>
        <source>with full permission</source>
        <translation>mit voller Berechtigung</translation>
    </message>
    <message>
        <source>with permission to configure</source>
        <translation>mit Berechtigung zum Konfigurieren</translation>
    </message>
    <message>
        <source>read only</source>
        <translation>schreibgeschützt</translation>
    </message>
    <message>
        <source>The protection&apos;s public key: %1</source>
        <translation>Öffentlicher Schlüssel des Schutzes: %1</translation>
    </message>
    <message>
        <source>password protected, key %1 …
Config Options change %2; opened %3</source>
        <translation>passwortgeschützt, Schlüssel %1 …
Konfigurationsoptionen ändern sich %2; geöffnet %3</translation>
    </message>
</context>
<context>
    <name>rs::ui::ProjectTree</name>
    <message>
        <source>Projects</source>
        <translation>Projekte</translation>
    </message>
    <message>
        <source>Project Text</source>
        <translation>Projekttext</translation>
    </message>
    <message>
        <source>I/O Options</source>
        <translation>E/A-Optionen</translation>
    </message>
    <message>
        <source>Variables</source>
        <translation>Variablen</translation>
    </message>
    <message>
        <source>PLC Code</source>
        <translation>SPS-Code</translation>
    </message>
    <message>
        <source>Sequence %1</source>
        <translation>Sequenz %1</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>AS-i Options</source>
        <translation>AS-i-Optionen</translation>
    </message>
    <message>
        <source>Gateway %1 (%2)</source>
        <translation>Gateway %1 (%2)</translation>
    </message>
    <message>
        <source>Properties</source>
        <translation>Eigenschaften</translation>
    </message>
</context>
<context>
    <name>rs::ui::ProofResultsView</name>
    <message>
        <source>Line</source>
        <translation>Zeile</translation>
    </message>
    <message>
        <source>Property</source>
        <translation>Eigenschaft</translation>
    </message>
    <message>
        <source>Result</source>
        <translation>Ergebnis</translation>
    </message>
    <message>
        <source>Scans</source>
        <translation>Zyklen</translation>
    </message>
    <message>
        <source>Reason</source>
        <translation>Grund</translation>
    </message>
    <message>
        <source>proved</source>
        <translation>bewiesen</translation>
    </message>
    <message>
        <source>failed</source>
        <translation>verletzt</translation>
    </message>
    <message>
        <source>unknown</source>
        <translation>unbekannt</translation>
    </message>
    <message>
        <source>covered</source>
        <translation>erreicht</translation>
    </message>
    <message>
        <source>never covered</source>
        <translation>nie erreicht</translation>
    </message>
    <message>
        <source>waiting</source>
        <translation>wartet</translation>
    </message>
    <message>
        <source>proving…</source>
        <translation>wird bewiesen …</translation>
    </message>
    <message numerus="yes">
        <source>Proved by induction over %n scan(s)</source>
        <translation>
            <numerusform>Durch Induktion über %n Zyklus bewiesen</numerusform>
            <numerusform>Durch Induktion über %n Zyklen bewiesen</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>A counterexample of %n scan(s) from power on</source>
        <translation>
            <numerusform>Ein Gegenbeispiel von %n Zyklus ab dem Einschalten</numerusform>
            <numerusform>Ein Gegenbeispiel von %n Zyklen ab dem Einschalten</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Reached in %n scan(s) from power on</source>
        <translation>
            <numerusform>In %n Zyklus ab dem Einschalten erreicht</numerusform>
            <numerusform>In %n Zyklen ab dem Einschalten erreicht</numerusform>
        </translation>
    </message>
    <message>
        <source>Open Counterexample runs it in the simulator</source>
        <translation>Gegenbeispiel öffnen führt es im Simulator aus</translation>
    </message>
    <message>
        <source>not proved</source>
        <translation>nicht bewiesen</translation>
    </message>
</context>
<context>
    <name>rs::ui::ProofRun</name>
    <message>
        <source>The property has no counterexample to open.</source>
        <translation>Die Eigenschaft hat kein Gegenbeispiel zum Öffnen.</translation>
    </message>
    <message>
        <source>A scenario is running already.</source>
        <translation>Es läuft bereits ein Szenario.</translation>
    </message>
    <message>
        <source>cancelled</source>
        <translation>abgebrochen</translation>
    </message>
    <message numerus="yes">
        <source>the time limit of %n s per property ran out</source>
        <translation>
            <numerusform>die Zeitgrenze von %n s je Eigenschaft ist abgelaufen</numerusform>
            <numerusform>die Zeitgrenze von %n s je Eigenschaft ist abgelaufen</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>no counterexample within %n scans</source>
        <translation>
            <numerusform>kein Gegenbeispiel innerhalb von %n Zyklus</numerusform>
            <numerusform>kein Gegenbeispiel innerhalb von %n Zyklen</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>internal error: the prover&apos;s counterexample of %n scans does not replay (%1); please report it</source>
        <translation>
            <numerusform>interner Fehler: Das Gegenbeispiel des Beweisers von %n Zyklus lässt sich nicht nachspielen (%1); bitte melden Sie das</numerusform>
            <numerusform>interner Fehler: Das Gegenbeispiel des Beweisers von %n Zyklen lässt sich nicht nachspielen (%1); bitte melden Sie das</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>internal error: the prover&apos;s witness of %n scans does not replay (%1); please report it</source>
        <translation>
            <numerusform>interner Fehler: Der Zeuge des Beweisers von %n Zyklus lässt sich nicht nachspielen (%1); bitte melden Sie das</numerusform>
            <numerusform>interner Fehler: Der Zeuge des Beweisers von %n Zyklen lässt sich nicht nachspielen (%1); bitte melden Sie das</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>The project has %n error(s); compile it (F7) to see them.</source>
        <translation>
            <numerusform>Das Projekt hat %n Fehler; kompilieren Sie es (F7), um den Fehler zu sehen.</numerusform>
            <numerusform>Das Projekt hat %n Fehler; kompilieren Sie es (F7), um die Fehler zu sehen.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>rs::ui::PropertiesPage</name>
    <message>
        <source>; What must hold in every scan, for every input sequence: one property a line.
; Remove the &apos;;&apos; before a line to use it, with the operands of this project.
; always Q0.2 -&gt; I0.12                 ; the output only with the stop circuit closed
; never Q0.2 * Q0.3                    ; never both contactors at once
; always /I0.12 -&gt; within 20ms /Q0.2   ; the output drops within 20 ms of a stop
; always I0.0 -&gt; next Q0.2             ; the output follows the start in the next scan
; assume /(I0.0 * I0.1)                ; the two sensors are never made at once
; cover Q0.2                           ; the output can come on
</source>
        <translation>; Was in jedem Zyklus für jede Eingangsfolge gelten muss: eine Eigenschaft je Zeile.
; Entfernen Sie das &apos;;&apos; vor einer Zeile, um sie mit den Operanden dieses Projekts zu nutzen.
; always Q0.2 -&gt; I0.12                 ; der Ausgang nur bei geschlossenem Stoppkreis
; never Q0.2 * Q0.3                    ; nie beide Schütze zugleich
; always /I0.12 -&gt; within 20ms /Q0.2   ; der Ausgang fällt binnen 20 ms nach einem Stopp ab
; always I0.0 -&gt; next Q0.2             ; der Ausgang folgt dem Start im nächsten Zyklus
; assume /(I0.0 * I0.1)                ; die beiden Sensoren sind nie zugleich betätigt
; cover Q0.2                           ; der Ausgang kann einschalten
</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <source>Open Counterexample</source>
        <translation>Gegenbeispiel öffnen</translation>
    </message>
    <message>
        <source>Complete Word</source>
        <translation>Wort vervollständigen</translation>
    </message>
    <message>
        <source>Insert Example</source>
        <translation>Beispiel einfügen</translation>
    </message>
    <message>
        <source>Stop proving; the properties proved so far keep their results</source>
        <translation>Das Beweisen anhalten; die bisher bewiesenen Eigenschaften behalten ihre Ergebnisse</translation>
    </message>
    <message>
        <source>Run the chosen property&apos;s counterexample (or witness) in the simulator, with the waveform, stopped at its last scan</source>
        <translation>Das Gegenbeispiel (oder den Zeugen) der gewählten Eigenschaft im Simulator ausführen, mit Signalverlauf, angehalten nach seinem letzten Zyklus</translation>
    </message>
    <message>
        <source>&lt;p&gt;No properties yet. Write one a line, with conditions as in the code (operands, names, &lt;code&gt;/&lt;/code&gt;, &lt;code&gt;*&lt;/code&gt;, &lt;code&gt;+&lt;/code&gt;, parentheses):&lt;/p&gt;&lt;p&gt;&lt;code&gt;always A&lt;/code&gt;, &lt;code&gt;never A&lt;/code&gt;, &lt;code&gt;always A -&amp;gt; B&lt;/code&gt;, &lt;code&gt;always A -&amp;gt; within 20ms B&lt;/code&gt;, &lt;code&gt;always A -&amp;gt; next B&lt;/code&gt;, &lt;code&gt;assume A&lt;/code&gt;, &lt;code&gt;cover A&lt;/code&gt;.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Prove All&lt;/b&gt; proves each for every input sequence, or finds one that breaks it and opens it in the simulator.&lt;/p&gt;</source>
        <translation>&lt;p&gt;Noch keine Eigenschaften. Schreiben Sie eine je Zeile, mit Bedingungen wie im Code (Operanden, Namen, &lt;code&gt;/&lt;/code&gt;, &lt;code&gt;*&lt;/code&gt;, &lt;code&gt;+&lt;/code&gt;, Klammern):&lt;/p&gt;&lt;p&gt;&lt;code&gt;always A&lt;/code&gt;, &lt;code&gt;never A&lt;/code&gt;, &lt;code&gt;always A -&amp;gt; B&lt;/code&gt;, &lt;code&gt;always A -&amp;gt; within 20ms B&lt;/code&gt;, &lt;code&gt;always A -&amp;gt; next B&lt;/code&gt;, &lt;code&gt;assume A&lt;/code&gt;, &lt;code&gt;cover A&lt;/code&gt;.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Alle beweisen&lt;/b&gt; beweist jede für jede Eingangsfolge oder findet eine Folge, die sie verletzt, und öffnet sie im Simulator.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>Put a commented example of every kind of line in the text</source>
        <translation>Ein auskommentiertes Beispiel jeder Zeilenart in den Text einfügen</translation>
    </message>
    <message>
        <source>%1 — Properties</source>
        <translation>%1 — Eigenschaften</translation>
    </message>
    <message>
        <source>Saved with the project, beside its file, once it has one: its name with the extension .prop.</source>
        <translation>Wird mit dem Projekt gespeichert, neben seiner Datei, sobald es eine hat: ihr Name mit der Endung .prop.</translation>
    </message>
    <message>
        <source>Saved with the project as %1, which rungsmith-cli prove takes too.</source>
        <translation>Wird mit dem Projekt als %1 gespeichert, die auch rungsmith-cli prove liest.</translation>
    </message>
    <message numerus="yes">
        <source>The properties have %n error(s), marked in the text: nothing is proved until they read.</source>
        <translation>
            <numerusform>Die Eigenschaften haben %n Fehler, im Text markiert: Nichts wird bewiesen, bis sie sich lesen lassen.</numerusform>
            <numerusform>Die Eigenschaften haben %n Fehler, im Text markiert: Nichts wird bewiesen, bis sie sich lesen lassen.</numerusform>
        </translation>
    </message>
    <message>
        <source>Write a property first: there is nothing to prove.</source>
        <translation>Schreiben Sie zuerst eine Eigenschaft: Es gibt nichts zu beweisen.</translation>
    </message>
    <message>
        <source>Compiling %1...</source>
        <translation>%1 wird kompiliert …</translation>
    </message>
    <message>
        <source>Property %1 of %2</source>
        <translation>Eigenschaft %1 von %2</translation>
    </message>
    <message>
        <source>Proving property %1 of %2...</source>
        <translation>Eigenschaft %1 von %2 wird bewiesen …</translation>
    </message>
    <message>
        <source>cancelled</source>
        <translation>abgebrochen</translation>
    </message>
    <message>
        <source>%1 proved, %2 failed, %3 unknown</source>
        <translation>%1 bewiesen, %2 verletzt, %3 unbekannt</translation>
    </message>
    <message>
        <source>Cancelled: %1.</source>
        <translation>Abgebrochen: %1.</translation>
    </message>
    <message>
        <source>The properties or the project changed since this proof; Prove All again for results of the text as it is now.</source>
        <translation>Die Eigenschaften oder das Projekt haben sich seit diesem Beweis geändert; wählen Sie erneut Alle beweisen, um Ergebnisse für den aktuellen Text zu erhalten.</translation>
    </message>
    <message>
        <source>Open Witness</source>
        <translation>Zeugen öffnen</translation>
    </message>
</context>
<context>
    <name>rs::ui::ProtectedOpenDialog</name>
    <message>
        <source>Open with &amp;full permission</source>
        <translation>Mit &amp;voller Berechtigung öffnen</translation>
    </message>
    <message>
        <source>Open with permission to &amp;configure</source>
        <translation>Mit Berechtigung zum &amp;Konfigurieren öffnen</translation>
    </message>
    <message>
        <source>Open in &amp;read only mode</source>
        <translation>&amp;Schreibgeschützt öffnen</translation>
    </message>
    <message>
        <source>Open Protected Project</source>
        <translation>Geschütztes Projekt öffnen</translation>
    </message>
    <message>
        <source>“%1” is password protected. It opens without a password, but then nothing in it can change.</source>
        <translation>„%1“ ist mit einem Passwort geschützt. Es lässt sich ohne Passwort öffnen, aber dann kann sich nichts darin ändern.</translation>
    </message>
    <message>
        <source>Takes the main password; everything can change.</source>
        <translation>Erfordert das Hauptpasswort; alles kann sich ändern.</translation>
    </message>
    <message>
        <source>Takes no password; only the Config Options can change.</source>
        <translation>Erfordert kein Passwort; nur die Konfigurationsoptionen können sich ändern.</translation>
    </message>
    <message>
        <source>Takes the config options password, or the main one; only the Config Options can change.</source>
        <translation>Erfordert das Passwort für die Konfigurationsoptionen oder das Hauptpasswort; nur die Konfigurationsoptionen können sich ändern.</translation>
    </message>
    <message>
        <source>Takes no password; nothing can change.</source>
        <translation>Erfordert kein Passwort; nichts kann sich ändern.</translation>
    </message>
    <message>
        <source>&amp;Password:</source>
        <translation>&amp;Passwort:</translation>
    </message>
    <message>
        <source>The password does not open the project with this permission.</source>
        <translation>Das Passwort öffnet das Projekt nicht mit dieser Berechtigung.</translation>
    </message>
    <message numerus="yes">
        <source>The password does not open the project with this permission. Try again in %n second(s).</source>
        <translation>
            <numerusform>Das Passwort öffnet das Projekt nicht mit dieser Berechtigung. Versuchen Sie es in %n Sekunde erneut.</numerusform>
            <numerusform>Das Passwort öffnet das Projekt nicht mit dieser Berechtigung. Versuchen Sie es in %n Sekunden erneut.</numerusform>
        </translation>
    </message>
    <message>
        <source>Accept the Change</source>
        <translation>Änderung annehmen</translation>
    </message>
</context>
<context>
    <name>rs::ui::RemanentDialog</name>
    <message>
        <source>Remanent Variables of Pluto %1</source>
        <translation>Remanente Variablen von Pluto %1</translation>
    </message>
    <message>
        <source>Remanent variables keep their value when the power is off. Registers R100-R131 and memories M100-M131 can be remanent in any combination, except that with all the registers no memory can be.</source>
        <translation>Remanente Variablen behalten ihren Wert bei ausgeschalteter Versorgung. Register R100-R131 und Merker M100-M131 können in beliebiger Kombination remanent sein, nur kann mit allen Registern kein Merker remanent sein.</translation>
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
        <source>Registers</source>
        <translation>Register</translation>
    </message>
    <message>
        <source>Memories</source>
        <translation>Merker</translation>
    </message>
    <message>
        <source>All 32 registers are remanent, so no memory can be.</source>
        <translation>Alle 32 Register sind remanent, deshalb kann kein Merker remanent sein.</translation>
    </message>
</context>
<context>
    <name>rs::ui::ScenarioFileViewer</name>
    <message>
        <source>&amp;Open in Editor</source>
        <translation>Im Editor ö&amp;ffnen</translation>
    </message>
    <message>
        <source>%1 (read-only)</source>
        <translation>%1 (schreibgeschützt)</translation>
    </message>
    <message>
        <source>%1, line %2</source>
        <translation>%1, Zeile %2</translation>
    </message>
</context>
<context>
    <name>rs::ui::ScenarioResultsView</name>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>%1: %2 passed, %3 failed</source>
        <translation>%1: %2 bestanden, %3 fehlgeschlagen</translation>
    </message>
    <message>
        <source>Double-click to show line %1 of %2</source>
        <translation>Doppelklicken, um Zeile %1 von %2 zu zeigen</translation>
    </message>
    <message>
        <source>%1: cancelled at t = %2 s, %3 passed, %4 failed so far</source>
        <translation>%1: abgebrochen bei t = %2 s, bis dahin %3 bestanden, %4 fehlgeschlagen</translation>
    </message>
</context>
<context>
    <name>rs::ui::SignatureLabel</name>
    <message>
        <source>Changes exactly when what the program does changes; formatting, comments, names and descriptions leave it as it is</source>
        <translation>Ändert sich genau dann, wenn sich ändert, was das Programm tut; Formatierung, Kommentare, Namen und Beschreibungen lassen sie, wie sie ist</translation>
    </message>
    <message>
        <source>computing...</source>
        <translation>wird berechnet …</translation>
    </message>
    <message>
        <source>none while the project has errors (Build &gt; Compile shows them)</source>
        <translation>keine, solange das Projekt Fehler hat (Erstellen &gt; Kompilieren zeigt sie)</translation>
    </message>
</context>
<context>
    <name>rs::ui::SimulationControls</name>
    <message>
        <source>t = %1 s  (%2 scans)</source>
        <translation>t = %1 s  (%2 Zyklen)</translation>
    </message>
    <message>
        <source>&amp;Simulate</source>
        <translation>&amp;Simulieren</translation>
    </message>
    <message>
        <source>Simulate</source>
        <translation>Simulieren</translation>
    </message>
    <message>
        <source>Si&amp;mulation Mode</source>
        <translation>Si&amp;mulationsmodus</translation>
    </message>
    <message>
        <source>Run the project in the simulator and show its live state; editing ends it</source>
        <translation>Das Projekt im Simulator ausführen und seinen aktuellen Zustand zeigen; Bearbeiten beendet die Simulation</translation>
    </message>
    <message>
        <source>&amp;Start</source>
        <translation>&amp;Starten</translation>
    </message>
    <message>
        <source>Run the program on the simulated clock</source>
        <translation>Das Programm mit der simulierten Uhr ausführen</translation>
    </message>
    <message>
        <source>S&amp;top</source>
        <translation>&amp;Anhalten</translation>
    </message>
    <message>
        <source>Hold the program and the clock; the state stays shown</source>
        <translation>Programm und Uhr anhalten; der Zustand bleibt sichtbar</translation>
    </message>
    <message>
        <source>Single S&amp;can</source>
        <translation>&amp;Einzelzyklus</translation>
    </message>
    <message>
        <source>Run one scan of every unit</source>
        <translation>Einen Zyklus jeder Einheit ausführen</translation>
    </message>
    <message>
        <source>&amp;Reset</source>
        <translation>&amp;Zurücksetzen</translation>
    </message>
    <message>
        <source>Power on again at time 0; forces stay</source>
        <translation>Erneut einschalten bei Zeit 0; Forcewerte bleiben erhalten</translation>
    </message>
    <message>
        <source>Run Sce&amp;nario...</source>
        <translation>Sze&amp;nario ausführen …</translation>
    </message>
    <message>
        <source>Run a scenario file (.scn) and list its results</source>
        <translation>Eine Szenariodatei (.scn) ausführen und ihre Ergebnisse auflisten</translation>
    </message>
    <message>
        <source>Real time</source>
        <translation>Echtzeit</translation>
    </message>
    <message>
        <source>10x</source>
        <translation>10x</translation>
    </message>
    <message>
        <source>As fast as possible</source>
        <translation>So schnell wie möglich</translation>
    </message>
    <message>
        <source>How fast the simulated clock runs</source>
        <translation>Wie schnell die simulierte Uhr läuft</translation>
    </message>
    <message>
        <source>The simulated clock</source>
        <translation>Die simulierte Uhr</translation>
    </message>
    <message>
        <source>S&amp;peed</source>
        <translation>&amp;Geschwindigkeit</translation>
    </message>
    <message>
        <source>Not simulating</source>
        <translation>Keine Simulation</translation>
    </message>
</context>
<context>
    <name>rs::ui::SimulationMode</name>
    <message>
        <source>Forces</source>
        <translation>Forcewerte</translation>
    </message>
    <message>
        <source>Watch</source>
        <translation>Beobachtung</translation>
    </message>
    <message>
        <source>Waveform</source>
        <translation>Signalverlauf</translation>
    </message>
    <message>
        <source>Bus Status</source>
        <translation>Busstatus</translation>
    </message>
    <message>
        <source>Scenarios</source>
        <translation>Szenarien</translation>
    </message>
    <message>
        <source>Simulation</source>
        <translation>Simulation</translation>
    </message>
    <message>
        <source>Run Scenario</source>
        <translation>Szenario ausführen</translation>
    </message>
    <message>
        <source>Scenarios (*.scn);;All files (*)</source>
        <translation>Szenarien (*.scn);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Simulating %1. Editing the project ends the simulation.</source>
        <translation>%1 wird simuliert. Bearbeiten des Projekts beendet die Simulation.</translation>
    </message>
    <message>
        <source>%1 is not an input: right-click it to force it.</source>
        <translation>%1 ist kein Eingang: Klicken Sie mit der rechten Maustaste darauf, um ihn zu forcen.</translation>
    </message>
    <message>
        <source>Force %1 to &amp;0</source>
        <translation>%1 auf &amp;0 forcen</translation>
    </message>
    <message>
        <source>Force %1 to &amp;1</source>
        <translation>%1 auf &amp;1 forcen</translation>
    </message>
    <message>
        <source>Force %1 to a &amp;Value...</source>
        <translation>%1 auf einen &amp;Wert forcen …</translation>
    </message>
    <message>
        <source>Force</source>
        <translation>Forcen</translation>
    </message>
    <message>
        <source>Value of %1:</source>
        <translation>Wert von %1:</translation>
    </message>
    <message>
        <source>&amp;Release %1</source>
        <translation>Forcen von %1 &amp;aufheben</translation>
    </message>
    <message>
        <source>&amp;Watch %1</source>
        <translation>%1 &amp;beobachten</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <source>Stop the scenario; the simulation shows where it got</source>
        <translation>Das Szenario anhalten; die Simulation zeigt, wie weit es kam</translation>
    </message>
    <message>
        <source>Scenario: %1 of %2 s</source>
        <translation>Szenario: %1 von %2 s</translation>
    </message>
    <message>
        <source>A scenario is running already.</source>
        <translation>Es läuft bereits ein Szenario.</translation>
    </message>
    <message>
        <source>Scenario %1 cancelled at t = %2 s.</source>
        <translation>Szenario %1 bei t = %2 s abgebrochen.</translation>
    </message>
    <message>
        <source>Serve &amp;Modbus TCP</source>
        <translation>&amp;Modbus TCP bedienen</translation>
    </message>
    <message>
        <source>Gateways</source>
        <translation>Gateways</translation>
    </message>
    <message>
        <source>Answer Modbus TCP clients for the project&apos;s Ethernet gateway while simulating, at the address the preferences give</source>
        <translation>Während der Simulation Modbus-TCP-Clients für das Ethernet-Gateway des Projekts antworten, an der Adresse aus den Einstellungen</translation>
    </message>
    <message>
        <source>Serve Modbus TCP</source>
        <translation>Modbus TCP bedienen</translation>
    </message>
    <message>
        <source>Cannot serve Modbus TCP on %1:%2: %3. Choose another address or port in the preferences.</source>
        <translation>Modbus TCP kann auf %1:%2 nicht bedient werden: %3. Wählen Sie in den Einstellungen eine andere Adresse oder einen anderen Port.</translation>
    </message>
    <message>
        <source>Serving Modbus TCP on %1.</source>
        <translation>Modbus TCP wird auf %1 bedient.</translation>
    </message>
</context>
<context>
    <name>rs::ui::SimulationSession</name>
    <message>
        <source>No project is open.</source>
        <translation>Kein Projekt ist geöffnet.</translation>
    </message>
    <message>
        <source>The project&apos;s text has errors; fix them before simulating.</source>
        <translation>Der Text des Projekts hat Fehler; beheben Sie sie vor dem Simulieren.</translation>
    </message>
    <message numerus="yes">
        <source>The project has %n error(s); compile it (F7) to see them.</source>
        <translation>
            <numerusform>Das Projekt hat %n Fehler; kompilieren Sie es (F7), um den Fehler zu sehen.</numerusform>
            <numerusform>Das Projekt hat %n Fehler; kompilieren Sie es (F7), um die Fehler zu sehen.</numerusform>
        </translation>
    </message>
    <message>
        <source>The project has no Pluto to simulate.</source>
        <translation>Das Projekt hat keinen Pluto zum Simulieren.</translation>
    </message>
    <message>
        <source>The project changed, so the simulation ended. Start it again to simulate the new version.</source>
        <translation>Das Projekt hat sich geändert, deshalb wurde die Simulation beendet. Starten Sie sie erneut, um die neue Version zu simulieren.</translation>
    </message>
    <message>
        <source>The project was closed, so the simulation ended.</source>
        <translation>Das Projekt wurde geschlossen, deshalb wurde die Simulation beendet.</translation>
    </message>
    <message>
        <source>The simulation is not running.</source>
        <translation>Die Simulation läuft nicht.</translation>
    </message>
    <message>
        <source>A scenario is running already.</source>
        <translation>Es läuft bereits ein Szenario.</translation>
    </message>
</context>
<context>
    <name>rs::ui::TextPage</name>
    <message>
        <source>%1 — Project Text</source>
        <translation>%1 — Projekttext</translation>
    </message>
    <message>
        <source>This file has errors, so it is shown as text until they are fixed. Lines with errors could not be shown on the other pages.</source>
        <translation>Diese Datei hat Fehler und wird deshalb als Text gezeigt, bis sie behoben sind. Zeilen mit Fehlern ließen sich auf den anderen Seiten nicht zeigen.</translation>
    </message>
    <message>
        <source>%1 — PLC Code</source>
        <translation>%1 — SPS-Code</translation>
    </message>
    <message>
        <source>Edit Code of Pluto %1</source>
        <translation>Code von Pluto %1 bearbeiten</translation>
    </message>
    <message>
        <source>Ladder</source>
        <translation>Kontaktplan</translation>
    </message>
    <message>
        <source>Show this code as ladder networks</source>
        <translation>Diesen Code als Kontaktplan-Netzwerke zeigen</translation>
    </message>
</context>
<context>
    <name>rs::ui::UnitCommands</name>
    <message>
        <source>New &amp;Pluto...</source>
        <translation>Neuer &amp;Pluto …</translation>
    </message>
    <message>
        <source>Add a Pluto unit to the project</source>
        <translation>Dem Projekt eine Pluto-Einheit hinzufügen</translation>
    </message>
    <message>
        <source>New &amp;Sequence...</source>
        <translation>Neue &amp;Sequenz …</translation>
    </message>
    <message>
        <source>&amp;Remove Pluto...</source>
        <translation>Pluto &amp;entfernen …</translation>
    </message>
    <message>
        <source>Re&amp;manent Variables...</source>
        <translation>Re&amp;manente Variablen …</translation>
    </message>
    <message>
        <source>&amp;Import Variable Names (CSV)...</source>
        <translation>Variablennamen &amp;importieren (CSV) …</translation>
    </message>
    <message>
        <source>E&amp;xport Variable Names (CSV)...</source>
        <translation>Variablennamen e&amp;xportieren (CSV) …</translation>
    </message>
    <message>
        <source>New Pluto</source>
        <translation>Neuer Pluto</translation>
    </message>
    <message>
        <source>The project has 32 units, the most a bus can have.</source>
        <translation>Das Projekt hat 32 Einheiten, die höchste Zahl, die ein Bus haben kann.</translation>
    </message>
    <message>
        <source>New Pluto %1</source>
        <translation>Neuer Pluto %1</translation>
    </message>
    <message>
        <source>New Sequence</source>
        <translation>Neue Sequenz</translation>
    </message>
    <message>
        <source>Pluto %1 has all nine sequences.</source>
        <translation>Pluto %1 hat alle neun Sequenzen.</translation>
    </message>
    <message>
        <source>Sequence number for Pluto %1 (1-9):</source>
        <translation>Sequenznummer für Pluto %1 (1-9):</translation>
    </message>
    <message>
        <source>New Sequence %1 of Pluto %2</source>
        <translation>Neue Sequenz %1 von Pluto %2</translation>
    </message>
    <message>
        <source>Remove Pluto</source>
        <translation>Pluto entfernen</translation>
    </message>
    <message>
        <source>Remove %1 with its code, names and descriptions from the project? Edit &gt; Undo brings it back.</source>
        <translation>%1 mit Code, Namen und Beschreibungen aus dem Projekt entfernen? Bearbeiten &gt; Rückgängig holt die Einheit zurück.</translation>
    </message>
    <message>
        <source>Remove Pluto %1</source>
        <translation>Pluto %1 entfernen</translation>
    </message>
    <message>
        <source>Set Remanent Variables of Pluto %1</source>
        <translation>Remanente Variablen von Pluto %1 setzen</translation>
    </message>
    <message>
        <source>Remanent Variables</source>
        <translation>Remanente Variablen</translation>
    </message>
    <message>
        <source>Import Variable Names to Pluto %1</source>
        <translation>Variablennamen in Pluto %1 importieren</translation>
    </message>
    <message numerus="yes">
        <source>Imported %n variable(s).</source>
        <translation>
            <numerusform>%n Variable importiert.</numerusform>
            <numerusform>%n Variablen importiert.</numerusform>
        </translation>
    </message>
    <message>
        <source>Export Variable Names</source>
        <translation>Variablennamen exportieren</translation>
    </message>
    <message>
        <source>Wrote %1</source>
        <translation>%1 geschrieben</translation>
    </message>
</context>
<context>
    <name>rs::ui::UnitPage</name>
    <message>
        <source>&amp;Remanent Variables...</source>
        <translation>&amp;Remanente Variablen …</translation>
    </message>
    <message>
        <source>This unit has code but no &apos;! id_pluto&apos; declaration. Any change below writes one.</source>
        <translation>Diese Einheit hat Code, aber keine &apos;! id_pluto&apos;-Deklaration. Jede Änderung unten schreibt eine.</translation>
    </message>
    <message>
        <source>Variables on the bus and at power off</source>
        <translation>Variablen auf dem Bus und bei ausgeschalteter Versorgung</translation>
    </message>
    <message>
        <source>Export variables:</source>
        <translation>Exportvariablen:</translation>
    </message>
    <message>
        <source>Remanent variables:</source>
        <translation>Remanente Variablen:</translation>
    </message>
    <message>
        <source>Station %1 of project %2</source>
        <translation>Station %1 von Projekt %2</translation>
    </message>
    <message>
        <source>need instruction set 3</source>
        <translation>benötigen Befehlssatz 3</translation>
    </message>
    <message>
        <source>%1 of %2 extra telegram pairs (project: %3 of %4)</source>
        <translation>%1 von %2 zusätzlichen Telegrammpaaren (Projekt: %3 von %4)</translation>
    </message>
    <message>
        <source>this type has none</source>
        <translation>dieser Typ hat keine</translation>
    </message>
    <message>
        <source>none</source>
        <translation>keine</translation>
    </message>
    <message>
        <source>Change Pluto %1</source>
        <translation>Pluto %1 ändern</translation>
    </message>
    <message numerus="yes">
        <source>This removes %n declaration(s), name(s), description(s) or attribute(s) of the unit that the new type or instruction set cannot have. Change it?</source>
        <translation>
            <numerusform>Dadurch wird %n Deklaration, Name, Beschreibung oder Attribut der Einheit entfernt, die der neue Typ oder Befehlssatz nicht haben kann. Ändern?</numerusform>
            <numerusform>Dadurch werden %n Deklarationen, Namen, Beschreibungen oder Attribute der Einheit entfernt, die der neue Typ oder Befehlssatz nicht haben kann. Ändern?</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 of %2</source>
        <translation>%1 von %2</translation>
    </message>
    <message>
        <source>%1 of %2 (%3 of them by block instances)</source>
        <translation>%1 von %2 (davon %3 durch Bausteininstanzen)</translation>
    </message>
    <message>
        <source>Resources in use</source>
        <translation>Belegte Ressourcen</translation>
    </message>
    <message>
        <source>Timers:</source>
        <translation>Timer:</translation>
    </message>
    <message>
        <source>Memories:</source>
        <translation>Merker:</translation>
    </message>
    <message>
        <source>Registers:</source>
        <translation>Register:</translation>
    </message>
    <message>
        <source>Program signature:</source>
        <translation>Programmsignatur:</translation>
    </message>
    <message>
        <source>Review</source>
        <translation>Prüfung</translation>
    </message>
    <message>
        <source>&amp;Advanced Settings...</source>
        <translation>&amp;Erweiterte Einstellungen...</translation>
    </message>
    <message>
        <source>CAN bus cycle time:</source>
        <translation>CAN-Bus-Zykluszeit:</translation>
    </message>
    <message>
        <source>%1 ms</source>
        <translation>%1 ms</translation>
    </message>
    <message>
        <source>the unit&apos;s default</source>
        <translation>Vorgabe der Einheit</translation>
    </message>
    <message>
        <source>Set CAN Bus Cycle Time of Pluto %1</source>
        <translation>CAN-Bus-Zykluszeit von Pluto %1 setzen</translation>
    </message>
    <message>
        <source>E&amp;xternal Communication...</source>
        <translation>E&amp;xterne Kommunikation...</translation>
    </message>
    <message>
        <source>Gateway data received:</source>
        <translation>Empfangene Gateway-Daten:</translation>
    </message>
    <message>
        <source>block %1 from gateway %2, packet %3</source>
        <translation>Block %1 von Gateway %2, Paket %3</translation>
    </message>
    <message>
        <source>Set External Communication of Pluto %1</source>
        <translation>Externe Kommunikation von Pluto %1 setzen</translation>
    </message>
</context>
<context>
    <name>rs::ui::UnitSettingsForm</name>
    <message>
        <source>Instruction set &amp;2</source>
        <translation>Befehlssatz &amp;2</translation>
    </message>
    <message>
        <source>Instruction set &amp;3</source>
        <translation>Befehlssatz &amp;3</translation>
    </message>
    <message>
        <source>Instruction set 3 needs Pluto OS 3.0 or later. It adds the off-delay timer, multiplication and division with constants, double registers (32 bits), &quot;not positive edge&quot; and &quot;not negative edge&quot;, register bits and a larger address range.</source>
        <translation>Befehlssatz 3 benötigt Pluto OS 3.0 oder neuer. Er bringt den ausschaltverzögerten Timer, Multiplikation und Division mit Konstanten, Doppelregister (32 Bit), &quot;nicht positive Flanke&quot; und &quot;nicht negative Flanke&quot;, Registerbits und einen größeren Adressbereich.</translation>
    </message>
    <message>
        <source>IDFIX number</source>
        <translation>IDFIX-Nummer</translation>
    </message>
    <message>
        <source>No IDFIX</source>
        <translation>Kein IDFIX</translation>
    </message>
    <message>
        <source>12 hexadecimal digits, e.g. 000034AD4AE1</source>
        <translation>12 Hexadezimalziffern, z. B. 000034AD4AE1</translation>
    </message>
    <message>
        <source>For your own notes; not downloaded to the unit</source>
        <translation>Für Ihre eigenen Notizen; wird nicht in die Einheit geladen</translation>
    </message>
    <message>
        <source>&amp;Station number:</source>
        <translation>&amp;Stationsnummer:</translation>
    </message>
    <message>
        <source>Pluto &amp;type:</source>
        <translation>Pluto-&amp;Typ:</translation>
    </message>
    <message>
        <source>Instruction set:</source>
        <translation>Befehlssatz:</translation>
    </message>
    <message>
        <source>&amp;IDFIX:</source>
        <translation>&amp;IDFIX:</translation>
    </message>
    <message>
        <source>&amp;Description:</source>
        <translation>&amp;Beschreibung:</translation>
    </message>
    <message numerus="yes">
        <source>The IDFIX number has %n of its 12 hexadecimal digits. Choose &quot;No IDFIX&quot; if the unit has no identifier circuit.</source>
        <translation>
            <numerusform>Die IDFIX-Nummer hat %n von 12 Hexadezimalziffern. Wählen Sie &quot;Kein IDFIX&quot;, wenn die Einheit keinen Kennungsbaustein hat.</numerusform>
            <numerusform>Die IDFIX-Nummer hat %n von 12 Hexadezimalziffern. Wählen Sie &quot;Kein IDFIX&quot;, wenn die Einheit keinen Kennungsbaustein hat.</numerusform>
        </translation>
    </message>
    <message>
        <source>The %1 runs instruction set 2 only.</source>
        <translation>%1 kann nur Befehlssatz 2.</translation>
    </message>
    <message>
        <source>IDFIX-PROG</source>
        <translation>IDFIX-PROG</translation>
    </message>
    <message>
        <source>A programmable identifier circuit: the number given here is the one written to it (Write IDFIX, on the unit).</source>
        <translation>Ein programmierbarer Identifikationsbaustein: Die hier angegebene Nummer wird in ihn geschrieben (IDFIX schreiben, an der Einheit).</translation>
    </message>
</context>
<context>
    <name>rs::ui::VariableTableModel</name>
    <message>
        <source>Safety Inputs</source>
        <translation>Sicherheitseingänge</translation>
    </message>
    <message>
        <source>Safety Outputs</source>
        <translation>Sicherheitsausgänge</translation>
    </message>
    <message>
        <source>NonSafety Outputs</source>
        <translation>Nicht sichere Ausgänge</translation>
    </message>
    <message>
        <source>Global Memories</source>
        <translation>Globale Merker</translation>
    </message>
    <message>
        <source>Memories</source>
        <translation>Merker</translation>
    </message>
    <message>
        <source>Registers</source>
        <translation>Register</translation>
    </message>
    <message>
        <source>Double Registers</source>
        <translation>Doppelregister</translation>
    </message>
    <message>
        <source>System Memories</source>
        <translation>Systemmerker</translation>
    </message>
    <message>
        <source>System Registers</source>
        <translation>Systemregister</translation>
    </message>
    <message>
        <source>AS-i Slaves</source>
        <translation>AS-i-Slaves</translation>
    </message>
    <message>
        <source>Used in the code of the unit</source>
        <translation>Im Code der Einheit verwendet</translation>
    </message>
    <message>
        <source>[G] Global variable: visible to the other Plutos on the bus.</source>
        <translation>[G] Globale Variable: für die anderen Plutos am Bus sichtbar.</translation>
    </message>
    <message>
        <source>[E] Exported variable: made visible to the other Plutos on the bus.</source>
        <translation>[E] Exportierte Variable: für die anderen Plutos am Bus sichtbar gemacht.</translation>
    </message>
    <message>
        <source>[R] Remanent variable: keeps its value when the power is off.</source>
        <translation>[R] Remanente Variable: behält ihren Wert bei ausgeschalteter Versorgung.</translation>
    </message>
    <message>
        <source>The manuals&apos; name of this system variable</source>
        <translation>Der Name dieser Systemvariablen in den Handbüchern</translation>
    </message>
    <message>
        <source>Status</source>
        <translation>Status</translation>
    </message>
    <message>
        <source>Variable</source>
        <translation>Variable</translation>
    </message>
    <message>
        <source>Attributes</source>
        <translation>Attribute</translation>
    </message>
    <message>
        <source>Symbolic Name</source>
        <translation>Symbolischer Name</translation>
    </message>
    <message>
        <source>Description</source>
        <translation>Beschreibung</translation>
    </message>
    <message>
        <source>Remove Name of %1</source>
        <translation>Namen von %1 entfernen</translation>
    </message>
    <message>
        <source>Name %1 %2</source>
        <translation>%1 %2 nennen</translation>
    </message>
    <message>
        <source>Describe %1</source>
        <translation>%1 beschreiben</translation>
    </message>
    <message>
        <source>%1 F</source>
        <comment>a forced value</comment>
        <translation>%1 F</translation>
    </message>
    <message>
        <source>Forced to %1 in the simulation; release it in the Forces list.</source>
        <translation>In der Simulation auf %1 geforct; heben Sie das Forcen in der Liste Forcewerte auf.</translation>
    </message>
    <message>
        <source>The value after the last scan of the simulation</source>
        <translation>Der Wert nach dem letzten Zyklus der Simulation</translation>
    </message>
    <message>
        <source>used</source>
        <comment>a variable the code reads or writes</comment>
        <translation>verwendet</translation>
    </message>
</context>
<context>
    <name>rs::ui::VariablesPage</name>
    <message>
        <source>Filter by variable, name or description</source>
        <translation>Nach Variable, Name oder Beschreibung filtern</translation>
    </message>
    <message>
        <source>Variable attributes: [G] global, visible to the other Plutos on the bus; [E] exported; [R] remanent, kept at power off.</source>
        <translation>Variablenattribute: [G] global, für die anderen Plutos am Bus sichtbar; [E] exportiert; [R] remanent, bleibt bei ausgeschalteter Versorgung erhalten.</translation>
    </message>
    <message>
        <source>&amp;Remanent Variables...</source>
        <translation>&amp;Remanente Variablen …</translation>
    </message>
    <message>
        <source>&amp;Import CSV...</source>
        <translation>CSV &amp;importieren …</translation>
    </message>
    <message>
        <source>E&amp;xport CSV...</source>
        <translation>CSV e&amp;xportieren …</translation>
    </message>
    <message>
        <source>%1 — Variables</source>
        <translation>%1 — Variablen</translation>
    </message>
    <message>
        <source>Export variables need instruction set 3.</source>
        <translation>Exportvariablen benötigen Befehlssatz 3.</translation>
    </message>
    <message>
        <source>Export variables: %1 of %2 extra telegram pairs (project: %3 of %4)</source>
        <translation>Exportvariablen: %1 von %2 zusätzlichen Telegrammpaaren (Projekt: %3 von %4)</translation>
    </message>
    <message>
        <source>Export %1</source>
        <translation>%1 exportieren</translation>
    </message>
    <message>
        <source>Stop Exporting %1</source>
        <translation>%1 nicht mehr exportieren</translation>
    </message>
    <message>
        <source>&amp;Export Variable [E]</source>
        <translation>Variable &amp;exportieren [E]</translation>
    </message>
    <message>
        <source>&amp;Import Variable Names from CSV...</source>
        <translation>Variablennamen aus CSV &amp;importieren …</translation>
    </message>
    <message>
        <source>E&amp;xport Variable Names to CSV...</source>
        <translation>Variablennamen in CSV e&amp;xportieren …</translation>
    </message>
</context>
<context>
    <name>rs::ui::WatchView</name>
    <message>
        <source>Symbolic name or address, e.g. Q0.2</source>
        <translation>Symbolischer Name oder Adresse, z. B. Q0.2</translation>
    </message>
    <message>
        <source>&amp;Watch</source>
        <translation>&amp;Beobachten</translation>
    </message>
    <message>
        <source>Variable</source>
        <translation>Variable</translation>
    </message>
    <message>
        <source>Symbolic Name</source>
        <translation>Symbolischer Name</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>Wert</translation>
    </message>
    <message>
        <source>Type a value to set an input or force any other variable</source>
        <translation>Geben Sie einen Wert ein, um einen Eingang zu setzen oder eine andere Variable zu forcen</translation>
    </message>
    <message>
        <source>Type a symbolic name or an address.</source>
        <translation>Geben Sie einen symbolischen Namen oder eine Adresse ein.</translation>
    </message>
    <message>
        <source>%1 F</source>
        <comment>a forced value</comment>
        <translation>%1 F</translation>
    </message>
    <message>
        <source>Forced</source>
        <translation>Geforct</translation>
    </message>
    <message>
        <source>“%1” is not a number.</source>
        <translation>„%1“ ist keine Zahl.</translation>
    </message>
    <message>
        <source>&amp;Release Force</source>
        <translation>Forcen &amp;aufheben</translation>
    </message>
    <message>
        <source>Stop &amp;Watching</source>
        <translation>&amp;Nicht mehr beobachten</translation>
    </message>
    <message>
        <source>A channel is open (0) or closed (1).</source>
        <translation>Ein Kanal ist offen (0) oder geschlossen (1).</translation>
    </message>
</context>
<context>
    <name>rs::ui::WaveformPanel</name>
    <message>
        <source>Add a variable to plot</source>
        <translation>Variable darstellen …</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>Entfernen</translation>
    </message>
    <message>
        <source>Stop plotting the chosen variable</source>
        <translation>Die gewählte Variable nicht mehr darstellen</translation>
    </message>
    <message>
        <source>Zoom in: show less time (Ctrl+wheel)</source>
        <translation>Vergrößern: weniger Zeit zeigen (Strg+Mausrad)</translation>
    </message>
    <message>
        <source>Zoom out: show more time (Ctrl+wheel)</source>
        <translation>Verkleinern: mehr Zeit zeigen (Strg+Mausrad)</translation>
    </message>
    <message>
        <source>Fit</source>
        <translation>Einpassen</translation>
    </message>
    <message>
        <source>Show the whole recording</source>
        <translation>Die ganze Aufzeichnung zeigen</translation>
    </message>
    <message>
        <source>Export VCD...</source>
        <translation>VCD exportieren …</translation>
    </message>
    <message>
        <source>Write the recording as a Value Change Dump, for GTKWave</source>
        <translation>Die Aufzeichnung als Value Change Dump für GTKWave schreiben</translation>
    </message>
    <message>
        <source>Export VCD</source>
        <translation>VCD exportieren</translation>
    </message>
    <message>
        <source>Nothing is recorded yet: start the simulation or run a scenario.</source>
        <translation>Noch nichts aufgezeichnet: Starten Sie die Simulation oder führen Sie ein Szenario aus.</translation>
    </message>
    <message>
        <source>Value Change Dumps (*.vcd);;All files (*)</source>
        <translation>Value Change Dumps (*.vcd);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Remove All</source>
        <translation>Alle entfernen</translation>
    </message>
    <message>
        <source>Stop plotting every variable, also those a scenario added</source>
        <translation>Keine Variable mehr darstellen, auch nicht die von einem Szenario hinzugefügten</translation>
    </message>
</context>
<context>
    <name>rs::ui::WaveformView</name>
    <message>
        <source>Add variables to plot them over the simulation&apos;s time.</source>
        <translation>Fügen Sie Variablen hinzu, um sie über die Zeit der Simulation darzustellen.</translation>
    </message>
</context>
<context>
    <name>rs::ui::WelcomePage</name>
    <message>
        <source>&lt;h2&gt;No project is open&lt;/h2&gt;&lt;p&gt;Start a new project, open one, or look at the example from the manual.&lt;/p&gt;</source>
        <translation>&lt;h2&gt;Kein Projekt ist geöffnet&lt;/h2&gt;&lt;p&gt;Beginnen Sie ein neues Projekt, öffnen Sie eines oder sehen Sie sich das Beispiel aus dem Handbuch an.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&lt;b&gt;&amp;Recent projects&lt;/b&gt;</source>
        <translation>&lt;b&gt;&amp;Zuletzt geöffnete Projekte&lt;/b&gt;</translation>
    </message>
</context>
</TS>
