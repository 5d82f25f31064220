<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="sv">
<context>
    <name>BlockDocumentation</name>
    <message>
        <source>Library %1, version %2. Block version %3.</source>
        <translation>Bibliotek %1, version %2. Blockversion %3.</translation>
    </message>
    <message>
        <source>A system block: the simulator carries out its instruction %1, which the language cannot say.</source>
        <translation>Ett systemblock: simulatorn utför dess instruktion %1, som språket inte kan uttrycka.</translation>
    </message>
    <message>
        <source>Pins</source>
        <translation>Anslutningar</translation>
    </message>
    <message>
        <source>Pin</source>
        <translation>Anslutning</translation>
    </message>
    <message>
        <source>Kind</source>
        <translation>Slag</translation>
    </message>
    <message>
        <source>When not bound</source>
        <translation>Om inte ansluten</translation>
    </message>
    <message>
        <source>default %1</source>
        <translation>standard %1</translation>
    </message>
    <message>
        <source>must be bound</source>
        <translation>måste anslutas</translation>
    </message>
    <message>
        <source>may stay open</source>
        <translation>får lämnas öppen</translation>
    </message>
    <message>
        <source>Timing diagram</source>
        <translation>Tidsdiagram</translation>
    </message>
    <message>
        <source>No timing diagram: %1</source>
        <translation>Inget tidsdiagram: %1</translation>
    </message>
    <message>
        <source>The pins of the example project %1 while its scenario %2 runs, from power on.</source>
        <translation>Exempelprojektets %1 anslutningar medan dess scenario %2 körs, från tillslag.</translation>
    </message>
    <message numerus="yes">
        <source>All %n expectation(s) of the scenario held.</source>
        <translation>
            <numerusform>Scenariots enda förväntan höll.</numerusform>
            <numerusform>Scenariots alla %n förväntningar höll.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n expectation(s) of the scenario failed: the diagram shows what the block did, not what the example expects.</source>
        <translation>
            <numerusform>%n förväntan i scenariot höll inte: diagrammet visar vad blocket gjorde, inte vad exemplet väntar sig.</numerusform>
            <numerusform>%n förväntningar i scenariot höll inte: diagrammet visar vad blocket gjorde, inte vad exemplet väntar sig.</numerusform>
        </translation>
    </message>
    <message>
        <source>States</source>
        <translation>Tillstånd</translation>
    </message>
    <message>
        <source>DiagCode holds the state as its 16-bit pattern (16#8000 reads -32768 in a register). The outputs each state switches on:</source>
        <translation>DiagCode håller tillståndet som dess 16-bitarsmönster (16#8000 läses -32768 i ett register). Utgångarna som varje tillstånd slår till:</translation>
    </message>
    <message>
        <source>The outputs each state switches on:</source>
        <translation>Utgångarna som varje tillstånd slår till:</translation>
    </message>
    <message>
        <source>State</source>
        <translation>Tillstånd</translation>
    </message>
    <message>
        <source>Meaning</source>
        <translation>Betydelse</translation>
    </message>
    <message>
        <source>Transitions</source>
        <translation>Övergångar</translation>
    </message>
    <message>
        <source>Each scan takes at most one transition: the first of the state&apos;s list whose condition holds. The outputs then follow the new state. In the conditions * is AND, + is OR and / is NOT, as in the program.</source>
        <translation>Varje programcykel tar högst en övergång: den första i tillståndets lista vars villkor är uppfyllt. Utgångarna följer sedan det nya tillståndet. I villkoren är * OCH, + ELLER och / INTE, som i programmet.</translation>
    </message>
    <message>
        <source>In state</source>
        <translation>I tillstånd</translation>
    </message>
    <message>
        <source>Condition</source>
        <translation>Villkor</translation>
    </message>
    <message>
        <source>Next state</source>
        <translation>Nästa tillstånd</translation>
    </message>
    <message>
        <source>always</source>
        <translation>alltid</translation>
    </message>
    <message>
        <source>any</source>
        <translation>alla</translation>
    </message>
    <message>
        <source>The other lines of the block&apos;s body, which the conditions and outputs use:</source>
        <translation>Blockets övriga rader, som villkoren och utgångarna använder:</translation>
    </message>
</context>
<context>
    <name>BlockText</name>
    <message>
        <source>A system block: the simulator carries out its instruction %1.</source>
        <translation>Ett systemblock: simulatorn utför dess instruktion %1.</translation>
    </message>
    <message>
        <source>library %1, version %2</source>
        <translation>bibliotek %1, version %2</translation>
    </message>
    <message>
        <source>may stay open</source>
        <translation>får lämnas öppen</translation>
    </message>
    <message>
        <source>must be bound</source>
        <translation>måste kopplas</translation>
    </message>
    <message>
        <source>default %1</source>
        <translation>standard %1</translation>
    </message>
    <message>
        <source>constant</source>
        <translation>konstant</translation>
    </message>
    <message>
        <source>time</source>
        <translation>tid</translation>
    </message>
    <message>
        <source>double register</source>
        <translation>dubbelregister</translation>
    </message>
    <message>
        <source>register</source>
        <translation>register</translation>
    </message>
    <message>
        <source>bit</source>
        <translation>bit</translation>
    </message>
    <message>
        <source>output</source>
        <translation>utgång</translation>
    </message>
    <message>
        <source>input</source>
        <translation>ingång</translation>
    </message>
</context>
<context>
    <name>CommandLine</name>
    <message>
        <source>IDE for Pluto safety PLCs.</source>
        <translation>Utvecklingsmiljö för Pluto säkerhets-PLC.</translation>
    </message>
    <message>
        <source>The project to open. Without it, the bundled example opens.</source>
        <translation>Projektet som ska öppnas. Utan det öppnas det medföljande exemplet.</translation>
    </message>
    <message>
        <source>Save a picture of the main window to OUT.png and exit.</source>
        <translation>Spara en bild av huvudfönstret i OUT.png och avsluta.</translation>
    </message>
    <message>
        <source>give at most one project file</source>
        <translation>ange högst en projektfil</translation>
    </message>
    <message>
        <source>the example</source>
        <translation>exemplet</translation>
    </message>
    <message>
        <source>%1 has no unit %2</source>
        <translation>%1 har ingen enhet %2</translation>
    </message>
    <message>
        <source>cannot write %1: %2</source>
        <translation>kan inte skriva %1: %2</translation>
    </message>
    <message>
        <source>Draw with the light or dark palette, or the system&apos;s, this time.</source>
        <translation>Rita med ljus eller mörk palett, eller systemets, den här gången.</translation>
    </message>
    <message>
        <source>unknown theme &apos;%1&apos;; use light, dark or system</source>
        <translation>okänt tema &apos;%1&apos;; använd light, dark eller system</translation>
    </message>
    <message>
        <source>Run the scenario in the simulator first, so the window shows the live state it ends in.</source>
        <translation>Kör först scenariot i simulatorn, så att fönstret visar det tillstånd som det slutar i.</translation>
    </message>
    <message>
        <source>%1 has no sequence %2 in unit %3</source>
        <translation>%1 har ingen sekvens %2 i enhet %3</translation>
    </message>
    <message>
        <source>%1 has no gateway %2</source>
        <translation>%1 har ingen gateway %2</translation>
    </message>
    <message>
        <source>The page to show: ladder:N (the code of unit N as ladder), text:N (as text), ladder:N.S or text:N.S (its sequence S), io:N (its I/O options), asi:N (its AS-i options), variables:N, unit:N, gateway:N (the gateway with node address N), project, or properties (the project&apos;s properties and their proofs).</source>
        <translation>Sidan som ska visas: ladder:N (koden för enhet N som ladder), text:N (som text), ladder:N.S eller text:N.S (dess sekvens S), io:N (dess I/O-alternativ), asi:N (dess AS-i-alternativ), variables:N, unit:N, gateway:N (gatewayen med nodadress N), project eller properties (projektets egenskaper och deras bevis).</translation>
    </message>
    <message>
        <source>Prove the project&apos;s properties first (Build &gt; Prove All), so the window shows their results.</source>
        <translation>Bevisa först projektets egenskaper (Bygg &gt; Bevisa alla), så att fönstret visar resultaten.</translation>
    </message>
    <message>
        <source>unknown page &apos;%1&apos;; the pages are ladder:N, text:N, io:N, asi:N, variables:N and unit:N for unit N, ladder:N.S and text:N.S for its sequence S, gateway:N for gateway N, project and properties</source>
        <translation>okänd sida &apos;%1&apos;; sidorna är ladder:N, text:N, io:N, asi:N, variables:N och unit:N för enhet N, ladder:N.S och text:N.S för dess sekvens S, gateway:N för gateway N, project och properties</translation>
    </message>
    <message>
        <source>%1 does not read, so it has no properties page</source>
        <translation>%1 går inte att läsa och har därför ingen egenskapssida</translation>
    </message>
    <message>
        <source>%1 is a PL110 program: its pages are ladder:N (from rung N), text:N and variables:N</source>
        <translation>%1 är ett PL110-program: dess sidor är ladder:N (från steg N), text:N och variables:N</translation>
    </message>
    <message>
        <source>%1 has no rung %2</source>
        <translation>%1 har inget steg %2</translation>
    </message>
    <message>
        <source>%1 is a PL110 program; proofs are for Pluto projects</source>
        <translation>%1 är ett PL110-program; bevis görs för Pluto-projekt</translation>
    </message>
</context>
<context>
    <name>ElementKinds</name>
    <message>
        <source>Contact (NO)</source>
        <translation>Kontakt, slutande (NO)</translation>
    </message>
    <message>
        <source>Contact (NC)</source>
        <translation>Kontakt, brytande (NC)</translation>
    </message>
    <message>
        <source>Positive Edge (P)</source>
        <translation>Positiv flank (P)</translation>
    </message>
    <message>
        <source>Negative Edge (N)</source>
        <translation>Negativ flank (N)</translation>
    </message>
    <message>
        <source>Not Positive Edge (/P)</source>
        <translation>Inte positiv flank (/P)</translation>
    </message>
    <message>
        <source>Not Negative Edge (/N)</source>
        <translation>Inte negativ flank (/N)</translation>
    </message>
    <message>
        <source>On-Delay Timer (TON)</source>
        <translation>Tillslagsfördröjd timer (TON)</translation>
    </message>
    <message>
        <source>Pulse Timer (TPS)</source>
        <translation>Pulstimer (TPS)</translation>
    </message>
    <message>
        <source>Off-Delay Timer (TOF)</source>
        <translation>Frånslagsfördröjd timer (TOF)</translation>
    </message>
    <message>
        <source>Comparison</source>
        <translation>Jämförelse</translation>
    </message>
    <message>
        <source>Coil</source>
        <translation>Spole</translation>
    </message>
    <message>
        <source>Set Latch</source>
        <translation>Sättande spole</translation>
    </message>
    <message>
        <source>Reset Latch</source>
        <translation>Återställande spole</translation>
    </message>
    <message>
        <source>Toggle Latch</source>
        <translation>Växlande spole</translation>
    </message>
    <message>
        <source>Jump</source>
        <translation>Hopp</translation>
    </message>
    <message>
        <source>Sequence Reset</source>
        <translation>Sekvensåterställning</translation>
    </message>
    <message>
        <source>Arithmetic</source>
        <translation>Aritmetik</translation>
    </message>
    <message>
        <source>Preset (time such as 2s50, or a register):</source>
        <translation>Förinställt värde (en tid som 2s50, eller ett register):</translation>
    </message>
    <message>
        <source>Register:</source>
        <translation>Register:</translation>
    </message>
    <message>
        <source>Target register:</source>
        <translation>Målregister:</translation>
    </message>
    <message>
        <source>Step (number, or +n / -n relative):</source>
        <translation>Steg (nummer, eller relativt +n / -n):</translation>
    </message>
    <message>
        <source>Sequence (such as S0.1):</source>
        <translation>Sekvens (t.ex. S0.1):</translation>
    </message>
    <message>
        <source>Variable:</source>
        <translation>Variabel:</translation>
    </message>
</context>
<context>
    <name>InstanceVariableText</name>
    <message>
        <source>Private variable #%1 of block %2 (line %3)</source>
        <translation>Privat variabel #%1 i block %2 (rad %3)</translation>
    </message>
    <message>
        <source>Pin %1 of block %2 (line %3)</source>
        <translation>Anslutning %1 i block %2 (rad %3)</translation>
    </message>
</context>
<context>
    <name>LadderActions</name>
    <message>
        <source>&amp;Make Block...</source>
        <translation>&amp;Gör block...</translation>
    </message>
    <message>
        <source>&amp;Update Block</source>
        <translation>&amp;Uppdatera block</translation>
    </message>
    <message>
        <source>F</source>
        <translation>F</translation>
    </message>
    <message>
        <source>A new network holding a function block of the libraries</source>
        <translation>Ett nytt nätverk med ett funktionsblock ur biblioteken</translation>
    </message>
    <message>
        <source>&amp;Function...</source>
        <translation>&amp;Funktion...</translation>
    </message>
    <message>
        <source>%1 (key %2)</source>
        <translation>%1 (tangent %2)</translation>
    </message>
    <message>
        <source>Text</source>
        <translation>Text</translation>
    </message>
    <message>
        <source>Show this code as text</source>
        <translation>Visa koden som text</translation>
    </message>
    <message>
        <source>After</source>
        <translation>Efter</translation>
    </message>
    <message>
        <source>Insert in series after the selection</source>
        <translation>Infoga i serie efter markeringen</translation>
    </message>
    <message>
        <source>Before</source>
        <translation>Före</translation>
    </message>
    <message>
        <source>Insert in series before the selection</source>
        <translation>Infoga i serie före markeringen</translation>
    </message>
    <message>
        <source>Parallel</source>
        <translation>Parallellt</translation>
    </message>
    <message>
        <source>Insert in a parallel branch around the selection</source>
        <translation>Infoga i en parallell gren runt markeringen</translation>
    </message>
    <message>
        <source>&amp;Delete</source>
        <translation>&amp;Ta bort</translation>
    </message>
    <message>
        <source>Delete the selected element</source>
        <translation>Ta bort det markerade elementet</translation>
    </message>
    <message>
        <source>&amp;New Network</source>
        <translation>&amp;Nytt nätverk</translation>
    </message>
    <message>
        <source>A new network below the selected one</source>
        <translation>Ett nytt nätverk under det markerade</translation>
    </message>
    <message>
        <source>Expand All</source>
        <translation>Fäll ut alla</translation>
    </message>
    <message>
        <source>Show the rungs of every network</source>
        <translation>Visa strömvägarna i alla nätverk</translation>
    </message>
    <message>
        <source>Collapse All</source>
        <translation>Fäll ihop alla</translation>
    </message>
    <message>
        <source>Show only the comments of the networks</source>
        <translation>Visa endast nätverkens kommentarer</translation>
    </message>
    <message>
        <source>&amp;Edit Network</source>
        <translation>&amp;Redigera nätverk</translation>
    </message>
    <message>
        <source>Gather the next edits of this network until Update</source>
        <translation>Samla nästa ändringar i nätverket fram till Uppdatera</translation>
    </message>
    <message>
        <source>Update</source>
        <translation>Uppdatera</translation>
    </message>
    <message>
        <source>Keep the edits of the network as one step</source>
        <translation>Behåll ändringarna i nätverket som ett enda ändringssteg</translation>
    </message>
    <message>
        <source>Undo Network</source>
        <translation>Ångra nätverk</translation>
    </message>
    <message>
        <source>Drop the edits of the network</source>
        <translation>Kasta ändringarna i nätverket</translation>
    </message>
    <message>
        <source>Zoom In</source>
        <translation>Zooma in</translation>
    </message>
    <message>
        <source>Zoom in</source>
        <translation>Zooma in</translation>
    </message>
    <message>
        <source>Zoom Out</source>
        <translation>Zooma ut</translation>
    </message>
    <message>
        <source>Zoom out</source>
        <translation>Zooma ut</translation>
    </message>
    <message>
        <source>100%</source>
        <translation>100 %</translation>
    </message>
    <message>
        <source>Actual size</source>
        <translation>Verklig storlek</translation>
    </message>
    <message>
        <source>Print...</source>
        <translation>Skriv ut …</translation>
    </message>
    <message>
        <source>Print the networks of this page</source>
        <translation>Skriv ut nätverken på den här sidan</translation>
    </message>
    <message>
        <source>PDF...</source>
        <translation>PDF …</translation>
    </message>
    <message>
        <source>Export the networks of this page as PDF</source>
        <translation>Exportera nätverken på den här sidan som PDF</translation>
    </message>
    <message>
        <source>P&amp;roperties...</source>
        <translation>&amp;Egenskaper …</translation>
    </message>
    <message>
        <source>&amp;Toggle</source>
        <translation>&amp;Växla</translation>
    </message>
    <message>
        <source>&amp;Force...</source>
        <translation>&amp;Forcera …</translation>
    </message>
    <message>
        <source>Move Left</source>
        <translation>Flytta vänster</translation>
    </message>
    <message>
        <source>Move Right</source>
        <translation>Flytta höger</translation>
    </message>
    <message>
        <source>Move Up</source>
        <translation>Flytta upp</translation>
    </message>
    <message>
        <source>Move Down</source>
        <translation>Flytta ned</translation>
    </message>
    <message>
        <source>Select Enclosing Group</source>
        <translation>Markera omgivande grupp</translation>
    </message>
    <message>
        <source>Select Network</source>
        <translation>Markera nätverket</translation>
    </message>
    <message>
        <source>New &amp;Config Option...</source>
        <translation>Nytt &amp;konfigurationsalternativ …</translation>
    </message>
    <message>
        <source>Cu&amp;t Network(s)</source>
        <translation>Klipp &amp;ut nätverk</translation>
    </message>
    <message>
        <source>&amp;Copy Network(s)</source>
        <translation>&amp;Kopiera nätverk</translation>
    </message>
    <message>
        <source>&amp;Paste Network(s)</source>
        <translation>Klistra &amp;in nätverk</translation>
    </message>
    <message>
        <source>&amp;Delete Network(s)</source>
        <translation>&amp;Ta bort nätverk</translation>
    </message>
    <message>
        <source>Network Co&amp;mment...</source>
        <translation>Nätverksko&amp;mmentar …</translation>
    </message>
    <message>
        <source>New &amp;Step</source>
        <translation>Nytt &amp;steg</translation>
    </message>
    <message>
        <source>New Se&amp;quence...</source>
        <translation>Ny sek&amp;vens …</translation>
    </message>
    <message>
        <source>&amp;Block Documentation...</source>
        <translation>&amp;Blockdokumentation...</translation>
    </message>
    <message>
        <source>Expand</source>
        <translation>Fäll ut</translation>
    </message>
    <message>
        <source>Collapse</source>
        <translation>Fäll ihop</translation>
    </message>
    <message>
        <source>Edit Network</source>
        <comment>tool bar</comment>
        <translation>Redigera nätverk</translation>
    </message>
    <message>
        <source>Undo Network</source>
        <comment>tool bar</comment>
        <translation>Ångra nätverk</translation>
    </message>
    <message>
        <source>New Network</source>
        <comment>tool bar</comment>
        <translation>Nytt nätverk</translation>
    </message>
</context>
<context>
    <name>ProjectComparison</name>
    <message numerus="yes">
        <source>%1 has %n error(s), so its behaviour cannot be compared. Build &gt; Compile lists them.</source>
        <translation>
            <numerusform>%1 har %n fel, så dess beteende kan inte jämföras. Bygg &gt; Kompilera listar det.</numerusform>
            <numerusform>%1 har %n fel, så dess beteende kan inte jämföras. Bygg &gt; Kompilera listar dem.</numerusform>
        </translation>
    </message>
    <message>
        <source>The project</source>
        <translation>Projektet</translation>
    </message>
</context>
<context>
    <name>ProjectMerging</name>
    <message>
        <source>Merge Project</source>
        <translation>Sammanfoga projekt</translation>
    </message>
    <message>
        <source>Open the project to merge first (File &gt; Open); its units are then added to %1.</source>
        <translation>Öppna först projektet som ska sammanfogas (Arkiv &gt; Öppna); dess enheter läggs sedan till i %1.</translation>
    </message>
    <message>
        <source>Add the units of this project to %1:</source>
        <translation>Lägg till enheterna i det här projektet i %1:</translation>
    </message>
    <message>
        <source>%1 cannot be merged into %2: every unit must keep its station and every symbolic name must be one project&apos;s only.</source>
        <translation>%1 kan inte sammanfogas med %2: varje enhet måste behålla sin station och varje symboliskt namn får bara finnas i ett av projekten.</translation>
    </message>
    <message>
        <source>%1 is merged into %2. Each name both used stays only in the units that define it; elsewhere its variable is written as its address.</source>
        <translation>%1 är sammanfogat med %2. Varje namn som båda använde finns kvar bara i de enheter som definierar det; på andra ställen skrivs variabeln med sin adress.</translation>
    </message>
    <message>
        <source>%1 is merged into %2.</source>
        <translation>%1 är sammanfogat med %2.</translation>
    </message>
</context>
<context>
    <name>QObject</name>
    <message>
        <source>Option on</source>
        <translation>Alternativ till</translation>
    </message>
    <message>
        <source>Option off</source>
        <translation>Alternativ från</translation>
    </message>
    <message>
        <source>Added since validation on %1</source>
        <translation>Tillagt sedan valideringen %1</translation>
    </message>
    <message>
        <source>Changed since validation on %1</source>
        <translation>Ändrat sedan valideringen %1</translation>
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
        <translation>Spara</translation>
    </message>
    <message>
        <source>Save All</source>
        <translation>Spara alla</translation>
    </message>
    <message>
        <source>Open</source>
        <translation>Öppna</translation>
    </message>
    <message>
        <source>&amp;Yes</source>
        <translation>&amp;Ja</translation>
    </message>
    <message>
        <source>Yes to &amp;All</source>
        <translation>Ja till &amp;alla</translation>
    </message>
    <message>
        <source>&amp;No</source>
        <translation>&amp;Nej</translation>
    </message>
    <message>
        <source>N&amp;o to All</source>
        <translation>N&amp;ej till alla</translation>
    </message>
    <message>
        <source>Abort</source>
        <translation>Avbryt</translation>
    </message>
    <message>
        <source>Retry</source>
        <translation>Försök igen</translation>
    </message>
    <message>
        <source>Ignore</source>
        <translation>Ignorera</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>Stäng</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Avbryt</translation>
    </message>
    <message>
        <source>Discard</source>
        <translation>Förkasta</translation>
    </message>
    <message>
        <source>Help</source>
        <translation>Hjälp</translation>
    </message>
    <message>
        <source>Apply</source>
        <translation>Verkställ</translation>
    </message>
    <message>
        <source>Reset</source>
        <translation>Återställ</translation>
    </message>
    <message>
        <source>Restore Defaults</source>
        <translation>Återställ standardvärden</translation>
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
        <translation>steg %1</translation>
    </message>
</context>
<context>
    <name>rs::pl110::Area</name>
    <message>
        <source>Digital inputs: I1-I8 on the terminals, the rest from expansion modules</source>
        <translation>Digitala ingångar: I1–I8 på plintarna, resten från expansionsmoduler</translation>
    </message>
    <message>
        <source>Digital outputs: Q1-Q8 are the relays, the rest go to expansion modules</source>
        <translation>Digitala utgångar: Q1–Q8 är reläerna, resten går till expansionsmoduler</translation>
    </message>
    <message>
        <source>Markers</source>
        <translation>Minnesceller</translation>
    </message>
    <message>
        <source>Bistable relays: each energisation of the coil changes the contact</source>
        <translation>Bistabila reläer: varje aktivering av spolen växlar kontakten</translation>
    </message>
    <message>
        <source>Timers: the contact and the value in units of the time base</source>
        <translation>Timrar: kontakten och värdet i tidbasens enheter</translation>
    </message>
    <message>
        <source>Counters: the contact and the value</source>
        <translation>Räknare: kontakten och värdet</translation>
    </message>
    <message>
        <source>Variables, kept by the battery</source>
        <translation>Variabler, bevarade av batteriet</translation>
    </message>
    <message>
        <source>Special markers: status, clocks, scan times and settings</source>
        <translation>Specialminnen: status, klockor, cykeltider och inställningar</translation>
    </message>
    <message>
        <source>Analogue inputs, scaled by RANGE</source>
        <translation>Analoga ingångar, skalade av RANGE</translation>
    </message>
    <message>
        <source>Analogue output, 0-10 V</source>
        <translation>Analog utgång, 0–10 V</translation>
    </message>
    <message>
        <source>Timer presets</source>
        <translation>Förval för timrar</translation>
    </message>
    <message>
        <source>Counter presets</source>
        <translation>Förval för räknare</translation>
    </message>
    <message>
        <source>EEPROM words, kept without power</source>
        <translation>EEPROM-ord, bevarade utan matning</translation>
    </message>
</context>
<context>
    <name>rs::ui::AdvancedSettingsDialog</name>
    <message>
        <source>&amp;Set the CAN bus cycle time:</source>
        <translation>&amp;Ställ in CAN-bussens cykeltid:</translation>
    </message>
    <message>
        <source>Advanced Settings of Pluto %1</source>
        <translation>Avancerade inställningar för Pluto %1</translation>
    </message>
    <message>
        <source>These settings have influence on the system response time. Do not change these values without a good knowledge of the function of the system. The hardware manual describes them.</source>
        <translation>Dessa inställningar påverkar systemets reaktionstid. Ändra inte dessa värden utan god kunskap om systemets funktion. Hårdvarumanualen beskriver dem.</translation>
    </message>
    <message>
        <source> ms</source>
        <translation> ms</translation>
    </message>
    <message>
        <source>Unset, the unit keeps its default. The simulator sends a unit&apos;s variables to the other units after every scan by default, and with a cycle time set, once per cycle time.</source>
        <translation>Utan inställning behåller enheten sitt standardvärde. Simulatorn skickar som standard en enhets variabler till de andra enheterna efter varje cykel, och med en inställd cykeltid en gång per cykeltid.</translation>
    </message>
</context>
<context>
    <name>rs::ui::AsiOptionsPage</name>
    <message>
        <source>Bus Master</source>
        <translation>Busmaster</translation>
    </message>
    <message>
        <source>Monitor only</source>
        <translation>Endast monitor</translation>
    </message>
    <message>
        <source>Monitor / Slave</source>
        <translation>Monitor / slav</translation>
    </message>
    <message>
        <source>Monitor / Slave with 3 extra virtual slaves</source>
        <translation>Monitor / slav med 3 extra virtuella slavar</translation>
    </message>
    <message>
        <source>AS-i bus not used</source>
        <translation>AS-i-bussen används inte</translation>
    </message>
    <message>
        <source>Undefined</source>
        <translation>Odefinierad</translation>
    </message>
    <message>
        <source>Safe Input</source>
        <translation>Säker ingång</translation>
    </message>
    <message>
        <source>Nonsafe Std</source>
        <translation>Icke säker std</translation>
    </message>
    <message>
        <source>Nonsafe B</source>
        <translation>Icke säker B</translation>
    </message>
    <message>
        <source>Nonsafe A</source>
        <translation>Icke säker A</translation>
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
        <translation>Säker utgång</translation>
    </message>
    <message>
        <source>Pluto as Safe Input</source>
        <translation>Pluto som säker ingång</translation>
    </message>
    <message>
        <source>No channel monitoring</source>
        <translation>Ingen kanalövervakning</translation>
    </message>
    <message>
        <source>Channel monitoring</source>
        <translation>Kanalövervakning</translation>
    </message>
    <message>
        <source>Chan mon &amp; debounce filter</source>
        <translation>Kanalöv. &amp; avstudsfilter</translation>
    </message>
    <message>
        <source>Simultaneously</source>
        <translation>Samtidigt</translation>
    </message>
    <message>
        <source>Simultaneously &amp; debounce</source>
        <translation>Samtidigt &amp; avstudsning</translation>
    </message>
    <message>
        <source>AS-i general options</source>
        <translation>Allmänna AS-i-alternativ</translation>
    </message>
    <message>
        <source>AS-i bus working mode</source>
        <translation>AS-i-bussens driftläge</translation>
    </message>
    <message>
        <source>Set AS-i bus working mode</source>
        <translation>Ställ in AS-i-driftläge</translation>
    </message>
    <message>
        <source>ASi &amp;slave address:</source>
        <translation>ASi-&amp;slavadress:</translation>
    </message>
    <message>
        <source>Set AS-i slave address</source>
        <translation>Ställ in AS-i-slavadress</translation>
    </message>
    <message>
        <source>Optimize for</source>
        <translation>Optimera för</translation>
    </message>
    <message>
        <source>Short stop time (worst case, when error)</source>
        <translation>Kort stopptid (värsta fall, vid fel)</translation>
    </message>
    <message>
        <source>Disturbance immunity</source>
        <translation>Störtålighet</translation>
    </message>
    <message>
        <source>Disturbance immunity is not recommended when fewer than 20 slaves are used: the worst case stop time grows by 10 ms.</source>
        <translation>Störtålighet rekommenderas inte med färre än 20 slavar: stopptiden i värsta fall ökar med 10 ms.</translation>
    </message>
    <message>
        <source>Set AS-i optimisation</source>
        <translation>Ställ in AS-i-optimering</translation>
    </message>
    <message>
        <source>AS-i slaves</source>
        <translation>AS-i-slavar</translation>
    </message>
    <message>
        <source>Slave No</source>
        <translation>Slav nr</translation>
    </message>
    <message>
        <source>Type of Slave</source>
        <translation>Typ av slav</translation>
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
        <translation>Kanalövervakning</translation>
    </message>
    <message>
        <source>Time limit</source>
        <translation>Tidsgräns</translation>
    </message>
    <message>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <source>Reading the slaves from the bus, teaching safety codes, the code tables and changing a slave&apos;s address need a Pluto on a real AS-i bus, and are not in Rungsmith. A slave the code uses but this table does not define is a warning when compiling; the simulator gives each safe input slave two channels that follow its channel monitoring.</source>
        <translation>Att läsa in slavarna från bussen, lära in säkerhetskoder, kodtabellerna och att byta en slavs adress kräver en Pluto på en riktig AS-i-buss och finns inte i Rungsmith. En slav som koden använder men som tabellen inte definierar ger en varning vid kompilering; simulatorn ger varje säker ingångsslav två kanaler som följer dess kanalövervakning.</translation>
    </message>
    <message>
        <source>%1 — AS-i Options</source>
        <translation>%1 — AS-i-alternativ</translation>
    </message>
    <message>
        <source>How the unit works on its AS-i bus, and what each slave address holds (manual Part 1, 7.1).</source>
        <translation>Hur enheten arbetar på sin AS-i-buss och vad varje slavadress rymmer (manualen del 1, 7.1).</translation>
    </message>
    <message>
        <source>%1 of %2 slaves are Safe Output or Pluto as Safe Input, the most a Pluto takes.</source>
        <translation>%1 av %2 slavar är säkra utgångar eller Pluto som säker ingång, det mesta en Pluto tar.</translation>
    </message>
    <message>
        <source>%1 takes the whole address: a B slave only goes beside an A/B slave.</source>
        <translation>%1 tar hela adressen: en B-slav kan bara stå bredvid en A/B-slav.</translation>
    </message>
    <message>
        <source>%1 monitors its channels itself.</source>
        <translation>%1 övervakar sina kanaler själv.</translation>
    </message>
    <message>
        <source>Set AS-i slave %1</source>
        <translation>Ställ in AS-i-slav %1</translation>
    </message>
</context>
<context>
    <name>rs::ui::AsiProfileDialog</name>
    <message>
        <source>%1 (Outputs)</source>
        <translation>%1 (Utgångar)</translation>
    </message>
    <message>
        <source>%1 (Safe slave)</source>
        <translation>%1 (Säker slav)</translation>
    </message>
    <message>
        <source>%1 (Standard slave)</source>
        <translation>%1 (Standardslav)</translation>
    </message>
    <message>
        <source>AS-i Profile</source>
        <translation>AS-i-profil</translation>
    </message>
    <message>
        <source>&amp;I/O configuration:</source>
        <translation>&amp;I/O-konfiguration:</translation>
    </message>
    <message>
        <source>I&amp;D code:</source>
        <translation>I&amp;D-kod:</translation>
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
        <translation>Exempel ur manualen: S-0.B… en säker slav; S-7.B… en säker slav med utgångar; S-7.0… en icke säker standardslav med 4 ingångar och 4 utgångar. Slavens egen manual anger dess profil.</translation>
    </message>
    <message>
        <source>Profile for %1 = %2</source>
        <translation>Profil för %1 = %2</translation>
    </message>
</context>
<context>
    <name>rs::ui::BlockChooserDialog</name>
    <message>
        <source>The project&apos;s libraries hold no blocks. Add a library on the project page (Function libraries).</source>
        <translation>Projektets bibliotek innehåller inga block. Lägg till ett bibliotek på projektsidan (Funktionsbibliotek).</translation>
    </message>
    <message>
        <source>&amp;Find:</source>
        <translation>&amp;Sök:</translation>
    </message>
    <message>
        <source>Type to filter by name or description</source>
        <translation>Skriv för att filtrera på namn eller beskrivning</translation>
    </message>
    <message>
        <source>Insert Function Block</source>
        <translation>Infoga funktionsblock</translation>
    </message>
    <message>
        <source>&amp;Documentation...</source>
        <translation>&amp;Dokumentation...</translation>
    </message>
    <message>
        <source>The block&apos;s documentation: states, transitions and a timing diagram</source>
        <translation>Blockets dokumentation: tillstånd, övergångar och ett tidsdiagram</translation>
    </message>
</context>
<context>
    <name>rs::ui::BlockDocumentationDialog</name>
    <message>
        <source>%1 — Block Documentation</source>
        <translation>%1 — Blockdokumentation</translation>
    </message>
</context>
<context>
    <name>rs::ui::BlockPinsDialog</name>
    <message>
        <source>%1 Pins</source>
        <translation>Anslutningar för %1</translation>
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
        <translation>Pluto %1: E0=Inget fel</translation>
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
        <translation>Tillstånd</translation>
    </message>
    <message>
        <source>Code</source>
        <translation>Kod</translation>
    </message>
    <message>
        <source>Missing</source>
        <translation>Saknas</translation>
    </message>
    <message>
        <source>Ok, running</source>
        <translation>OK, körs</translation>
    </message>
    <message>
        <source>Ok, stopped</source>
        <translation>OK, stoppad</translation>
    </message>
    <message>
        <source>E0=No Error</source>
        <translation>E0=Inget fel</translation>
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
        <translation>Programsignaturen för enhetens kompilerade kod, som rungsmith-cli signature skriver ut den; den ändras precis när det enheten gör ändras</translation>
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
        <translation>enhet tillagd</translation>
    </message>
    <message>
        <source>unit removed</source>
        <translation>enhet borttagen</translation>
    </message>
    <message>
        <source>type changed</source>
        <translation>typ ändrad</translation>
    </message>
    <message>
        <source>ID code changed</source>
        <translation>ID-kod ändrad</translation>
    </message>
    <message>
        <source>I/O options changed</source>
        <translation>I/O-alternativ ändrade</translation>
    </message>
    <message>
        <source>exported and remanent variables changed</source>
        <translation>exporterade och remanenta variabler ändrade</translation>
    </message>
    <message>
        <source>names and descriptions changed</source>
        <translation>namn och beskrivningar ändrade</translation>
    </message>
    <message>
        <source>comments changed</source>
        <translation>kommentarer ändrade</translation>
    </message>
    <message>
        <source>Save Review as &amp;PDF...</source>
        <translation>Spara granskning som &amp;PDF …</translation>
    </message>
    <message>
        <source>Changes Since Validation</source>
        <translation>Ändringar sedan valideringen</translation>
    </message>
    <message>
        <source>Compare With</source>
        <translation>Jämför med</translation>
    </message>
    <message>
        <source>%1 as it is now, against the version validated on %2 by %3</source>
        <translation>%1 som det är nu, mot versionen som validerades %2 av %3</translation>
    </message>
    <message>
        <source>%1 as it is now (new), against %2 (old)</source>
        <translation>%1 som det är nu (nytt), mot %2 (gammalt)</translation>
    </message>
    <message>
        <source>Enter or a double click opens a network in the ladder</source>
        <translation>Enter eller ett dubbelklick öppnar ett nätverk i stegdiagrammet</translation>
    </message>
    <message>
        <source>Comparing...</source>
        <translation>Jämför …</translation>
    </message>
    <message>
        <source>Pluto %1: %2</source>
        <translation>Pluto %1: %2</translation>
    </message>
    <message>
        <source>Pluto %1 %2 network %3: added</source>
        <translation>Pluto %1 %2 nätverk %3: tillagt</translation>
    </message>
    <message>
        <source>Pluto %1 %2 network %3: removed</source>
        <translation>Pluto %1 %2 nätverk %3: borttaget</translation>
    </message>
    <message>
        <source>Pluto %1 %2 network %3: changed</source>
        <translation>Pluto %1 %2 nätverk %3: ändrat</translation>
    </message>
    <message>
        <source>No network, unit or option differs.</source>
        <translation>Inget nätverk, ingen enhet och inget alternativ skiljer sig.</translation>
    </message>
    <message>
        <source>No change in behaviour; only the text changed.</source>
        <translation>Inget ändrat beteende; bara texten har ändrats.</translation>
    </message>
    <message>
        <source>No change in behaviour.</source>
        <translation>Inget ändrat beteende.</translation>
    </message>
    <message>
        <source>Pluto %1</source>
        <translation>Pluto %1</translation>
    </message>
    <message>
        <source>Behaviour changed in %1 (project signature %2, was %3).</source>
        <translation>Beteendet har ändrats i %1 (projektsignatur %2, var %3).</translation>
    </message>
    <message>
        <source>There is nothing to save yet.</source>
        <translation>Det finns inget att spara än.</translation>
    </message>
    <message>
        <source>Save Review as PDF</source>
        <translation>Spara granskning som PDF</translation>
    </message>
    <message>
        <source>PDF files (*.pdf)</source>
        <translation>PDF-filer (*.pdf)</translation>
    </message>
</context>
<context>
    <name>rs::ui::CompileOutput</name>
    <message>
        <source>Compiling %1...</source>
        <translation>Kompilerar %1 …</translation>
    </message>
    <message>
        <source>Compiling %1</source>
        <translation>Kompilerar %1</translation>
    </message>
    <message>
        <source>Wrote %1</source>
        <translation>Skrev %1</translation>
    </message>
    <message>
        <source>Build &gt; Compile (F7) checks the project and writes the compiled file.</source>
        <translation>Bygg &gt; Kompilera (F7) kontrollerar projektet och skriver den kompilerade filen.</translation>
    </message>
    <message>
        <source>error: the compiled file was not written: %1</source>
        <translation>fel: den kompilerade filen skrevs inte: %1</translation>
    </message>
</context>
<context>
    <name>rs::ui::CompileOutputModel</name>
    <message>
        <source>Pluto %1, line %2:%3</source>
        <translation>Pluto %1, rad %2:%3</translation>
    </message>
    <message>
        <source>Pluto %1, settings</source>
        <translation>Pluto %1, inställningar</translation>
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
        <translation>fel: %1</translation>
    </message>
    <message>
        <source>warning: %1</source>
        <translation>varning: %1</translation>
    </message>
    <message>
        <source>Line %1 of the project file</source>
        <translation>Rad %1 i projektfilen</translation>
    </message>
    <message>
        <source>Place</source>
        <translation>Plats</translation>
    </message>
    <message>
        <source>Message</source>
        <translation>Meddelande</translation>
    </message>
</context>
<context>
    <name>rs::ui::CompileRun</name>
    <message>
        <source>Compiling</source>
        <translation>Kompilerar</translation>
    </message>
    <message>
        <source>Compiling %1...</source>
        <translation>Kompilerar %1 …</translation>
    </message>
    <message>
        <source>Compile</source>
        <translation>Kompilera</translation>
    </message>
    <message>
        <source>Compiled without errors. Save the project to write the compiled file.</source>
        <translation>Kompilerat utan fel. Spara projektet för att skriva den kompilerade filen.</translation>
    </message>
    <message>
        <source>Checked without errors. The compiled file is not written, as the project has unsaved changes.</source>
        <translation>Kontrollerat utan fel. Den kompilerade filen skrivs inte, eftersom projektet har osparade ändringar.</translation>
    </message>
</context>
<context>
    <name>rs::ui::ConfigOptionDialog</name>
    <message>
        <source>&amp;Enabled</source>
        <translation>&amp;Aktiverat</translation>
    </message>
    <message>
        <source>Config Option</source>
        <translation>Konfigurationsalternativ</translation>
    </message>
    <message>
        <source>a memory, such as M%1.5</source>
        <translation>ett minne, t.ex. M%1.5</translation>
    </message>
    <message>
        <source>&amp;Description:</source>
        <translation>&amp;Beskrivning:</translation>
    </message>
    <message>
        <source>&amp;Memory:</source>
        <translation>&amp;Minne:</translation>
    </message>
    <message>
        <source>Describe the option: the description is what the check box says.</source>
        <translation>Beskriv alternativet: beskrivningen är texten vid kryssrutan.</translation>
    </message>
    <message>
        <source>Only memories can be options (manual 11.6).</source>
        <translation>Endast minnen kan vara alternativ (manualen 11.6).</translation>
    </message>
    <message>
        <source>A config option is a check box on its network: it sets the memory when checked and resets it when not, so that one program serves machines with and without an option (manual 11.6).</source>
        <translation>Ett konfigurationsalternativ är en kryssruta på sitt nätverk: det sätter minnet när rutan är ikryssad och återställer det annars, så att ett program passar maskiner med och utan ett tillval (manualen 11.6).</translation>
    </message>
</context>
<context>
    <name>rs::ui::CsvExportDialog</name>
    <message>
        <source>Export Variable Names from Pluto %1</source>
        <translation>Exportera variabelnamn från Pluto %1</translation>
    </message>
    <message>
        <source>none</source>
        <translation>inga</translation>
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
        <translation>&amp;Bläddra …</translation>
    </message>
    <message>
        <source>Variables:</source>
        <translation>Variabler:</translation>
    </message>
    <message>
        <source>&amp;Global and local</source>
        <translation>&amp;Globala och lokala</translation>
    </message>
    <message>
        <source>G&amp;lobal only</source>
        <translation>Endast g&amp;lobala</translation>
    </message>
    <message>
        <source>L&amp;ocal only</source>
        <translation>Endast l&amp;okala</translation>
    </message>
    <message>
        <source>&amp;Prefix for names:</source>
        <translation>&amp;Prefix för namn:</translation>
    </message>
    <message>
        <source>Sort by:</source>
        <translation>Sortera efter:</translation>
    </message>
    <message>
        <source>&amp;Variable</source>
        <translation>&amp;Variabel</translation>
    </message>
    <message>
        <source>Symbolic &amp;name</source>
        <translation>Symboliskt &amp;namn</translation>
    </message>
    <message>
        <source>&amp;Separator:</source>
        <translation>&amp;Avgränsare:</translation>
    </message>
    <message>
        <source>&amp;File:</source>
        <translation>&amp;Fil:</translation>
    </message>
    <message>
        <source>&amp;Export</source>
        <translation>&amp;Exportera</translation>
    </message>
    <message>
        <source>CSV files (*.csv);;All files (*)</source>
        <translation>CSV-filer (*.csv);;Alla filer (*)</translation>
    </message>
</context>
<context>
    <name>rs::ui::CsvImportDialog</name>
    <message>
        <source>semicolons</source>
        <translation>semikolon</translation>
    </message>
    <message>
        <source>tabs</source>
        <translation>tabbar</translation>
    </message>
    <message>
        <source>commas</source>
        <translation>kommatecken</translation>
    </message>
    <message>
        <source>Import Variable Names to Pluto %1</source>
        <translation>Importera variabelnamn till Pluto %1</translation>
    </message>
    <message>
        <source>none</source>
        <translation>inga</translation>
    </message>
    <message>
        <source>&amp;Browse...</source>
        <translation>&amp;Bläddra …</translation>
    </message>
    <message>
        <source>&amp;File:</source>
        <translation>&amp;Fil:</translation>
    </message>
    <message>
        <source>&amp;Remove prefix from names:</source>
        <translation>&amp;Ta bort prefix från namn:</translation>
    </message>
    <message>
        <source>Line</source>
        <translation>Rad</translation>
    </message>
    <message>
        <source>Variable</source>
        <translation>Variabel</translation>
    </message>
    <message>
        <source>Symbolic Name</source>
        <translation>Symboliskt namn</translation>
    </message>
    <message>
        <source>Description</source>
        <translation>Beskrivning</translation>
    </message>
    <message>
        <source>Left out because</source>
        <translation>Utelämnad eftersom</translation>
    </message>
    <message>
        <source>&amp;Import</source>
        <translation>&amp;Importera</translation>
    </message>
    <message>
        <source>CSV files (*.csv *.txt);;All files (*)</source>
        <translation>CSV-filer (*.csv *.txt);;Alla filer (*)</translation>
    </message>
    <message>
        <source>Choose a CSV file with the columns Variable, Symbolic Name and Description. Nothing changes before you press Import.</source>
        <translation>Välj en CSV-fil med kolumnerna Variable, Symbolic Name och Description. Inget ändras innan du trycker på Importera.</translation>
    </message>
    <message>
        <source>Fields separated by %1. %2 to change, %3 unchanged, %4 left out.</source>
        <translation>Fälten är åtskilda med %1. %2 ändras, %3 oförändrade, %4 utelämnade.</translation>
    </message>
    <message numerus="yes">
        <source>%n variable(s)</source>
        <translation>
            <numerusform>%n variabel</numerusform>
            <numerusform>%n variabler</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n row(s)</source>
        <translation>
            <numerusform>%n rad</numerusform>
            <numerusform>%n rader</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>rs::ui::ElementDialog</name>
    <message>
        <source>Value:</source>
        <translation>Värde:</translation>
    </message>
    <message>
        <source>&amp;Negated (passes power when false)</source>
        <translation>&amp;Negerad (leder när den är falsk)</translation>
    </message>
    <message>
        <source>Output Properties</source>
        <translation>Egenskaper för utgång</translation>
    </message>
    <message>
        <source>Element Properties</source>
        <translation>Egenskaper för element</translation>
    </message>
    <message>
        <source>such as &gt;= 5, = R0.2, += 2, ++</source>
        <translation>t.ex. &gt;= 5, = R0.2, += 2, ++</translation>
    </message>
    <message>
        <source>&amp;Type:</source>
        <translation>&amp;Typ:</translation>
    </message>
    <message>
        <source>New &amp;Variable...</source>
        <translation>Ny &amp;variabel …</translation>
    </message>
    <message>
        <source>&amp;Comment:</source>
        <translation>&amp;Kommentar:</translation>
    </message>
    <message>
        <source>New Variable</source>
        <translation>Ny variabel</translation>
    </message>
    <message>
        <source>&amp;Address:</source>
        <translation>&amp;Adress:</translation>
    </message>
    <message>
        <source>Symbolic &amp;name:</source>
        <translation>Symboliskt &amp;namn:</translation>
    </message>
    <message>
        <source>Write an address such as I%1.0, Q%1.2 or M%1.5.</source>
        <translation>Skriv en adress, t.ex. I%1.0, Q%1.2 eller M%1.5.</translation>
    </message>
    <message>
        <source>Give the variable a name.</source>
        <translation>Ge variabeln ett namn.</translation>
    </message>
    <message>
        <source>Name %1 %2</source>
        <translation>Ge %1 namnet %2</translation>
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
        <translation>Extern kommunikation för Pluto %1</translation>
    </message>
    <message>
        <source>Which gateway data this unit receives: each External Comm Block takes one Data to Pluto packet of one gateway. A block that receives nothing for its timeout is cleared, and the Ext blocks of the code read it as not valid. The timeout must be greater than the gateway&apos;s cycle time (Gateway manual 4.5.1).</source>
        <translation>Vilka gatewaydata enheten tar emot: varje External Comm Block tar ett Data to Pluto-paket från en gateway. Ett block som inte tar emot något under sin timeout nollställs, och kodens Ext-block läser det som ogiltigt. Timeouten måste vara större än gatewayens cykeltid (Gateway-manualen 4.5.1).</translation>
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
        <translation>Timeout</translation>
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
        <translation>Ingen timeout</translation>
    </message>
    <message>
        <source>Gateway %1 (not in the project)</source>
        <translation>Gateway %1 (finns inte i projektet)</translation>
    </message>
    <message>
        <source>The project has no gateway: add one with Project &gt; New Gateway first.</source>
        <translation>Projektet har ingen gateway: lägg först till en med Projekt &gt; Ny gateway.</translation>
    </message>
</context>
<context>
    <name>rs::ui::ForcesView</name>
    <message>
        <source>&amp;Release</source>
        <translation>&amp;Häv</translation>
    </message>
    <message>
        <source>Release &amp;All</source>
        <translation>Häv &amp;alla</translation>
    </message>
    <message>
        <source>Variable</source>
        <translation>Variabel</translation>
    </message>
    <message>
        <source>Symbolic Name</source>
        <translation>Symboliskt namn</translation>
    </message>
    <message>
        <source>Forced To</source>
        <translation>Forcerad till</translation>
    </message>
    <message>
        <source>Release the chosen force: the program writes the variable again</source>
        <translation>Häv den valda forceringen: programmet skriver variabeln igen</translation>
    </message>
</context>
<context>
    <name>rs::ui::GatewayCommands</name>
    <message>
        <source>New &amp;Gateway...</source>
        <translation>Ny &amp;gateway...</translation>
    </message>
    <message>
        <source>Add a Pluto Gateway to the project&apos;s bus</source>
        <translation>Lägg till en Pluto Gateway på projektets buss</translation>
    </message>
    <message>
        <source>Remove Gate&amp;way...</source>
        <translation>Ta bort gate&amp;way...</translation>
    </message>
    <message>
        <source>New Gateway</source>
        <translation>Ny gateway</translation>
    </message>
    <message>
        <source>Every gateway node address 0-15 is in use.</source>
        <translation>Alla gatewaynodadresser 0-15 är upptagna.</translation>
    </message>
    <message>
        <source>A Pluto Gateway is a node of the Pluto bus that passes the Plutos&apos; data to a fieldbus. The Ethernet gateways (GATE-E1, GATE-E2) serve Modbus TCP while simulating.</source>
        <translation>En Pluto Gateway är en nod på Plutobussen som för Plutornas data vidare till en fältbuss. Ethernet-gatewayerna (GATE-E1, GATE-E2) betjänar Modbus TCP under simulering.</translation>
    </message>
    <message>
        <source>&amp;Type:</source>
        <translation>&amp;Typ:</translation>
    </message>
    <message>
        <source>&amp;Node address:</source>
        <translation>&amp;Nodadress:</translation>
    </message>
    <message>
        <source>New Gateway %1</source>
        <translation>Ny gateway %1</translation>
    </message>
    <message>
        <source>Remove Gateway</source>
        <translation>Ta bort gateway</translation>
    </message>
    <message>
        <source>Remove gateway %1 with its settings from the project? Units that receive its data keep their setting. Edit &gt; Undo brings it back.</source>
        <translation>Ta bort gateway %1 med dess inställningar från projektet? Enheter som tar emot dess data behåller sin inställning. Redigera &gt; Ångra tar tillbaka den.</translation>
    </message>
    <message>
        <source>Remove Gateway %1</source>
        <translation>Ta bort gateway %1</translation>
    </message>
</context>
<context>
    <name>rs::ui::GatewayPage</name>
    <message>
        <source>%1 (user block)</source>
        <translation>%1 (användarblock)</translation>
    </message>
    <message>
        <source>%1 Global data</source>
        <translation>%1 Globala data</translation>
    </message>
    <message>
        <source>&amp;Remove Gateway...</source>
        <translation>&amp;Ta bort gateway...</translation>
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
        <translation>Nodadress:</translation>
    </message>
    <message>
        <source>Set Gateway %1 Type</source>
        <translation>Ange typ för gateway %1</translation>
    </message>
    <message>
        <source>Data to Pluto</source>
        <translation>Data till Pluto</translation>
    </message>
    <message>
        <source>Packet &amp;%1</source>
        <translation>Paket &amp;%1</translation>
    </message>
    <message>
        <source>Enable Data to Pluto Packet %1</source>
        <translation>Aktivera Data till Pluto-paket %1</translation>
    </message>
    <message>
        <source>Disable Data to Pluto Packet %1</source>
        <translation>Inaktivera Data till Pluto-paket %1</translation>
    </message>
    <message>
        <source>Enabled:</source>
        <translation>Aktiverade:</translation>
    </message>
    <message>
        <source> ms</source>
        <translation> ms</translation>
    </message>
    <message>
        <source>&amp;Cycle time:</source>
        <translation>&amp;Cykeltid:</translation>
    </message>
    <message>
        <source>Set Gateway %1 Cycle Time</source>
        <translation>Ange cykeltid för gateway %1</translation>
    </message>
    <message>
        <source>No timeout</source>
        <translation>Ingen timeout</translation>
    </message>
    <message>
        <source>T&amp;imeout:</source>
        <translation>T&amp;imeout:</translation>
    </message>
    <message>
        <source>Set Gateway %1 Timeout</source>
        <translation>Ange timeout för gateway %1</translation>
    </message>
    <message>
        <source>Expected nodes</source>
        <translation>Förväntade noder</translation>
    </message>
    <message>
        <source>Set Gateway %1 Expected Nodes</source>
        <translation>Ange förväntade noder för gateway %1</translation>
    </message>
    <message>
        <source>Additional data areas</source>
        <translation>Extra dataområden</translation>
    </message>
    <message>
        <source>Area</source>
        <translation>Område</translation>
    </message>
    <message>
        <source>Pluto</source>
        <translation>Pluto</translation>
    </message>
    <message>
        <source>IO-type</source>
        <translation>IO-typ</translation>
    </message>
    <message>
        <source>Set Additional Data Area %1</source>
        <translation>Ange extra dataområde %1</translation>
    </message>
    <message>
        <source>Gateway %1 (%2)</source>
        <translation>Gateway %1 (%2)</translation>
    </message>
    <message>
        <source>A node of the Pluto bus that passes the Plutos&apos; data to a fieldbus and takes data to them back (Gateway manual). Project %1.</source>
        <translation>En nod på Plutobussen som för Plutornas data vidare till en fältbuss och tar data tillbaka till dem (Gateway-manualen). Projekt %1.</translation>
    </message>
    <message>
        <source>0 or %1-%2 ms on %3</source>
        <translation>0 eller %1-%2 ms på %3</translation>
    </message>
    <message>
        <source>0-%1 ms</source>
        <translation>0-%1 ms</translation>
    </message>
    <message>
        <source>Not used</source>
        <translation>Används inte</translation>
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
        <translation>Data</translation>
    </message>
    <message>
        <source>Hex</source>
        <translation>Hex</translation>
    </message>
    <message>
        <source>Bits 31..0</source>
        <translation>Bitar 31..0</translation>
    </message>
    <message>
        <source>Modbus TCP is not served.</source>
        <translation>Modbus TCP betjänas inte.</translation>
    </message>
    <message>
        <source>Serving Modbus TCP on %1; no client is connected.</source>
        <translation>Betjänar Modbus TCP på %1; ingen klient är ansluten.</translation>
    </message>
    <message>
        <source>Serving Modbus TCP on %1; clients: %2.</source>
        <translation>Betjänar Modbus TCP på %1; klienter: %2.</translation>
    </message>
    <message>
        <source>Gateway %1 (%2)</source>
        <translation>Gateway %1 (%2)</translation>
    </message>
    <message>
        <source>Node status</source>
        <translation>Nodstatus</translation>
    </message>
    <message>
        <source>Additional data %1 (Pluto %2, IO-type %3)</source>
        <translation>Extra data %1 (Pluto %2, IO-typ %3)</translation>
    </message>
    <message>
        <source>Data to Pluto %1</source>
        <translation>Data till Pluto %1</translation>
    </message>
    <message>
        <source>valid; register 0 = %1, register 1 = %2</source>
        <translation>giltig; register 0 = %1, register 1 = %2</translation>
    </message>
    <message>
        <source>not valid</source>
        <translation>ogiltig</translation>
    </message>
</context>
<context>
    <name>rs::ui::IoOptionsPage</name>
    <message>
        <source>Failsafe inputs</source>
        <translation>Felsäkra ingångar</translation>
    </message>
    <message>
        <source>Failsafe inputs / non-failsafe outputs</source>
        <translation>Felsäkra ingångar / icke felsäkra utgångar</translation>
    </message>
    <message>
        <source>Analogue inputs</source>
        <translation>Analoga ingångar</translation>
    </message>
    <message>
        <source>Safety outputs: test pulses</source>
        <translation>Säkerhetsutgångar: testpulser</translation>
    </message>
    <message>
        <source>Undefined</source>
        <translation>Odefinierad</translation>
    </message>
    <message>
        <source>Input</source>
        <translation>Ingång</translation>
    </message>
    <message>
        <source>Output</source>
        <translation>Utgång</translation>
    </message>
    <message>
        <source>Light button</source>
        <translation>Tryckknapp med lampa</translation>
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
        <translation>Räknare, upp</translation>
    </message>
    <message>
        <source>Counter, up/down</source>
        <translation>Räknare, upp/ned</translation>
    </message>
    <message>
        <source>Static</source>
        <translation>Statisk</translation>
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
        <translation>Alternativ</translation>
    </message>
    <message>
        <source>Type of signal</source>
        <translation>Signaltyp</translation>
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
        <translation>Konfigurationen måste stämma med kopplingen. Q0..Q3 finns inte med: de kan bara användas på ett sätt.</translation>
    </message>
    <message>
        <source>%1 — I/O Options</source>
        <translation>%1 — I/O-alternativ</translation>
    </message>
    <message>
        <source>Choose from the lists what each terminal is wired for; combinations the unit cannot take are not offered.</source>
        <translation>Välj i listorna vad varje plint är kopplad för; kombinationer som enheten inte klarar erbjuds inte.</translation>
    </message>
    <message>
        <source>Set I/O Options of %1</source>
        <translation>Ställ in I/O-alternativ för %1</translation>
    </message>
    <message>
        <source>Used by block</source>
        <translation>Används av block</translation>
    </message>
</context>
<context>
    <name>rs::ui::LadderPage</name>
    <message>
        <source>Block %1 is in %2; the F list offers it.</source>
        <translation>Block %1 finns i %2; F-listan erbjuder det.</translation>
    </message>
    <message>
        <source>Make Block %1</source>
        <translation>Gör block %1</translation>
    </message>
    <message>
        <source>The library %1 is not among the project&apos;s libraries.</source>
        <translation>Biblioteket %1 är inte bland projektets bibliotek.</translation>
    </message>
    <message>
        <source>The block could not be written: %1</source>
        <translation>Blocket kunde inte skrivas: %1</translation>
    </message>
    <message>
        <source>Make Block</source>
        <translation>Gör block</translation>
    </message>
    <message>
        <source>Save the project first: its blocks go to a library beside it.</source>
        <translation>Spara projektet först: dess block hamnar i ett bibliotek bredvid det.</translation>
    </message>
    <message>
        <source>A block cannot hold a block: leave block networks out of the selection.</source>
        <translation>Ett block kan inte innehålla ett block: lämna blocknätverk utanför markeringen.</translation>
    </message>
    <message>
        <source>Make Block takes networks of one step.</source>
        <translation>Gör block tar nätverk ur ett steg.</translation>
    </message>
    <message>
        <source>Update Block %1</source>
        <translation>Uppdatera block %1</translation>
    </message>
    <message>
        <source>Select a block made by another version of its block to update it.</source>
        <translation>Markera ett block gjort av en annan version av sitt block för att uppdatera det.</translation>
    </message>
    <message>
        <source>Change Block Pins</source>
        <translation>Ändra blockets anslutningar</translation>
    </message>
    <message>
        <source>No library of the project has this block: add its library on the project page to bind its pins.</source>
        <translation>Inget av projektets bibliotek har detta block: lägg till dess bibliotek på projektsidan för att koppla dess anslutningar.</translation>
    </message>
    <message>
        <source>Insert Block %1</source>
        <translation>Infoga block %1</translation>
    </message>
    <message>
        <source>Made by %1 version %2; the library has version %3 (Update Block).</source>
        <translation>Gjort av %1 version %2; biblioteket har version %3 (Uppdatera block).</translation>
    </message>
    <message>
        <source>%1 — PLC Code</source>
        <translation>%1 — PLC-kod</translation>
    </message>
    <message>
        <source>%1 — Sequence %2</source>
        <translation>%1 — Sekvens %2</translation>
    </message>
    <message>
        <source>The project changed, so the network&apos;s edits were dropped.</source>
        <translation>Projektet ändrades, så nätverkets ändringar kastades.</translation>
    </message>
    <message>
        <source>Step %1</source>
        <translation>Steg %1</translation>
    </message>
    <message>
        <source>Not done: %1</source>
        <translation>Inte utfört: %1</translation>
    </message>
    <message>
        <source>Insert %1</source>
        <translation>Infoga %1</translation>
    </message>
    <message>
        <source>A network starts with its output: insert a coil, latch, jump or arithmetic box first, then its contacts.</source>
        <translation>Ett nätverk börjar med sin utgång: infoga först en spole, sättande/återställande spole, ett hopp eller en aritmetikbox, sedan dess kontakter.</translation>
    </message>
    <message>
        <source>Change Element</source>
        <translation>Ändra element</translation>
    </message>
    <message>
        <source>Change Output</source>
        <translation>Ändra utgång</translation>
    </message>
    <message>
        <source>Delete Element</source>
        <translation>Ta bort element</translation>
    </message>
    <message>
        <source>Delete Output</source>
        <translation>Ta bort utgång</translation>
    </message>
    <message>
        <source>This sequence has no step yet.</source>
        <translation>Sekvensen har inget steg än.</translation>
    </message>
    <message>
        <source>New network: insert its output first (L coil, S set, R reset, J jump ...).</source>
        <translation>Nytt nätverk: infoga först dess utgång (L spole, S sätt, R återställ, J hopp …).</translation>
    </message>
    <message>
        <source>Options stand at the start of the PLC code: open the PLC Code page.</source>
        <translation>Alternativ står i början av PLC-koden: öppna sidan PLC-kod.</translation>
    </message>
    <message>
        <source>New Config Option</source>
        <translation>Nytt konfigurationsalternativ</translation>
    </message>
    <message>
        <source>Change Config Option</source>
        <translation>Ändra konfigurationsalternativ</translation>
    </message>
    <message>
        <source>Enable Option</source>
        <translation>Aktivera alternativ</translation>
    </message>
    <message>
        <source>Disable Option</source>
        <translation>Inaktivera alternativ</translation>
    </message>
    <message numerus="yes">
        <source>%n network(s) copied.</source>
        <translation>
            <numerusform>%n nätverk kopierat.</numerusform>
            <numerusform>%n nätverk kopierade.</numerusform>
        </translation>
    </message>
    <message>
        <source>The clipboard holds no networks.</source>
        <translation>Urklipp innehåller inga nätverk.</translation>
    </message>
    <message>
        <source>The clipboard holds no networks: %1</source>
        <translation>Urklipp innehåller inga nätverk: %1</translation>
    </message>
    <message numerus="yes">
        <source>Paste %n Network(s)</source>
        <translation>
            <numerusform>Klistra in %n nätverk</numerusform>
            <numerusform>Klistra in %n nätverk</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Delete %n Network(s)</source>
        <translation>
            <numerusform>Ta bort %n nätverk</numerusform>
            <numerusform>Ta bort %n nätverk</numerusform>
        </translation>
    </message>
    <message>
        <source>Insert the network&apos;s output before its comment.</source>
        <translation>Infoga nätverkets utgång före dess kommentar.</translation>
    </message>
    <message>
        <source>Comment Network %1</source>
        <translation>Kommentera nätverk %1</translation>
    </message>
    <message>
        <source>Step Comment</source>
        <translation>Stegkommentar</translation>
    </message>
    <message>
        <source>Comment of step %1:</source>
        <translation>Kommentar till steg %1:</translation>
    </message>
    <message>
        <source>Comment Step %1</source>
        <translation>Kommentera steg %1</translation>
    </message>
    <message>
        <source>New Step of Sequence %1</source>
        <translation>Nytt steg i sekvens %1</translation>
    </message>
    <message>
        <source>Step %1 added: insert the output of its first network.</source>
        <translation>Steg %1 tillagt: infoga utgången i dess första nätverk.</translation>
    </message>
    <message>
        <source>Edit Network %1</source>
        <translation>Redigera nätverk %1</translation>
    </message>
    <message>
        <source>Network %1 updated.</source>
        <translation>Nätverk %1 uppdaterat.</translation>
    </message>
    <message>
        <source>The edits of network %1 were dropped.</source>
        <translation>Ändringarna i nätverk %1 kastades.</translation>
    </message>
    <message>
        <source>Not moved: %1</source>
        <translation>Inte flyttat: %1</translation>
    </message>
    <message>
        <source>Move Element</source>
        <translation>Flytta element</translation>
    </message>
    <message>
        <source>Export PDF</source>
        <translation>Exportera PDF</translation>
    </message>
    <message>
        <source>PDF documents (*.pdf)</source>
        <translation>PDF-dokument (*.pdf)</translation>
    </message>
    <message>
        <source>Exported to %1.</source>
        <translation>Exporterat till %1.</translation>
    </message>
    <message>
        <source>Network %1</source>
        <translation>Nätverk %1</translation>
    </message>
    <message>
        <source>No networks in this code.</source>
        <translation>Inga nätverk i den här koden.</translation>
    </message>
    <message>
        <source>This code has %1 lines, more than the ladder page draws (%2).
Its text page (F6) shows and edits it.</source>
        <translation>Den här koden har %1 rader, fler än stegdiagramsidan ritar (%2).
Dess textsida (F6) visar och redigerar den.</translation>
    </message>
    <message>
        <source>Could not export to %1.</source>
        <translation>Kunde inte exportera till %1.</translation>
    </message>
    <message>
        <source>Could not export to %1: %2</source>
        <translation>Kunde inte exportera till %1: %2</translation>
    </message>
    <message>
        <source>Network %1 is in edit mode: Update (%2) keeps its edits as one step, Undo (%3) drops them.</source>
        <translation>Nätverk %1 är i redigeringsläge: Uppdatera (%2) behåller ändringarna som ett enda ändringssteg, Ångra (%3) kastar dem.</translation>
    </message>
    <message>
        <source>No networks yet. Press %1, or right-click &gt; New Network, then insert the network&apos;s output (L coil, S set, R reset, J jump ...) and its contacts.</source>
        <translation>Inga nätverk än. Tryck på %1, eller högerklicka &gt; Nytt nätverk, och infoga sedan nätverkets utgång (L spole, S sätt, R återställ, J hopp …) och dess kontakter.</translation>
    </message>
    <message>
        <source>Simulating: a click or %1 on an input toggles it; a right click or %2 forces any element&apos;s variable. Editing ends the simulation.</source>
        <translation>Simulerar: ett klick eller %1 på en ingång växlar den; högerklick eller %2 forcerar variabeln för valfritt element. Redigering avslutar simuleringen.</translation>
    </message>
    <message>
        <source>Keys: %1 insert the toolbar&apos;s elements; %2 %3 %4 before, after, parallel; %5 properties; %6 delete; %7 new network; %8 edit mode.</source>
        <translation>Tangenter: %1 infogar verktygsfältets element; %2 %3 %4 före, efter, parallellt; %5 egenskaper; %6 ta bort; %7 nytt nätverk; %8 redigeringsläge.</translation>
    </message>
    <message>
        <source>Select a block network whose block a library of the project has.</source>
        <translation>Välj ett blocknätverk vars block finns i ett av projektets bibliotek.</translation>
    </message>
    <message>
        <source>%1 did not run: its step is not active</source>
        <translation>%1 kördes inte: dess steg är inte aktivt</translation>
    </message>
    <message>
        <source>%1 is true</source>
        <translation>%1 är sant</translation>
    </message>
    <message>
        <source>%1 is false</source>
        <translation>%1 är falskt</translation>
    </message>
    <message>
        <source>%1 is on</source>
        <translation>%1 är till</translation>
    </message>
    <message>
        <source>%1 is off</source>
        <translation>%1 är från</translation>
    </message>
    <message>
        <source>%1 is open</source>
        <translation>%1 är öppen</translation>
    </message>
    <message>
        <source>%1 is on through %2</source>
        <translation>%1 är till genom %2</translation>
    </message>
    <message>
        <source>%1 is off: %2</source>
        <translation>%1 är från: %2</translation>
    </message>
    <message>
        <source>%1 is forced on; its rung is off: %2</source>
        <translation>%1 är forcerad till; dess strömväg är från: %2</translation>
    </message>
    <message>
        <source>%1 is on; its rung is off: %2</source>
        <translation>%1 är till; dess strömväg är från: %2</translation>
    </message>
    <message>
        <source>%1 is forced off; its rung is on</source>
        <translation>%1 är forcerad från; dess strömväg är till</translation>
    </message>
    <message>
        <source>%1 is off; its rung is on</source>
        <translation>%1 är från; dess strömväg är till</translation>
    </message>
    <message>
        <source>%1 is forced off; its rung is on through %2</source>
        <translation>%1 är forcerad från; dess strömväg är till genom %2</translation>
    </message>
    <message>
        <source>%1 is off; its rung is on through %2</source>
        <translation>%1 är från; dess strömväg är till genom %2</translation>
    </message>
    <message>
        <source>&amp;Comment of network %1:</source>
        <translation>&amp;Kommentar till nätverk %1:</translation>
    </message>
    <message>
        <source>Not copied: %1</source>
        <translation>Inte kopierat: %1</translation>
    </message>
    <message>
        <source>Copy Element</source>
        <translation>Kopiera element</translation>
    </message>
    <message>
        <source>Moving: drop it before or after an element. Release Shift to copy.</source>
        <translation>Flyttar: släpp det före eller efter ett element. Släpp Skift för att kopiera.</translation>
    </message>
    <message>
        <source>Copying: drop it before or after an element. Hold Shift to move.</source>
        <translation>Kopierar: släpp det före eller efter ett element. Håll ned Skift för att flytta.</translation>
    </message>
    <message>
        <source>Password protected, open with permission to configure: a click or %1 on a Config Option&apos;s box checks or unchecks it; nothing else can change.</source>
        <translation>Lösenordsskyddat, öppnat med behörighet att konfigurera: ett klick eller %1 på ett konfigurationsalternativs ruta markerar eller avmarkerar det; inget annat kan ändras.</translation>
    </message>
</context>
<context>
    <name>rs::ui::MainWindow</name>
    <message>
        <source>&amp;Undo</source>
        <translation>&amp;Ångra</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>&amp;Gör om</translation>
    </message>
    <message>
        <source>Cu&amp;t</source>
        <translation>Klipp &amp;ut</translation>
    </message>
    <message>
        <source>&amp;Copy</source>
        <translation>&amp;Kopiera</translation>
    </message>
    <message>
        <source>&amp;Paste</source>
        <translation>Klistra &amp;in</translation>
    </message>
    <message>
        <source>Select &amp;All</source>
        <translation>Markera &amp;allt</translation>
    </message>
    <message>
        <source>&amp;Format Document</source>
        <translation>&amp;Formatera dokument</translation>
    </message>
    <message>
        <source>Rewrite the text in the canonical layout</source>
        <translation>Skriv om texten i kanonisk form</translation>
    </message>
    <message>
        <source>&amp;About Rungsmith</source>
        <translation>&amp;Om Rungsmith</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Arkiv</translation>
    </message>
    <message>
        <source>Open &amp;Recent</source>
        <translation>&amp;Öppna senaste</translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation>&amp;Redigera</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Visa</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>&amp;Hjälp</translation>
    </message>
    <message>
        <source>Problems</source>
        <translation>Problem</translation>
    </message>
    <message>
        <source>Line %1, Column %2</source>
        <translation>Rad %1, kolumn %2</translation>
    </message>
    <message numerus="yes">
        <source>%n error(s)</source>
        <translation>
            <numerusform>%n fel</numerusform>
            <numerusform>%n fel</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n warning(s)</source>
        <translation>
            <numerusform>%n varning</numerusform>
            <numerusform>%n varningar</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Not formatted: the text has %n error(s).</source>
        <translation>
            <numerusform>Inte formaterad: texten har %n fel.</numerusform>
            <numerusform>Inte formaterad: texten har %n fel.</numerusform>
        </translation>
    </message>
    <message>
        <source>Formatted.</source>
        <translation>Formaterad.</translation>
    </message>
    <message>
        <source>About Rungsmith</source>
        <translation>Om Rungsmith</translation>
    </message>
    <message>
        <source>The project reads without errors now; its pages are back.</source>
        <translation>Projektet läses nu utan fel; dess sidor är tillbaka.</translation>
    </message>
    <message>
        <source>&amp;Save Project</source>
        <translation>&amp;Spara projekt</translation>
    </message>
    <message>
        <source>Save Project &amp;As...</source>
        <translation>Spara projekt &amp;som …</translation>
    </message>
    <message>
        <source>&amp;Close Project</source>
        <translation>S&amp;täng projekt</translation>
    </message>
    <message>
        <source>Pr&amp;eferences...</source>
        <translation>In&amp;ställningar …</translation>
    </message>
    <message>
        <source>New &amp;Pluto...</source>
        <translation>Ny &amp;Pluto …</translation>
    </message>
    <message>
        <source>New &amp;Sequence...</source>
        <translation>Ny s&amp;ekvens …</translation>
    </message>
    <message>
        <source>&amp;Remove Pluto...</source>
        <translation>&amp;Ta bort Pluto …</translation>
    </message>
    <message>
        <source>&amp;Compile</source>
        <translation>&amp;Kompilera</translation>
    </message>
    <message>
        <source>Check the project and write the compiled file (.hps)</source>
        <translation>Kontrollera projektet och skriv den kompilerade filen (.hps)</translation>
    </message>
    <message>
        <source>&amp;Export</source>
        <translation>&amp;Exportera</translation>
    </message>
    <message>
        <source>&amp;Project</source>
        <translation>&amp;Projekt</translation>
    </message>
    <message>
        <source>&amp;Build</source>
        <translation>&amp;Bygg</translation>
    </message>
    <message>
        <source>Main</source>
        <translation>Huvud</translation>
    </message>
    <message>
        <source>Projects</source>
        <translation>Projekt</translation>
    </message>
    <message>
        <source>Output</source>
        <translation>Utdata</translation>
    </message>
    <message>
        <source>Code With Errors</source>
        <translation>Kod med fel</translation>
    </message>
    <message>
        <source>The code of Pluto %1 has errors, so it cannot be read into the project.</source>
        <translation>Koden för Pluto %1 har fel, så den kan inte läsas in i projektet.</translation>
    </message>
    <message>
        <source>Keep editing to fix them, or discard the changes since the code last read without errors.</source>
        <translation>Fortsätt redigera för att rätta dem, eller kasta ändringarna sedan koden senast lästes utan fel.</translation>
    </message>
    <message>
        <source>&amp;Keep Editing</source>
        <translation>&amp;Fortsätt redigera</translation>
    </message>
    <message>
        <source>&amp;Undo %1</source>
        <translation>&amp;Ångra %1</translation>
    </message>
    <message>
        <source>&amp;Redo %1</source>
        <translation>&amp;Gör om %1</translation>
    </message>
    <message>
        <source>Export Program &amp;Text...</source>
        <translation>Exportera program&amp;text …</translation>
    </message>
    <message>
        <source>&amp;Import Variable Names to Pluto...</source>
        <translation>&amp;Importera variabelnamn till Pluto …</translation>
    </message>
    <message>
        <source>E&amp;xport Variable Names from Pluto...</source>
        <translation>E&amp;xportera variabelnamn från Pluto …</translation>
    </message>
    <message>
        <source>&amp;Remanent Variables...</source>
        <translation>&amp;Remanenta variabler …</translation>
    </message>
    <message>
        <source>&amp;Ladder or Text</source>
        <translation>&amp;Stegdiagram eller text</translation>
    </message>
    <message>
        <source>Show the code as ladder networks or as text</source>
        <translation>Visa koden som stegdiagramnätverk eller som text</translation>
    </message>
    <message>
        <source>&lt;h3&gt;Rungsmith %1&lt;/h3&gt;&lt;p&gt;An IDE for Pluto safety PLCs: projects, units, I/O options, variables and the program as ladder and as text, checked, compiled and simulated.&lt;/p&gt;&lt;p&gt;Built with Qt %2 and QScintilla %3.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;Rungsmith %1&lt;/h3&gt;&lt;p&gt;En utvecklingsmiljö för Pluto säkerhets-PLC: projekt, enheter, I/O-alternativ, variabler och programmet som stegdiagram och som text, kontrollerat, kompilerat och simulerat.&lt;/p&gt;&lt;p&gt;Byggd med Qt %2 och QScintilla %3.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Avsluta</translation>
    </message>
    <message>
        <source>Compile</source>
        <translation>Kompilera</translation>
    </message>
    <message>
        <source>%1 has changes that are not saved.</source>
        <translation>%1 har ändringar som inte är sparade.</translation>
    </message>
    <message>
        <source>The compiled file (.hps) is written beside the project and must come from the saved file. Save first, or only check the changes without writing the compiled file.</source>
        <translation>Den kompilerade filen (.hps) skrivs bredvid projektet och måste komma från den sparade filen. Spara först, eller kontrollera bara ändringarna utan att skriva den kompilerade filen.</translation>
    </message>
    <message>
        <source>&amp;Save and Compile</source>
        <translation>&amp;Spara och kompilera</translation>
    </message>
    <message>
        <source>C&amp;heck Only</source>
        <translation>&amp;Kontrollera bara</translation>
    </message>
    <message>
        <source>Mark as &amp;Validated...</source>
        <translation>Markera som &amp;validerat …</translation>
    </message>
    <message>
        <source>Record this version&apos;s program signatures as the validated baseline</source>
        <translation>Spara den här versionens programsignaturer som den validerade baslinjen</translation>
    </message>
    <message>
        <source>%1 is marked as validated.</source>
        <translation>%1 är markerat som validerat.</translation>
    </message>
    <message>
        <source>Compare &amp;With...</source>
        <translation>&amp;Jämför med …</translation>
    </message>
    <message>
        <source>What differs between another version of the project and this one, network by network</source>
        <translation>Vad som skiljer en annan version av projektet från den här, nätverk för nätverk</translation>
    </message>
    <message>
        <source>Compare With</source>
        <translation>Jämför med</translation>
    </message>
    <message>
        <source>Rungsmith projects (*.sps)</source>
        <translation>Rungsmith-projekt (*.sps)</translation>
    </message>
    <message>
        <source>Compare With Va&amp;lidated</source>
        <translation>Jämför med va&amp;liderat</translation>
    </message>
    <message>
        <source>What changed since the project was marked as validated</source>
        <translation>Vad som har ändrats sedan projektet markerades som validerat</translation>
    </message>
    <message>
        <source>Merge Project (&amp;ignore conflicts)...</source>
        <translation>Sammanfoga projekt (&amp;ignorera konflikter) …</translation>
    </message>
    <message>
        <source>&amp;Merge Project...</source>
        <translation>Sa&amp;mmanfoga projekt …</translation>
    </message>
    <message>
        <source>%1 (read only)</source>
        <translation>%1 (skrivskyddat)</translation>
    </message>
    <message>
        <source>%1 (config options only)</source>
        <translation>%1 (endast konfigurationsalternativ)</translation>
    </message>
    <message>
        <source>New &amp;Gateway...</source>
        <translation>Ny &amp;gateway...</translation>
    </message>
    <message>
        <source>Remove Gate&amp;way...</source>
        <translation>Ta bort gate&amp;way...</translation>
    </message>
    <message>
        <source>Running %1 in the simulator.</source>
        <translation>Kör %1 i simulatorn.</translation>
    </message>
    <message>
        <source>&amp;Prove All</source>
        <translation>&amp;Bevisa alla</translation>
    </message>
    <message>
        <source>Prove every property of the project for every input sequence, or find one that breaks it</source>
        <translation>Bevisa varje egenskap i projektet för varje insignalsföljd, eller hitta en följd som bryter den</translation>
    </message>
</context>
<context>
    <name>rs::ui::MakeBlockDialog</name>
    <message>
        <source>The library file is a name of letters, digits and &apos;_&apos; in the project&apos;s folder, such as My_Blocks.rslib.</source>
        <translation>Biblioteksfilen är ett namn av bokstäver, siffror och &apos;_&apos; i projektets mapp, till exempel Mina_Block.rslib.</translation>
    </message>
    <message>
        <source>private memory</source>
        <translation>privat minne</translation>
    </message>
    <message>
        <source>Stands for</source>
        <translation>Står för</translation>
    </message>
    <message>
        <source>Pin or private variable</source>
        <translation>Anslutning eller privat variabel</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Namn</translation>
    </message>
    <message>
        <source>What the networks read becomes an input, what they write an output; a memory only they use becomes the block&apos;s own. Name the pins as the block&apos;s users will see them. Comments on the statements do not go into the block.</source>
        <translation>Det nätverken läser blir en ingång, det de skriver en utgång; ett minne som bara de använder blir blockets eget. Namnge anslutningarna som blockets användare ska se dem. Kommentarer på satserna följer inte med in i blocket.</translation>
    </message>
    <message>
        <source>&amp;Description:</source>
        <translation>&amp;Beskrivning:</translation>
    </message>
    <message>
        <source>&amp;Library file:</source>
        <translation>&amp;Biblioteksfil:</translation>
    </message>
    <message>
        <source>Block &amp;name:</source>
        <translation>Block&amp;namn:</translation>
    </message>
    <message>
        <source>What the block does, for its users</source>
        <translation>Vad blocket gör, för dess användare</translation>
    </message>
    <message>
        <source>Make Block</source>
        <translation>Gör block</translation>
    </message>
</context>
<context>
    <name>rs::ui::MarkValidatedDialog</name>
    <message>
        <source>Mark as Validated</source>
        <translation>Markera som validerat</translation>
    </message>
    <message>
        <source>Records this version&apos;s program signatures as the validated baseline: from now on the review says what changed since. It changes nothing the units do.</source>
        <translation>Sparar den här versionens programsignaturer som den validerade baslinjen: från och med nu säger granskningen vad som har ändrats sedan dess. Det ändrar inget som enheterna gör.</translation>
    </message>
    <message>
        <source>Validated &amp;by:</source>
        <translation>Validerat &amp;av:</translation>
    </message>
    <message>
        <source>&amp;Comment:</source>
        <translation>&amp;Kommentar:</translation>
    </message>
    <message>
        <source>&amp;Mark as Validated</source>
        <translation>&amp;Markera som validerat</translation>
    </message>
    <message numerus="yes">
        <source>The project has %n error(s) and cannot be validated. Build &gt; Compile (F7) lists them.</source>
        <translation>
            <numerusform>Projektet har %n fel och kan inte valideras. Bygg &gt; Kompilera (F7) listar det.</numerusform>
            <numerusform>Projektet har %n fel och kan inte valideras. Bygg &gt; Kompilera (F7) listar dem.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>rs::ui::NetworkCommentDialog</name>
    <message>
        <source>Network Comment</source>
        <translation>Nätverkskommentar</translation>
    </message>
    <message>
        <source>Return starts a new line; Ctrl+Return confirms.</source>
        <translation>Retur börjar en ny rad; Ctrl+Retur bekräftar.</translation>
    </message>
</context>
<context>
    <name>rs::ui::NewProjectDialog</name>
    <message>
        <source>New project</source>
        <translation>Nytt projekt</translation>
    </message>
    <message>
        <source>&amp;Include source code in compiled file</source>
        <translation>&amp;Inkludera källkoden i den kompilerade filen</translation>
    </message>
    <message>
        <source>New Project</source>
        <translation>Nytt projekt</translation>
    </message>
    <message>
        <source>For your own notes</source>
        <translation>För dina egna anteckningar</translation>
    </message>
    <message>
        <source>The project name is downloaded to the units and checked when going online. With the source code included, a program uploaded from a unit can be opened again; the file grows and anyone with the password can change the program.</source>
        <translation>Projektnamnet laddas ned till enheterna och kontrolleras vid uppkoppling. Med källkoden inkluderad kan ett program som laddats upp från en enhet öppnas igen; filen blir större och alla som har lösenordet kan ändra programmet.</translation>
    </message>
    <message>
        <source>Project &amp;name:</source>
        <translation>Projekt&amp;namn:</translation>
    </message>
    <message>
        <source>Project &amp;description:</source>
        <translation>Projekt&amp;beskrivning:</translation>
    </message>
    <message>
        <source>Pluto safety PLCs (1 to 32 units on one bus)</source>
        <translation>Pluto säkerhets-PLC (1 till 32 enheter på en buss)</translation>
    </message>
    <message>
        <source>Pixsys PL110 (one ladder PLC)</source>
        <translation>Pixsys PL110 (en PLC med stegdiagram)</translation>
    </message>
    <message>
        <source>&amp;Target:</source>
        <translation>&amp;Mål:</translation>
    </message>
</context>
<context>
    <name>rs::ui::NewUnitDialog</name>
    <message>
        <source>New Pluto</source>
        <translation>Ny Pluto</translation>
    </message>
    <message>
        <source>Choose the Pluto type and a station number that no other unit of the project has. The station number is part of every address of the unit: inputs of Pluto 1 are I1.0, I1.1, ...</source>
        <translation>Välj Pluto-typ och ett stationsnummer som ingen annan enhet i projektet har. Stationsnumret ingår i varje adress för enheten: ingångarna i Pluto 1 är I1.0, I1.1, …</translation>
    </message>
</context>
<context>
    <name>rs::ui::OpenProjects</name>
    <message>
        <source>Pluto projects (*.sps);;All files (*)</source>
        <translation>Pluto-projekt (*.sps);;Alla filer (*)</translation>
    </message>
    <message>
        <source>&amp;New Project...</source>
        <translation>&amp;Nytt projekt …</translation>
    </message>
    <message>
        <source>Start a new project</source>
        <translation>Starta ett nytt projekt</translation>
    </message>
    <message>
        <source>&amp;Open Project...</source>
        <translation>Ö&amp;ppna projekt …</translation>
    </message>
    <message>
        <source>Open a project file</source>
        <translation>Öppna en projektfil</translation>
    </message>
    <message>
        <source>&amp;Save Project</source>
        <translation>&amp;Spara projekt</translation>
    </message>
    <message>
        <source>Save the project</source>
        <translation>Spara projektet</translation>
    </message>
    <message>
        <source>Save Project &amp;As...</source>
        <translation>Spara projekt &amp;som …</translation>
    </message>
    <message>
        <source>Save the project under a new name</source>
        <translation>Spara projektet under ett nytt namn</translation>
    </message>
    <message>
        <source>Save A&amp;ll</source>
        <translation>Spara a&amp;lla</translation>
    </message>
    <message>
        <source>Save every open project</source>
        <translation>Spara alla öppna projekt</translation>
    </message>
    <message>
        <source>&amp;Close Project</source>
        <translation>S&amp;täng projekt</translation>
    </message>
    <message>
        <source>Close the project</source>
        <translation>Stäng projektet</translation>
    </message>
    <message>
        <source>&amp;Program Text...</source>
        <translation>&amp;Programtext …</translation>
    </message>
    <message>
        <source>Write the program in the language alone, for a text editor or the original compiler</source>
        <translation>Skriv programmet enbart i språket, för en textredigerare eller den ursprungliga kompilatorn</translation>
    </message>
    <message>
        <source>Open &amp;Example Project</source>
        <translation>Öppna &amp;exempelprojekt</translation>
    </message>
    <message>
        <source>&amp;Clear Menu</source>
        <translation>&amp;Töm menyn</translation>
    </message>
    <message>
        <source>Opened %1. It has errors: fix them in its text.</source>
        <translation>Öppnade %1. Den har fel: rätta dem i dess text.</translation>
    </message>
    <message>
        <source>Opened %1</source>
        <translation>Öppnade %1</translation>
    </message>
    <message>
        <source>Open Project</source>
        <translation>Öppna projekt</translation>
    </message>
    <message>
        <source>Could not open “%1”.</source>
        <translation>Kunde inte öppna ”%1”.</translation>
    </message>
    <message>
        <source>Save Project</source>
        <translation>Spara projekt</translation>
    </message>
    <message>
        <source>The code of Pluto %1 has errors, so your last changes to it are not part of the project. Save the project without them?</source>
        <translation>Koden för Pluto %1 har fel, så dina senaste ändringar i den ingår inte i projektet. Spara projektet utan dem?</translation>
    </message>
    <message>
        <source>Save Project As</source>
        <translation>Spara projekt som</translation>
    </message>
    <message>
        <source>Could not save “%1”.</source>
        <translation>Kunde inte spara ”%1”.</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>Sparade %1</translation>
    </message>
    <message>
        <source>Unsaved Changes</source>
        <translation>Osparade ändringar</translation>
    </message>
    <message>
        <source>“%1” has changes that are not saved. Save them?</source>
        <translation>”%1” har ändringar som inte är sparade. Spara dem?</translation>
    </message>
    <message>
        <source>Export Program Text</source>
        <translation>Exportera programtext</translation>
    </message>
    <message>
        <source>-program</source>
        <translation>-program</translation>
    </message>
    <message>
        <source>Wrote the program text to %1</source>
        <translation>Skrev programtexten till %1</translation>
    </message>
    <message>
        <source>Autosave failed: %1</source>
        <translation>Automatisk sparning misslyckades: %1</translation>
    </message>
    <message>
        <source>Recover Projects</source>
        <translation>Återställ projekt</translation>
    </message>
    <message>
        <source>Rungsmith was not closed properly. These projects have changes that were saved automatically:</source>
        <translation>Rungsmith stängdes inte på rätt sätt. De här projekten har ändringar som sparades automatiskt:</translation>
    </message>
    <message>
        <source>&amp;Recover</source>
        <translation>&amp;Återställ</translation>
    </message>
    <message>
        <source>Pass&amp;word Protect...</source>
        <translation>Lösen&amp;ordsskydda …</translation>
    </message>
    <message>
        <source>Protect the project with a password, change its protection or take it off</source>
        <translation>Skydda projektet med ett lösenord, ändra skyddet eller ta bort det</translation>
    </message>
    <message>
        <source>“%1” was changed outside Rungsmith after it was password protected.</source>
        <translation>”%1” har ändrats utanför Rungsmith efter att det lösenordsskyddades.</translation>
    </message>
    <message>
        <source>Password Protect</source>
        <translation>Lösenordsskydda</translation>
    </message>
    <message>
        <source>Protected with a password: saving writes the protection.</source>
        <translation>Skyddat med lösenord: skyddet skrivs när projektet sparas.</translation>
    </message>
    <message>
        <source>Remove Password Protection</source>
        <translation>Ta bort lösenordsskydd</translation>
    </message>
    <message>
        <source>The password protection is off once the project is saved.</source>
        <translation>Lösenordsskyddet är borta när projektet har sparats.</translation>
    </message>
    <message>
        <source>The first change is at line %1: the signature the password made does not cover it. The project opens read only; its protection is evidence of changes, not a lock, and the file stays readable text. The holder of the main password can accept the change once it is reviewed.</source>
        <translation>Den första ändringen finns på rad %1: signaturen som lösenordet gjorde täcker den inte. Projektet öppnas skrivskyddat; skyddet visar ändringar men låser inget, och filen förblir läsbar text. Den som har huvudlösenordet kan godta ändringen när den är granskad.</translation>
    </message>
    <message>
        <source>Open &amp;Read Only</source>
        <translation>Öppna &amp;skrivskyddat</translation>
    </message>
    <message>
        <source>&amp;Accept the Change...</source>
        <translation>&amp;Godta ändringen …</translation>
    </message>
    <message>
        <source>Opened %1 in a PL110 window</source>
        <translation>Öppnade %1 i ett PL110-fönster</translation>
    </message>
</context>
<context>
    <name>rs::ui::PasswordProtectDialog</name>
    <message>
        <source>&amp;Password protect source file</source>
        <translation>&amp;Lösenordsskydda källfilen</translation>
    </message>
    <message>
        <source>Change of config options</source>
        <translation>Ändring av konfigurationsalternativ</translation>
    </message>
    <message>
        <source>Only possible with &amp;main password</source>
        <translation>Endast möjlig med &amp;huvudlösenordet</translation>
    </message>
    <message>
        <source>Possible &amp;without password</source>
        <translation>Möjlig &amp;utan lösenord</translation>
    </message>
    <message>
        <source>Config &amp;options password required</source>
        <translation>Lösenord för konfigurationsal&amp;ternativ krävs</translation>
    </message>
    <message>
        <source>Password Protect</source>
        <translation>Lösenordsskydda</translation>
    </message>
    <message>
        <source>The file keeps no password: it keeps a signature only the password can make, so a change made outside Rungsmith shows. Anybody can still open and read the file.</source>
        <translation>Filen sparar inget lösenord, bara en signatur som endast lösenordet kan göra, så att en ändring gjord utanför Rungsmith syns. Vem som helst kan fortfarande öppna och läsa filen.</translation>
    </message>
    <message>
        <source>Ma&amp;in password:</source>
        <translation>Hu&amp;vudlösenord:</translation>
    </message>
    <message>
        <source>&amp;Repeat:</source>
        <translation>U&amp;pprepa:</translation>
    </message>
    <message>
        <source>Config options pa&amp;ssword:</source>
        <translation>Lö&amp;senord för konfigurationsalternativ:</translation>
    </message>
    <message>
        <source>R&amp;epeat:</source>
        <translation>Upp&amp;repa:</translation>
    </message>
    <message>
        <source>Give the main password.</source>
        <translation>Ange huvudlösenordet.</translation>
    </message>
    <message>
        <source>The main password and its repetition differ.</source>
        <translation>Huvudlösenordet och upprepningen skiljer sig åt.</translation>
    </message>
    <message>
        <source>Give the config options password.</source>
        <translation>Ange lösenordet för konfigurationsalternativen.</translation>
    </message>
    <message>
        <source>The config options password and its repetition differ.</source>
        <translation>Lösenordet för konfigurationsalternativen och upprepningen skiljer sig åt.</translation>
    </message>
    <message>
        <source>The config options password must differ from the main password, or it would give full permission.</source>
        <translation>Lösenordet för konfigurationsalternativen måste skilja sig från huvudlösenordet, annars skulle det ge full behörighet.</translation>
    </message>
</context>
<context>
    <name>rs::ui::PermissionNote</name>
    <message>
        <source>Password protected, open read only: nothing can change.</source>
        <translation>Lösenordsskyddat, öppnat skrivskyddat: inget kan ändras.</translation>
    </message>
    <message>
        <source>Password protected, open with permission to configure: only Config Options can change, on the ladder.</source>
        <translation>Lösenordsskyddat, öppnat med behörighet att konfigurera: bara konfigurationsalternativ kan ändras, i stegdiagrammet.</translation>
    </message>
</context>
<context>
    <name>rs::ui::Pl110Document</name>
    <message>
        <source>It is not a PL110 program: its first line is not “$target PL110”.</source>
        <translation>Det är inget PL110-program: dess första rad är inte ”$target PL110”.</translation>
    </message>
    <message>
        <source>Untitled</source>
        <translation>Namnlöst</translation>
    </message>
    <message>
        <source>The program has no file yet: use Save As.</source>
        <translation>Programmet har ingen fil än: använd Spara som.</translation>
    </message>
</context>
<context>
    <name>rs::ui::Pl110LadderView</name>
    <message>
        <source>INIT — runs once, before the first scan</source>
        <translation>INIT — körs en gång, före första cykeln</translation>
    </message>
    <message>
        <source>MAIN — runs every scan</source>
        <translation>MAIN — körs varje cykel</translation>
    </message>
    <message>
        <source>Rung %1</source>
        <translation>Steg %1</translation>
    </message>
    <message>
        <source>The program has no rungs yet: write them on the Program page.</source>
        <translation>Programmet har inga steg än: skriv dem på sidan Program.</translation>
    </message>
</context>
<context>
    <name>rs::ui::Pl110NamesPage</name>
    <message>
        <source>&amp;Import CSV...</source>
        <translation>&amp;Importera CSV …</translation>
    </message>
    <message>
        <source>Name addresses from a CSV file: Variable, Symbolic Name, Description</source>
        <translation>Namnge adresser från en CSV-fil: variabel, symboliskt namn, beskrivning</translation>
    </message>
    <message>
        <source>E&amp;xport CSV...</source>
        <translation>E&amp;xportera CSV …</translation>
    </message>
    <message>
        <source>Write the names and descriptions to a CSV file</source>
        <translation>Skriv namnen och beskrivningarna till en CSV-fil</translation>
    </message>
    <message>
        <source>Address</source>
        <translation>Adress</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Namn</translation>
    </message>
    <message>
        <source>Description</source>
        <translation>Beskrivning</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>Värde</translation>
    </message>
    <message>
        <source>Addresses</source>
        <translation>Adresser</translation>
    </message>
    <message>
        <source>Program writes</source>
        <translation>Programmet skriver</translation>
    </message>
    <message>
        <source>Modbus (word / bit)</source>
        <translation>Modbus (ord / bit)</translation>
    </message>
    <message>
        <source>What it holds</source>
        <translation>Innehåll</translation>
    </message>
    <message>
        <source>Names: double-click a cell to change it; the last row names another address.</source>
        <translation>Namn: dubbelklicka på en cell för att ändra den; sista raden namnger ytterligare en adress.</translation>
    </message>
    <message>
        <source>Memory areas of the PL110 (datasheet, section 2)</source>
        <translation>PL110:s minnesområden (datablad, avsnitt 2)</translation>
    </message>
    <message>
        <source>yes</source>
        <translation>ja</translation>
    </message>
    <message>
        <source>no</source>
        <translation>nej</translation>
    </message>
    <message>
        <source>–</source>
        <translation>–</translation>
    </message>
    <message>
        <source> (read only)</source>
        <translation> (endast läsning)</translation>
    </message>
    <message>
        <source>Type an address such as I6, Q4, M10 or VW20</source>
        <translation>Skriv en adress, till exempel I6, Q4, M10 eller VW20</translation>
    </message>
    <message>
        <source>%1 rewrites the program text; fix its errors on the Program page first, so that no line is lost.</source>
        <translation>%1 skriver om programtexten; rätta först dess fel på sidan Program, så att ingen rad går förlorad.</translation>
    </message>
    <message>
        <source>Naming</source>
        <translation>Namngivning</translation>
    </message>
    <message>
        <source>“%1” is not a PL110 address</source>
        <translation>”%1” är ingen PL110-adress</translation>
    </message>
    <message>
        <source>Name %1</source>
        <translation>Namnge %1</translation>
    </message>
    <message>
        <source>Import Names</source>
        <translation>Importera namn</translation>
    </message>
    <message>
        <source>CSV files (*.csv *.txt);;All files (*)</source>
        <translation>CSV-filer (*.csv *.txt);;Alla filer (*)</translation>
    </message>
    <message>
        <source>Importing names</source>
        <translation>Import av namn</translation>
    </message>
    <message numerus="yes">
        <source>Nothing was imported: %n row(s) could not be read.
%1</source>
        <translation>
            <numerusform>Inget importerades: %n rad kunde inte läsas.
%1</numerusform>
            <numerusform>Inget importerades: %n rader kunde inte läsas.
%1</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Imported %n name(s) from %1</source>
        <translation>
            <numerusform>Importerade %n namn från %1</numerusform>
            <numerusform>Importerade %n namn från %1</numerusform>
        </translation>
    </message>
    <message>
        <source>CSV, comma-separated (*.csv)</source>
        <translation>CSV, kommaseparerad (*.csv)</translation>
    </message>
    <message>
        <source>CSV, semicolon-separated, as spreadsheets in Swedish and German expect (*.csv)</source>
        <translation>CSV, semikolonseparerad, som kalkylprogram på svenska och tyska väntar sig (*.csv)</translation>
    </message>
    <message>
        <source>Export Names</source>
        <translation>Exportera namn</translation>
    </message>
    <message>
        <source>Exported the names to %1</source>
        <translation>Exporterade namnen till %1</translation>
    </message>
    <message>
        <source>Type a value to set the input or force the variable</source>
        <translation>Skriv ett värde för att sätta ingången eller tvångsstyra variabeln</translation>
    </message>
    <message>
        <source>Start the simulation to set values.</source>
        <translation>Starta simuleringen för att sätta värden.</translation>
    </message>
    <message>
        <source>“%1” is not a whole number</source>
        <translation>”%1” är inget heltal</translation>
    </message>
</context>
<context>
    <name>rs::ui::Pl110Simulation</name>
    <message>
        <source>The program changed: the simulation stopped. Start it again to run the new program.</source>
        <translation>Programmet ändrades: simuleringen stoppades. Starta den igen för att köra det nya programmet.</translation>
    </message>
    <message>
        <source>The program has errors; fix them to simulate it.</source>
        <translation>Programmet har fel; rätta dem för att simulera det.</translation>
    </message>
</context>
<context>
    <name>rs::ui::Pl110WaveformPanel</name>
    <message>
        <source>Add a variable to plot: an address or a name</source>
        <translation>Lägg till en variabel att rita: en adress eller ett namn</translation>
    </message>
    <message>
        <source>Export VCD</source>
        <translation>Exportera VCD</translation>
    </message>
    <message>
        <source>%1 is plotted already</source>
        <translation>%1 ritas redan</translation>
    </message>
    <message>
        <source>Nothing is recorded yet: start the simulation or run a scenario.</source>
        <translation>Inget är inspelat än: starta simuleringen eller kör ett scenario.</translation>
    </message>
    <message>
        <source>Value Change Dumps (*.vcd);;All files (*)</source>
        <translation>Value Change Dumps (*.vcd);;Alla filer (*)</translation>
    </message>
</context>
<context>
    <name>rs::ui::Pl110Window</name>
    <message>
        <source>error</source>
        <translation>fel</translation>
    </message>
    <message>
        <source>warning</source>
        <translation>varning</translation>
    </message>
    <message>
        <source>&amp;Ladder</source>
        <translation>Steg&amp;diagram</translation>
    </message>
    <message>
        <source>&amp;Names and Areas</source>
        <translation>&amp;Namn och områden</translation>
    </message>
    <message>
        <source>Problems</source>
        <translation>Problem</translation>
    </message>
    <message>
        <source>Scenario Results</source>
        <translation>Scenarioresultat</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Arkiv</translation>
    </message>
    <message>
        <source>&amp;New PL110 Program</source>
        <translation>&amp;Nytt PL110-program</translation>
    </message>
    <message>
        <source>New program</source>
        <translation>Nytt program</translation>
    </message>
    <message>
        <source>&amp;Open...</source>
        <translation>Ö&amp;ppna …</translation>
    </message>
    <message>
        <source>&amp;Save</source>
        <translation>&amp;Spara</translation>
    </message>
    <message>
        <source>Save &amp;As...</source>
        <translation>Spara s&amp;om …</translation>
    </message>
    <message>
        <source>&amp;Close</source>
        <translation>S&amp;täng</translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation>&amp;Redigera</translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation>&amp;Ångra</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>&amp;Gör om</translation>
    </message>
    <message>
        <source>&amp;Undo %1</source>
        <translation>&amp;Ångra %1</translation>
    </message>
    <message>
        <source>&amp;Redo %1</source>
        <translation>&amp;Gör om %1</translation>
    </message>
    <message>
        <source>&amp;Format Text</source>
        <translation>&amp;Formatera text</translation>
    </message>
    <message>
        <source>Write the program as the printer writes it: one space around operators, names as declared</source>
        <translation>Skriv programmet som skrivaren skriver det: ett mellanslag kring operatorer, namn som de deklarerats</translation>
    </message>
    <message>
        <source>Fix the errors first: formatting would drop the lines that do not read.</source>
        <translation>Rätta felen först: formateringen skulle ta bort raderna som inte kan läsas.</translation>
    </message>
    <message>
        <source>Format Text</source>
        <translation>Formatera text</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Visa</translation>
    </message>
    <message>
        <source>&amp;Program Text</source>
        <translation>&amp;Programtext</translation>
    </message>
    <message>
        <source>&amp;Simulation</source>
        <translation>&amp;Simulering</translation>
    </message>
    <message>
        <source>&amp;Start</source>
        <translation>&amp;Starta</translation>
    </message>
    <message>
        <source>Run the program on the simulated clock; click an input&apos;s contact to switch it</source>
        <translation>Kör programmet på den simulerade klockan; klicka på en ingångs kontakt för att slå om den</translation>
    </message>
    <message>
        <source>S&amp;top</source>
        <translation>S&amp;toppa</translation>
    </message>
    <message>
        <source>Hold the program and the clock; the state stays shown</source>
        <translation>Stoppa programmet och klockan; tillståndet visas kvar</translation>
    </message>
    <message>
        <source>Single S&amp;can</source>
        <translation>En &amp;cykel</translation>
    </message>
    <message>
        <source>&amp;Reset</source>
        <translation>Starta &amp;om</translation>
    </message>
    <message>
        <source>Power on again at time 0; inputs set and forces stay</source>
        <translation>Slå på igen vid tid 0; satta ingångar och tvångsstyrningar finns kvar</translation>
    </message>
    <message>
        <source>Run Sce&amp;nario...</source>
        <translation>Kör sce&amp;nario …</translation>
    </message>
    <message>
        <source>Run a scenario file (.scn) from power on and list its results</source>
        <translation>Kör en scenariofil (.scn) från tillslag och lista dess resultat</translation>
    </message>
    <message>
        <source>Simulation</source>
        <translation>Simulering</translation>
    </message>
    <message>
        <source>Typing</source>
        <translation>Skrivning</translation>
    </message>
    <message numerus="yes">
        <source>%n rung(s), no errors</source>
        <translation>
            <numerusform>%n steg, inga fel</numerusform>
            <numerusform>%n steg, inga fel</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n error(s): the ladder shows the lines that read</source>
        <translation>
            <numerusform>%n fel: stegdiagrammet visar raderna som kan läsas</numerusform>
            <numerusform>%n fel: stegdiagrammet visar raderna som kan läsas</numerusform>
        </translation>
    </message>
    <message>
        <source>%1[*] — PL110 — Rungsmith</source>
        <translation>%1[*] — PL110 — Rungsmith</translation>
    </message>
    <message>
        <source>Simulating: %1 s, scan %2</source>
        <translation>Simulerar: %1 s, cykel %2</translation>
    </message>
    <message>
        <source>Stopped at %1 s, scan %2</source>
        <translation>Stoppad vid %1 s, cykel %2</translation>
    </message>
    <message>
        <source>Start the simulation (F5) to switch inputs from the ladder.</source>
        <translation>Starta simuleringen (F5) för att slå om ingångar i stegdiagrammet.</translation>
    </message>
    <message>
        <source>%1 set to %2</source>
        <translation>%1 satt till %2</translation>
    </message>
    <message>
        <source>%1 forced to %2</source>
        <translation>%1 tvångsstyrd till %2</translation>
    </message>
    <message>
        <source>Set %1 to 1</source>
        <translation>Sätt %1 till 1</translation>
    </message>
    <message>
        <source>Force %1 to 1</source>
        <translation>Tvångsstyr %1 till 1</translation>
    </message>
    <message>
        <source>Set %1 to 0</source>
        <translation>Sätt %1 till 0</translation>
    </message>
    <message>
        <source>Force %1 to 0</source>
        <translation>Tvångsstyr %1 till 0</translation>
    </message>
    <message>
        <source>Let go of %1</source>
        <translation>Släpp %1</translation>
    </message>
    <message>
        <source>Release %1</source>
        <translation>Häv tvångsstyrning av %1</translation>
    </message>
    <message>
        <source>Show in Program Text</source>
        <translation>Visa i programtexten</translation>
    </message>
    <message>
        <source>Save</source>
        <translation>Spara</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>Sparade %1</translation>
    </message>
    <message>
        <source>Save PL110 Program As</source>
        <translation>Spara PL110-program som</translation>
    </message>
    <message>
        <source>PL110 programs (*.sps)</source>
        <translation>PL110-program (*.sps)</translation>
    </message>
    <message>
        <source>Save As</source>
        <translation>Spara som</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>Stäng</translation>
    </message>
    <message>
        <source>Save the changes to %1?</source>
        <translation>Spara ändringarna i %1?</translation>
    </message>
    <message>
        <source>Open PL110 Program</source>
        <translation>Öppna PL110-program</translation>
    </message>
    <message>
        <source>PL110 programs (*.sps);;All files (*)</source>
        <translation>PL110-program (*.sps);;Alla filer (*)</translation>
    </message>
    <message>
        <source>Open</source>
        <translation>Öppna</translation>
    </message>
    <message>
        <source>Could not open “%1”.</source>
        <translation>Kunde inte öppna ”%1”.</translation>
    </message>
    <message>
        <source>Run Scenario</source>
        <translation>Kör scenario</translation>
    </message>
    <message>
        <source>Scenarios (*.scn);;All files (*)</source>
        <translation>Scenarier (*.scn);;Alla filer (*)</translation>
    </message>
    <message>
        <source>%1: %2 passed, %3 failed</source>
        <translation>%1: %2 godkända, %3 underkända</translation>
    </message>
    <message>
        <source>%1 did not run: it has errors</source>
        <translation>%1 kördes inte: det har fel</translation>
    </message>
    <message>
        <source>&amp;New Rung...</source>
        <translation>&amp;Nytt steg …</translation>
    </message>
    <message>
        <source>Write a rung after the selected one: its output, &apos;=&apos; and its condition</source>
        <translation>Skriv ett steg efter det valda: dess utgång, ”=” och dess villkor</translation>
    </message>
    <message>
        <source>&amp;Edit...</source>
        <translation>&amp;Redigera …</translation>
    </message>
    <message>
        <source>Change the selected contact, or the selected rung as its line</source>
        <translation>Ändra den valda kontakten, eller det valda steget som sin rad</translation>
    </message>
    <message>
        <source>Contact &amp;After...</source>
        <translation>Kontakt &amp;efter …</translation>
    </message>
    <message>
        <source>Contact &amp;Before...</source>
        <translation>Kontakt &amp;före …</translation>
    </message>
    <message>
        <source>Contact in &amp;Parallel...</source>
        <translation>Kontakt &amp;parallellt …</translation>
    </message>
    <message>
        <source>&amp;Delete</source>
        <translation>Ta &amp;bort</translation>
    </message>
    <message>
        <source>Delete the selected element; with the output selected, the rung</source>
        <translation>Ta bort det valda elementet; med utgången vald, steget</translation>
    </message>
    <message>
        <source>Move Rung &amp;Up</source>
        <translation>Flytta steg &amp;upp</translation>
    </message>
    <message>
        <source>Move Rung Do&amp;wn</source>
        <translation>Flytta steg ne&amp;d</translation>
    </message>
    <message>
        <source>While simulating: switch the selected contact&apos;s input, or force its variable the other way</source>
        <translation>Under simulering: slå om den valda kontaktens ingång, eller tvångsstyr dess variabel åt andra hållet</translation>
    </message>
    <message>
        <source>Ladder or &amp;Text</source>
        <translation>Stegdiagram eller &amp;text</translation>
    </message>
    <message>
        <source>Switch between the ladder and the program text at the same rung</source>
        <translation>Växla mellan stegdiagrammet och programtexten vid samma steg</translation>
    </message>
    <message>
        <source>Fix the errors on the Program page first: the ladder&apos;s edits rewrite the text, and lines with errors would be lost.</source>
        <translation>Rätta först felen på sidan Program: ändringarna i stegdiagrammet skriver om texten, och rader med fel skulle gå förlorade.</translation>
    </message>
    <message>
        <source>%1 was not done: %2</source>
        <translation>%1 gjordes inte: %2</translation>
    </message>
    <message>
        <source>Column %1: %2</source>
        <translation>Kolumn %1: %2</translation>
    </message>
    <message>
        <source>New Rung</source>
        <translation>Nytt steg</translation>
    </message>
    <message>
        <source>The rung as its line is written: its output, &apos;=&apos; and its condition, for example Q1 = I1 * /I2</source>
        <translation>Steget som dess rad skrivs: dess utgång, ”=” och dess villkor, till exempel Q1 = I1 * /I2</translation>
    </message>
    <message>
        <source>Edit Rung</source>
        <translation>Redigera steg</translation>
    </message>
    <message>
        <source>The rung as its line is written: its output, &apos;=&apos; and its condition, and a comment after &apos;;&apos;</source>
        <translation>Steget som dess rad skrivs: dess utgång, ”=” och dess villkor, och en kommentar efter ”;”</translation>
    </message>
    <message>
        <source>Edit Element</source>
        <translation>Redigera element</translation>
    </message>
    <message>
        <source>The element as a rung writes it: a contact such as I3 or /I3, a comparison such as (VW1 &gt;= 10), NOT, P or N; several joined by * and + take its place together</source>
        <translation>Elementet som ett steg skriver det: en kontakt som I3 eller /I3, en jämförelse som (VW1 &gt;= 10), NOT, P eller N; flera, förenade med * och +, tar tillsammans dess plats</translation>
    </message>
    <message>
        <source>Contact in Parallel</source>
        <translation>Kontakt parallellt</translation>
    </message>
    <message>
        <source>Contact Before</source>
        <translation>Kontakt före</translation>
    </message>
    <message>
        <source>Contact After</source>
        <translation>Kontakt efter</translation>
    </message>
    <message>
        <source>A contact such as I3 or /I3, a comparison such as (VW1 &gt;= 10), NOT, P or N, or several joined by * and +</source>
        <translation>En kontakt som I3 eller /I3, en jämförelse som (VW1 &gt;= 10), NOT, P eller N, eller flera förenade med * och +</translation>
    </message>
    <message>
        <source>Delete Rung</source>
        <translation>Ta bort steg</translation>
    </message>
    <message>
        <source>Delete Element</source>
        <translation>Ta bort element</translation>
    </message>
    <message>
        <source>Move Rung Up</source>
        <translation>Flytta steg upp</translation>
    </message>
    <message>
        <source>Move Rung Down</source>
        <translation>Flytta steg ned</translation>
    </message>
    <message>
        <source>Ladder</source>
        <translation>Stegdiagram</translation>
    </message>
    <message>
        <source>Program</source>
        <translation>Program</translation>
    </message>
    <message>
        <source>Names and Areas</source>
        <translation>Namn och områden</translation>
    </message>
    <message>
        <source>T&amp;oggle</source>
        <translation>Väx&amp;la</translation>
    </message>
    <message>
        <source>Waveform</source>
        <translation>Vågform</translation>
    </message>
    <message>
        <source>Serve &amp;Modbus RTU</source>
        <translation>Betjäna &amp;Modbus RTU</translation>
    </message>
    <message>
        <source>Answer Modbus RTU requests on a pseudo-terminal, as the PL110&apos;s serial port, from the simulated memory (slave 1)</source>
        <translation>Besvara Modbus RTU-förfrågningar på en pseudoterminal, som PL110:s seriella port, ur det simulerade minnet (slav 1)</translation>
    </message>
    <message>
        <source>Modbus RTU: %1, slave 1</source>
        <translation>Modbus RTU: %1, slav 1</translation>
    </message>
    <message>
        <source>Plot in &amp;Waveform</source>
        <translation>Rita i &amp;vågform</translation>
    </message>
    <message>
        <source>Record the selected contact&apos;s or output&apos;s variable in the waveform</source>
        <translation>Spela in den valda kontaktens eller utgångens variabel i vågformen</translation>
    </message>
    <message>
        <source>%1 is plotted in the waveform</source>
        <translation>%1 ritas i vågformen</translation>
    </message>
    <message>
        <source>Autosave failed: %1</source>
        <translation>Automatisk sparning misslyckades: %1</translation>
    </message>
    <message>
        <source>New Rung in &amp;INIT...</source>
        <translation>Nytt steg i &amp;INIT …</translation>
    </message>
    <message>
        <source>Write a rung at the end of INIT, which runs once before the first scan</source>
        <translation>Skriv ett steg i slutet av INIT, som körs en gång före första cykeln</translation>
    </message>
    <message>
        <source>New Rung in INIT</source>
        <translation>Nytt steg i INIT</translation>
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
        <translation>Strukturerad post</translation>
    </message>
    <message>
        <source>Declaration</source>
        <translation>Deklaration</translation>
    </message>
    <message>
        <source>Declaration option</source>
        <translation>Deklarationsalternativ</translation>
    </message>
    <message>
        <source>Directive</source>
        <translation>Direktiv</translation>
    </message>
    <message>
        <source>Directive text</source>
        <translation>Direktivtext</translation>
    </message>
    <message>
        <source>Step header</source>
        <translation>Steghuvud</translation>
    </message>
    <message>
        <source>Address</source>
        <translation>Adress</translation>
    </message>
    <message>
        <source>Instruction</source>
        <translation>Instruktion</translation>
    </message>
    <message>
        <source>Time constant</source>
        <translation>Tidskonstant</translation>
    </message>
    <message>
        <source>Number</source>
        <translation>Tal</translation>
    </message>
    <message>
        <source>Operator</source>
        <translation>Operator</translation>
    </message>
    <message>
        <source>Symbolic name</source>
        <translation>Symboliskt namn</translation>
    </message>
    <message>
        <source>Invalid text</source>
        <translation>Ogiltig text</translation>
    </message>
</context>
<context>
    <name>rs::ui::PreferencesDialog</name>
    <message>
        <source>Start with ladder diagrams &amp;expanded</source>
        <translation>Starta med stegdiagrammen &amp;utfällda</translation>
    </message>
    <message>
        <source>&amp;Unconfigured I/O warnings at compile time</source>
        <translation>Varningar för &amp;okonfigurerad I/O vid kompilering</translation>
    </message>
    <message>
        <source>Preferences</source>
        <translation>Inställningar</translation>
    </message>
    <message>
        <source>Ladder colours</source>
        <translation>Färger i stegdiagram</translation>
    </message>
    <message>
        <source>Ladder background:</source>
        <translation>Bakgrund:</translation>
    </message>
    <message>
        <source>Focused ladder background:</source>
        <translation>Bakgrund med fokus:</translation>
    </message>
    <message>
        <source>Ladder component body:</source>
        <translation>Komponentkropp:</translation>
    </message>
    <message>
        <source>Ladder lines:</source>
        <translation>Linjer:</translation>
    </message>
    <message>
        <source>Ladder lines off:</source>
        <translation>Linjer, från:</translation>
    </message>
    <message>
        <source>Ladder lines on:</source>
        <translation>Linjer, till:</translation>
    </message>
    <message>
        <source>%1 ms</source>
        <translation>%1 ms</translation>
    </message>
    <message>
        <source>Update interval in online mode. A shorter interval makes the computer slower.</source>
        <translation>Uppdateringsintervall i online-läge. Ett kortare intervall gör datorn långsammare.</translation>
    </message>
    <message>
        <source>System language</source>
        <translation>Systemets språk</translation>
    </message>
    <message>
        <source>Follow the system</source>
        <translation>Följ systemet</translation>
    </message>
    <message>
        <source>Light</source>
        <translation>Ljust</translation>
    </message>
    <message>
        <source>Dark</source>
        <translation>Mörkt</translation>
    </message>
    <message>
        <source> min</source>
        <translation> min</translation>
    </message>
    <message>
        <source>A new language shows when Rungsmith starts again.</source>
        <translation>Ett nytt språk visas när Rungsmith startas igen.</translation>
    </message>
    <message>
        <source>General</source>
        <translation>Allmänt</translation>
    </message>
    <message>
        <source>Screen update &amp;interval:</source>
        <translation>Skärmens uppdaterings&amp;intervall:</translation>
    </message>
    <message>
        <source>&amp;Language:</source>
        <translation>&amp;Språk:</translation>
    </message>
    <message>
        <source>&amp;Theme:</source>
        <translation>&amp;Tema:</translation>
    </message>
    <message>
        <source>&amp;Autosave every:</source>
        <translation>Spara &amp;automatiskt var:</translation>
    </message>
    <message>
        <source>From %1 to %2 minutes. A crash loses at most this much work.</source>
        <translation>Från %1 till %2 minuter. En krasch förlorar högst så mycket arbete.</translation>
    </message>
    <message>
        <source>Theme &amp;Colours</source>
        <translation>Temats &amp;färger</translation>
    </message>
    <message>
        <source>Draw the ladder in the theme&apos;s colours again</source>
        <translation>Rita stegdiagrammet i temats färger igen</translation>
    </message>
    <message>
        <source>Theme</source>
        <translation>Tema</translation>
    </message>
    <message>
        <source>As the theme draws it; click to choose a colour</source>
        <translation>Som temat ritar det; klicka för att välja en färg</translation>
    </message>
    <message>
        <source>Simulated gateway</source>
        <translation>Simulerad gateway</translation>
    </message>
    <message>
        <source>Modbus TCP &amp;address:</source>
        <translation>Modbus TCP-&amp;adress:</translation>
    </message>
    <message>
        <source>Modbus TCP &amp;port:</source>
        <translation>Modbus TCP-&amp;port:</translation>
    </message>
    <message>
        <source>Where Serve Modbus TCP listens while simulating. 127.0.0.1 lets only this computer connect; 0.0.0.0 the network.</source>
        <translation>Där Betjäna Modbus TCP lyssnar under simulering. 127.0.0.1 låter bara den här datorn ansluta, 0.0.0.0 nätverket.</translation>
    </message>
</context>
<context>
    <name>rs::ui::ProblemsView</name>
    <message>
        <source>Location</source>
        <translation>Plats</translation>
    </message>
    <message>
        <source>Message</source>
        <translation>Meddelande</translation>
    </message>
    <message>
        <source>Error</source>
        <translation>Fel</translation>
    </message>
    <message>
        <source>Warning</source>
        <translation>Varning</translation>
    </message>
    <message>
        <source>No problems found.</source>
        <translation>Inga problem hittades.</translation>
    </message>
</context>
<context>
    <name>rs::ui::ProgramEditor</name>
    <message>
        <source>Error message</source>
        <translation>Felmeddelande</translation>
    </message>
    <message>
        <source>Warning message</source>
        <translation>Varningsmeddelande</translation>
    </message>
</context>
<context>
    <name>rs::ui::ProjectDocument</name>
    <message>
        <source>Expand Block Instances</source>
        <translation>Expandera blockinstanser</translation>
    </message>
    <message>
        <source>Untitled</source>
        <translation>Namnlöst</translation>
    </message>
    <message>
        <source>The project is open read only: nothing in it can change.</source>
        <translation>Projektet är öppnat skrivskyddat: inget i det kan ändras.</translation>
    </message>
    <message>
        <source>The project is open with permission to configure: only its Config Options can change.</source>
        <translation>Projektet är öppnat med behörighet att konfigurera: bara dess konfigurationsalternativ kan ändras.</translation>
    </message>
    <message>
        <source>It is a program for the Pixsys PL110, not a Pluto project: File &gt; Open opens it in a PL110 window.</source>
        <translation>Det är ett program för Pixsys PL110, inte ett Pluto-projekt: Arkiv &gt; Öppna öppnar det i ett PL110-fönster.</translation>
    </message>
</context>
<context>
    <name>rs::ui::ProjectPage</name>
    <message>
        <source>Add &amp;Standard Library</source>
        <translation>Lägg till &amp;standardbibliotek</translation>
    </message>
    <message>
        <source>Add &amp;User Library...</source>
        <translation>Lägg till an&amp;vändarbibliotek...</translation>
    </message>
    <message>
        <source>&amp;Remove Library</source>
        <translation>&amp;Ta bort bibliotek</translation>
    </message>
    <message>
        <source>No standard library is installed</source>
        <translation>Inget standardbibliotek är installerat</translation>
    </message>
    <message>
        <source>Function &amp;libraries:</source>
        <translation>Funktions&amp;bibliotek:</translation>
    </message>
    <message>
        <source>Every library found: the standard ones and those in the project&apos;s folder</source>
        <translation>Alla bibliotek som hittas: standardbiblioteken och de i projektets mapp</translation>
    </message>
    <message>
        <source>A user library in the project&apos;s folder</source>
        <translation>Ett användarbibliotek i projektets mapp</translation>
    </message>
    <message>
        <source>A standard library</source>
        <translation>Ett standardbibliotek</translation>
    </message>
    <message>
        <source>%1 (not found)</source>
        <translation>%1 (hittades inte)</translation>
    </message>
    <message>
        <source>Add Library %1</source>
        <translation>Lägg till bibliotek %1</translation>
    </message>
    <message>
        <source>Add User Library</source>
        <translation>Lägg till användarbibliotek</translation>
    </message>
    <message>
        <source>Function block libraries (*.rslib)</source>
        <translation>Funktionsblocksbibliotek (*.rslib)</translation>
    </message>
    <message>
        <source>Remove Library %1</source>
        <translation>Ta bort bibliotek %1</translation>
    </message>
    <message>
        <source>&amp;Include source code in compiled file</source>
        <translation>&amp;Inkludera källkoden i den kompilerade filen</translation>
    </message>
    <message>
        <source>Project &amp;name:</source>
        <translation>Projekt&amp;namn:</translation>
    </message>
    <message>
        <source>Project &amp;description:</source>
        <translation>Projekt&amp;beskrivning:</translation>
    </message>
    <message>
        <source>File:</source>
        <translation>Fil:</translation>
    </message>
    <message>
        <source>Units:</source>
        <translation>Enheter:</translation>
    </message>
    <message>
        <source>Include Source Code</source>
        <translation>Inkludera källkoden</translation>
    </message>
    <message>
        <source>Leave Out Source Code</source>
        <translation>Utelämna källkoden</translation>
    </message>
    <message>
        <source>Project %1</source>
        <translation>Projekt %1</translation>
    </message>
    <message>
        <source>Not saved yet</source>
        <translation>Inte sparat än</translation>
    </message>
    <message>
        <source>None yet. Add one with Project &gt; New Pluto.</source>
        <translation>Inga än. Lägg till en med Projekt &gt; Ny Pluto.</translation>
    </message>
    <message>
        <source>Rename Project</source>
        <translation>Byt namn på projektet</translation>
    </message>
    <message>
        <source>Change Project Description</source>
        <translation>Ändra projektbeskrivningen</translation>
    </message>
    <message>
        <source>Program signature:</source>
        <translation>Programsignatur:</translation>
    </message>
    <message>
        <source>Validated:</source>
        <translation>Validerat:</translation>
    </message>
    <message>
        <source>on %1 by %2 (signature %3)</source>
        <translation>den %1 av %2 (signatur %3)</translation>
    </message>
    <message>
        <source>not yet (Project &gt; Mark as Validated)</source>
        <translation>inte ännu (Projekt &gt; Markera som validerat)</translation>
    </message>
    <message>
        <source>Since then:</source>
        <translation>Sedan dess:</translation>
    </message>
    <message>
        <source>computing...</source>
        <translation>beräknas …</translation>
    </message>
    <message>
        <source>unknown while the project has errors (Build &gt; Compile shows them)</source>
        <translation>okänt så länge projektet har fel (Bygg &gt; Kompilera visar dem)</translation>
    </message>
    <message>
        <source>no change in behaviour since validation on %1</source>
        <translation>inget ändrat beteende sedan valideringen %1</translation>
    </message>
    <message>
        <source>changed since validation on %1 in %2</source>
        <translation>ändrat sedan valideringen %1 i %2</translation>
    </message>
    <message numerus="yes">
        <source>%n network(s) added, changed or removed</source>
        <translation>
            <numerusform>%n nätverk tillagt, ändrat eller borttaget</numerusform>
            <numerusform>%n nätverk tillagda, ändrade eller borttagna</numerusform>
        </translation>
    </message>
    <message>
        <source>Protection:</source>
        <translation>Skydd:</translation>
    </message>
    <message>
        <source>changed outside Rungsmith after it was password protected (first at line %1): open read only</source>
        <translation>ändrat utanför Rungsmith efter att det lösenordsskyddades (först på rad %1): öppnat skrivskyddat</translation>
    </message>
    <message>
        <source>none (File &gt; Password Protect)</source>
        <translation>inget (Arkiv &gt; Lösenordsskydda)</translation>
    </message>
    <message>
        <source>only with the main password</source>
        <translation>endast med huvudlösenordet</translation>
    </message>
    <message>
        <source>without a password</source>
        <translation>utan lösenord</translation>
    </message>
    <message>
        <source>with their own password</source>
        <translation>med sitt eget lösenord</translation>
    </message>
    <message>
        <source>with full permission</source>
        <translation>med full behörighet</translation>
    </message>
    <message>
        <source>with permission to configure</source>
        <translation>med behörighet att konfigurera</translation>
    </message>
    <message>
        <source>read only</source>
        <translation>skrivskyddat</translation>
    </message>
    <message>
        <source>The protection&apos;s public key: %1</source>
        <translation>Skyddets publika nyckel: %1</translation>
    </message>
    <message>
        <source>password protected, key %1 …
Config Options change %2; opened %3</source>
        <translation>lösenordsskyddat, nyckel %1 …
konfigurationsalternativen ändras %2; öppnat %3</translation>
    </message>
</context>
<context>
    <name>rs::ui::ProjectTree</name>
    <message>
        <source>Projects</source>
        <translation>Projekt</translation>
    </message>
    <message>
        <source>Project Text</source>
        <translation>Projekttext</translation>
    </message>
    <message>
        <source>I/O Options</source>
        <translation>I/O-alternativ</translation>
    </message>
    <message>
        <source>Variables</source>
        <translation>Variabler</translation>
    </message>
    <message>
        <source>PLC Code</source>
        <translation>PLC-kod</translation>
    </message>
    <message>
        <source>Sequence %1</source>
        <translation>Sekvens %1</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>AS-i Options</source>
        <translation>AS-i-alternativ</translation>
    </message>
    <message>
        <source>Gateway %1 (%2)</source>
        <translation>Gateway %1 (%2)</translation>
    </message>
    <message>
        <source>Properties</source>
        <translation>Egenskaper</translation>
    </message>
</context>
<context>
    <name>rs::ui::ProofResultsView</name>
    <message>
        <source>Line</source>
        <translation>Rad</translation>
    </message>
    <message>
        <source>Property</source>
        <translation>Egenskap</translation>
    </message>
    <message>
        <source>Result</source>
        <translation>Resultat</translation>
    </message>
    <message>
        <source>Scans</source>
        <translation>Cykler</translation>
    </message>
    <message>
        <source>Reason</source>
        <translation>Orsak</translation>
    </message>
    <message>
        <source>proved</source>
        <translation>bevisad</translation>
    </message>
    <message>
        <source>failed</source>
        <translation>bruten</translation>
    </message>
    <message>
        <source>unknown</source>
        <translation>okänd</translation>
    </message>
    <message>
        <source>covered</source>
        <translation>nådd</translation>
    </message>
    <message>
        <source>never covered</source>
        <translation>aldrig nådd</translation>
    </message>
    <message>
        <source>waiting</source>
        <translation>väntar</translation>
    </message>
    <message>
        <source>proving…</source>
        <translation>bevisas …</translation>
    </message>
    <message numerus="yes">
        <source>Proved by induction over %n scan(s)</source>
        <translation>
            <numerusform>Bevisad med induktion över %n cykel</numerusform>
            <numerusform>Bevisad med induktion över %n cykler</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>A counterexample of %n scan(s) from power on</source>
        <translation>
            <numerusform>Ett motexempel på %n cykel från tillslag</numerusform>
            <numerusform>Ett motexempel på %n cykler från tillslag</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Reached in %n scan(s) from power on</source>
        <translation>
            <numerusform>Nådd på %n cykel från tillslag</numerusform>
            <numerusform>Nådd på %n cykler från tillslag</numerusform>
        </translation>
    </message>
    <message>
        <source>Open Counterexample runs it in the simulator</source>
        <translation>Öppna motexempel kör det i simulatorn</translation>
    </message>
    <message>
        <source>not proved</source>
        <translation>inte bevisad</translation>
    </message>
</context>
<context>
    <name>rs::ui::ProofRun</name>
    <message>
        <source>The property has no counterexample to open.</source>
        <translation>Egenskapen har inget motexempel att öppna.</translation>
    </message>
    <message>
        <source>A scenario is running already.</source>
        <translation>Ett scenario körs redan.</translation>
    </message>
    <message>
        <source>cancelled</source>
        <translation>avbruten</translation>
    </message>
    <message numerus="yes">
        <source>the time limit of %n s per property ran out</source>
        <translation>
            <numerusform>tidsgränsen på %n s per egenskap tog slut</numerusform>
            <numerusform>tidsgränsen på %n s per egenskap tog slut</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>no counterexample within %n scans</source>
        <translation>
            <numerusform>inget motexempel inom %n cykel</numerusform>
            <numerusform>inget motexempel inom %n cykler</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>internal error: the prover&apos;s counterexample of %n scans does not replay (%1); please report it</source>
        <translation>
            <numerusform>internt fel: beviskontrollantens motexempel på %n cykel går inte att spela upp igen (%1); rapportera det gärna</numerusform>
            <numerusform>internt fel: beviskontrollantens motexempel på %n cykler går inte att spela upp igen (%1); rapportera det gärna</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>internal error: the prover&apos;s witness of %n scans does not replay (%1); please report it</source>
        <translation>
            <numerusform>internt fel: beviskontrollantens vittne på %n cykel går inte att spela upp igen (%1); rapportera det gärna</numerusform>
            <numerusform>internt fel: beviskontrollantens vittne på %n cykler går inte att spela upp igen (%1); rapportera det gärna</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>The project has %n error(s); compile it (F7) to see them.</source>
        <translation>
            <numerusform>Projektet har %n fel; kompilera det (F7) för att se felet.</numerusform>
            <numerusform>Projektet har %n fel; kompilera det (F7) för att se felen.</numerusform>
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
        <translation>; Det som måste gälla i varje cykel, för varje insignalsföljd: en egenskap per rad.
; Ta bort &apos;;&apos; före en rad för att använda den, med operanderna i detta projekt.
; always Q0.2 -&gt; I0.12                 ; utgången bara med stoppkretsen sluten
; never Q0.2 * Q0.3                    ; aldrig båda kontaktorerna samtidigt
; always /I0.12 -&gt; within 20ms /Q0.2   ; utgången faller inom 20 ms efter ett stopp
; always I0.0 -&gt; next Q0.2             ; utgången följer starten i nästa cykel
; assume /(I0.0 * I0.1)                ; de två givarna är aldrig påverkade samtidigt
; cover Q0.2                           ; utgången kan slå till
</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Avbryt</translation>
    </message>
    <message>
        <source>Open Counterexample</source>
        <translation>Öppna motexempel</translation>
    </message>
    <message>
        <source>Complete Word</source>
        <translation>Komplettera ord</translation>
    </message>
    <message>
        <source>Insert Example</source>
        <translation>Infoga exempel</translation>
    </message>
    <message>
        <source>Stop proving; the properties proved so far keep their results</source>
        <translation>Sluta bevisa; de egenskaper som hunnit bevisas behåller sina resultat</translation>
    </message>
    <message>
        <source>Run the chosen property&apos;s counterexample (or witness) in the simulator, with the waveform, stopped at its last scan</source>
        <translation>Kör den valda egenskapens motexempel (eller vittne) i simulatorn, med vågform, stoppat efter dess sista cykel</translation>
    </message>
    <message>
        <source>&lt;p&gt;No properties yet. Write one a line, with conditions as in the code (operands, names, &lt;code&gt;/&lt;/code&gt;, &lt;code&gt;*&lt;/code&gt;, &lt;code&gt;+&lt;/code&gt;, parentheses):&lt;/p&gt;&lt;p&gt;&lt;code&gt;always A&lt;/code&gt;, &lt;code&gt;never A&lt;/code&gt;, &lt;code&gt;always A -&amp;gt; B&lt;/code&gt;, &lt;code&gt;always A -&amp;gt; within 20ms B&lt;/code&gt;, &lt;code&gt;always A -&amp;gt; next B&lt;/code&gt;, &lt;code&gt;assume A&lt;/code&gt;, &lt;code&gt;cover A&lt;/code&gt;.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Prove All&lt;/b&gt; proves each for every input sequence, or finds one that breaks it and opens it in the simulator.&lt;/p&gt;</source>
        <translation>&lt;p&gt;Inga egenskaper ännu. Skriv en per rad, med villkor som i koden (operander, namn, &lt;code&gt;/&lt;/code&gt;, &lt;code&gt;*&lt;/code&gt;, &lt;code&gt;+&lt;/code&gt;, parenteser):&lt;/p&gt;&lt;p&gt;&lt;code&gt;always A&lt;/code&gt;, &lt;code&gt;never A&lt;/code&gt;, &lt;code&gt;always A -&amp;gt; B&lt;/code&gt;, &lt;code&gt;always A -&amp;gt; within 20ms B&lt;/code&gt;, &lt;code&gt;always A -&amp;gt; next B&lt;/code&gt;, &lt;code&gt;assume A&lt;/code&gt;, &lt;code&gt;cover A&lt;/code&gt;.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Bevisa alla&lt;/b&gt; bevisar var och en för varje insignalsföljd, eller hittar en följd som bryter den och öppnar den i simulatorn.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>Put a commented example of every kind of line in the text</source>
        <translation>Infoga ett bortkommenterat exempel på varje sorts rad i texten</translation>
    </message>
    <message>
        <source>%1 — Properties</source>
        <translation>%1 — Egenskaper</translation>
    </message>
    <message>
        <source>Saved with the project, beside its file, once it has one: its name with the extension .prop.</source>
        <translation>Sparas med projektet, bredvid dess fil när det har en: dess namn med filändelsen .prop.</translation>
    </message>
    <message>
        <source>Saved with the project as %1, which rungsmith-cli prove takes too.</source>
        <translation>Sparas med projektet som %1, som även rungsmith-cli prove läser.</translation>
    </message>
    <message numerus="yes">
        <source>The properties have %n error(s), marked in the text: nothing is proved until they read.</source>
        <translation>
            <numerusform>Egenskaperna har %n fel, markerat i texten: inget bevisas förrän de går att läsa.</numerusform>
            <numerusform>Egenskaperna har %n fel, markerade i texten: inget bevisas förrän de går att läsa.</numerusform>
        </translation>
    </message>
    <message>
        <source>Write a property first: there is nothing to prove.</source>
        <translation>Skriv en egenskap först: det finns inget att bevisa.</translation>
    </message>
    <message>
        <source>Compiling %1...</source>
        <translation>Kompilerar %1 …</translation>
    </message>
    <message>
        <source>Property %1 of %2</source>
        <translation>Egenskap %1 av %2</translation>
    </message>
    <message>
        <source>Proving property %1 of %2...</source>
        <translation>Bevisar egenskap %1 av %2 …</translation>
    </message>
    <message>
        <source>cancelled</source>
        <translation>avbruten</translation>
    </message>
    <message>
        <source>%1 proved, %2 failed, %3 unknown</source>
        <translation>%1 bevisade, %2 brutna, %3 okända</translation>
    </message>
    <message>
        <source>Cancelled: %1.</source>
        <translation>Avbrutet: %1.</translation>
    </message>
    <message>
        <source>The properties or the project changed since this proof; Prove All again for results of the text as it is now.</source>
        <translation>Egenskaperna eller projektet har ändrats sedan detta bevis; välj Bevisa alla igen för resultat av texten som den är nu.</translation>
    </message>
    <message>
        <source>Open Witness</source>
        <translation>Öppna vittne</translation>
    </message>
</context>
<context>
    <name>rs::ui::ProtectedOpenDialog</name>
    <message>
        <source>Open with &amp;full permission</source>
        <translation>Öppna med &amp;full behörighet</translation>
    </message>
    <message>
        <source>Open with permission to &amp;configure</source>
        <translation>Öppna med behörighet att &amp;konfigurera</translation>
    </message>
    <message>
        <source>Open in &amp;read only mode</source>
        <translation>Öppna &amp;skrivskyddat</translation>
    </message>
    <message>
        <source>Open Protected Project</source>
        <translation>Öppna skyddat projekt</translation>
    </message>
    <message>
        <source>“%1” is password protected. It opens without a password, but then nothing in it can change.</source>
        <translation>”%1” är lösenordsskyddat. Det öppnas utan lösenord, men då kan inget i det ändras.</translation>
    </message>
    <message>
        <source>Takes the main password; everything can change.</source>
        <translation>Kräver huvudlösenordet; allt kan ändras.</translation>
    </message>
    <message>
        <source>Takes no password; only the Config Options can change.</source>
        <translation>Kräver inget lösenord; bara konfigurationsalternativen kan ändras.</translation>
    </message>
    <message>
        <source>Takes the config options password, or the main one; only the Config Options can change.</source>
        <translation>Kräver lösenordet för konfigurationsalternativen eller huvudlösenordet; bara konfigurationsalternativen kan ändras.</translation>
    </message>
    <message>
        <source>Takes no password; nothing can change.</source>
        <translation>Kräver inget lösenord; inget kan ändras.</translation>
    </message>
    <message>
        <source>&amp;Password:</source>
        <translation>&amp;Lösenord:</translation>
    </message>
    <message>
        <source>The password does not open the project with this permission.</source>
        <translation>Lösenordet öppnar inte projektet med denna behörighet.</translation>
    </message>
    <message numerus="yes">
        <source>The password does not open the project with this permission. Try again in %n second(s).</source>
        <translation>
            <numerusform>Lösenordet öppnar inte projektet med denna behörighet. Försök igen om %n sekund.</numerusform>
            <numerusform>Lösenordet öppnar inte projektet med denna behörighet. Försök igen om %n sekunder.</numerusform>
        </translation>
    </message>
    <message>
        <source>Accept the Change</source>
        <translation>Godta ändringen</translation>
    </message>
</context>
<context>
    <name>rs::ui::RemanentDialog</name>
    <message>
        <source>Remanent Variables of Pluto %1</source>
        <translation>Remanenta variabler för Pluto %1</translation>
    </message>
    <message>
        <source>Remanent variables keep their value when the power is off. Registers R100-R131 and memories M100-M131 can be remanent in any combination, except that with all the registers no memory can be.</source>
        <translation>Remanenta variabler behåller sitt värde när strömmen är bruten. Register R100-R131 och minnen M100-M131 kan vara remanenta i valfri kombination, utom att inget minne kan vara det när alla register är det.</translation>
    </message>
    <message>
        <source>All</source>
        <translation>Alla</translation>
    </message>
    <message>
        <source>None</source>
        <translation>Inga</translation>
    </message>
    <message>
        <source>Registers</source>
        <translation>Register</translation>
    </message>
    <message>
        <source>Memories</source>
        <translation>Minnen</translation>
    </message>
    <message>
        <source>All 32 registers are remanent, so no memory can be.</source>
        <translation>Alla 32 register är remanenta, så inget minne kan vara det.</translation>
    </message>
</context>
<context>
    <name>rs::ui::ScenarioFileViewer</name>
    <message>
        <source>&amp;Open in Editor</source>
        <translation>&amp;Öppna i redigeraren</translation>
    </message>
    <message>
        <source>%1 (read-only)</source>
        <translation>%1 (skrivskyddad)</translation>
    </message>
    <message>
        <source>%1, line %2</source>
        <translation>%1, rad %2</translation>
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
        <translation>%1: %2 godkända, %3 underkända</translation>
    </message>
    <message>
        <source>Double-click to show line %1 of %2</source>
        <translation>Dubbelklicka för att visa rad %1 i %2</translation>
    </message>
    <message>
        <source>%1: cancelled at t = %2 s, %3 passed, %4 failed so far</source>
        <translation>%1: avbrutet vid t = %2 s, %3 godkända, %4 underkända hittills</translation>
    </message>
</context>
<context>
    <name>rs::ui::SignatureLabel</name>
    <message>
        <source>Changes exactly when what the program does changes; formatting, comments, names and descriptions leave it as it is</source>
        <translation>Ändras precis när det programmet gör ändras; formatering, kommentarer, namn och beskrivningar lämnar den som den är</translation>
    </message>
    <message>
        <source>computing...</source>
        <translation>beräknas …</translation>
    </message>
    <message>
        <source>none while the project has errors (Build &gt; Compile shows them)</source>
        <translation>ingen så länge projektet har fel (Bygg &gt; Kompilera visar dem)</translation>
    </message>
</context>
<context>
    <name>rs::ui::SimulationControls</name>
    <message>
        <source>t = %1 s  (%2 scans)</source>
        <translation>t = %1 s  (%2 cykler)</translation>
    </message>
    <message>
        <source>&amp;Simulate</source>
        <translation>&amp;Simulera</translation>
    </message>
    <message>
        <source>Simulate</source>
        <translation>Simulera</translation>
    </message>
    <message>
        <source>Si&amp;mulation Mode</source>
        <translation>Si&amp;muleringsläge</translation>
    </message>
    <message>
        <source>Run the project in the simulator and show its live state; editing ends it</source>
        <translation>Kör projektet i simulatorn och visa dess aktuella tillstånd; redigering avslutar simuleringen</translation>
    </message>
    <message>
        <source>&amp;Start</source>
        <translation>&amp;Starta</translation>
    </message>
    <message>
        <source>Run the program on the simulated clock</source>
        <translation>Kör programmet med den simulerade klockan</translation>
    </message>
    <message>
        <source>S&amp;top</source>
        <translation>S&amp;toppa</translation>
    </message>
    <message>
        <source>Hold the program and the clock; the state stays shown</source>
        <translation>Stoppa programmet och klockan; tillståndet visas kvar</translation>
    </message>
    <message>
        <source>Single S&amp;can</source>
        <translation>En &amp;cykel</translation>
    </message>
    <message>
        <source>Run one scan of every unit</source>
        <translation>Kör en cykel i varje enhet</translation>
    </message>
    <message>
        <source>&amp;Reset</source>
        <translation>Starta &amp;om</translation>
    </message>
    <message>
        <source>Power on again at time 0; forces stay</source>
        <translation>Slå på igen vid tiden 0; forceringar ligger kvar</translation>
    </message>
    <message>
        <source>Run Sce&amp;nario...</source>
        <translation>Kör sce&amp;nario …</translation>
    </message>
    <message>
        <source>Run a scenario file (.scn) and list its results</source>
        <translation>Kör en scenariofil (.scn) och lista dess resultat</translation>
    </message>
    <message>
        <source>Real time</source>
        <translation>Realtid</translation>
    </message>
    <message>
        <source>10x</source>
        <translation>10x</translation>
    </message>
    <message>
        <source>As fast as possible</source>
        <translation>Så snabbt som möjligt</translation>
    </message>
    <message>
        <source>How fast the simulated clock runs</source>
        <translation>Hur snabbt den simulerade klockan går</translation>
    </message>
    <message>
        <source>The simulated clock</source>
        <translation>Den simulerade klockan</translation>
    </message>
    <message>
        <source>S&amp;peed</source>
        <translation>&amp;Hastighet</translation>
    </message>
    <message>
        <source>Not simulating</source>
        <translation>Ingen simulering</translation>
    </message>
</context>
<context>
    <name>rs::ui::SimulationMode</name>
    <message>
        <source>Forces</source>
        <translation>Forceringar</translation>
    </message>
    <message>
        <source>Watch</source>
        <translation>Bevakning</translation>
    </message>
    <message>
        <source>Waveform</source>
        <translation>Vågform</translation>
    </message>
    <message>
        <source>Bus Status</source>
        <translation>Busstatus</translation>
    </message>
    <message>
        <source>Scenarios</source>
        <translation>Scenarier</translation>
    </message>
    <message>
        <source>Simulation</source>
        <translation>Simulering</translation>
    </message>
    <message>
        <source>Run Scenario</source>
        <translation>Kör scenario</translation>
    </message>
    <message>
        <source>Scenarios (*.scn);;All files (*)</source>
        <translation>Scenarier (*.scn);;Alla filer (*)</translation>
    </message>
    <message>
        <source>Simulating %1. Editing the project ends the simulation.</source>
        <translation>Simulerar %1. Om projektet redigeras avslutas simuleringen.</translation>
    </message>
    <message>
        <source>%1 is not an input: right-click it to force it.</source>
        <translation>%1 är inte en ingång: högerklicka på den för att forcera den.</translation>
    </message>
    <message>
        <source>Force %1 to &amp;0</source>
        <translation>Forcera %1 till &amp;0</translation>
    </message>
    <message>
        <source>Force %1 to &amp;1</source>
        <translation>Forcera %1 till &amp;1</translation>
    </message>
    <message>
        <source>Force %1 to a &amp;Value...</source>
        <translation>Forcera %1 till ett &amp;värde …</translation>
    </message>
    <message>
        <source>Force</source>
        <translation>Forcera</translation>
    </message>
    <message>
        <source>Value of %1:</source>
        <translation>Värde för %1:</translation>
    </message>
    <message>
        <source>&amp;Release %1</source>
        <translation>&amp;Häv forceringen av %1</translation>
    </message>
    <message>
        <source>&amp;Watch %1</source>
        <translation>&amp;Bevaka %1</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Avbryt</translation>
    </message>
    <message>
        <source>Stop the scenario; the simulation shows where it got</source>
        <translation>Stoppa scenariot; simuleringen visar hur långt det kom</translation>
    </message>
    <message>
        <source>Scenario: %1 of %2 s</source>
        <translation>Scenario: %1 av %2 s</translation>
    </message>
    <message>
        <source>A scenario is running already.</source>
        <translation>Ett scenario körs redan.</translation>
    </message>
    <message>
        <source>Scenario %1 cancelled at t = %2 s.</source>
        <translation>Scenario %1 avbrutet vid t = %2 s.</translation>
    </message>
    <message>
        <source>Serve &amp;Modbus TCP</source>
        <translation>Betjäna &amp;Modbus TCP</translation>
    </message>
    <message>
        <source>Gateways</source>
        <translation>Gatewayer</translation>
    </message>
    <message>
        <source>Answer Modbus TCP clients for the project&apos;s Ethernet gateway while simulating, at the address the preferences give</source>
        <translation>Svara Modbus TCP-klienter för projektets Ethernet-gateway under simulering, på adressen i inställningarna</translation>
    </message>
    <message>
        <source>Serve Modbus TCP</source>
        <translation>Betjäna Modbus TCP</translation>
    </message>
    <message>
        <source>Cannot serve Modbus TCP on %1:%2: %3. Choose another address or port in the preferences.</source>
        <translation>Kan inte betjäna Modbus TCP på %1:%2: %3. Välj en annan adress eller port i inställningarna.</translation>
    </message>
    <message>
        <source>Serving Modbus TCP on %1.</source>
        <translation>Betjänar Modbus TCP på %1.</translation>
    </message>
</context>
<context>
    <name>rs::ui::SimulationSession</name>
    <message>
        <source>No project is open.</source>
        <translation>Inget projekt är öppet.</translation>
    </message>
    <message>
        <source>The project&apos;s text has errors; fix them before simulating.</source>
        <translation>Projektets text har fel; rätta dem innan du simulerar.</translation>
    </message>
    <message numerus="yes">
        <source>The project has %n error(s); compile it (F7) to see them.</source>
        <translation>
            <numerusform>Projektet har %n fel; kompilera det (F7) för att se felet.</numerusform>
            <numerusform>Projektet har %n fel; kompilera det (F7) för att se felen.</numerusform>
        </translation>
    </message>
    <message>
        <source>The project has no Pluto to simulate.</source>
        <translation>Projektet har ingen Pluto att simulera.</translation>
    </message>
    <message>
        <source>The project changed, so the simulation ended. Start it again to simulate the new version.</source>
        <translation>Projektet ändrades, så simuleringen avslutades. Starta den igen för att simulera den nya versionen.</translation>
    </message>
    <message>
        <source>The project was closed, so the simulation ended.</source>
        <translation>Projektet stängdes, så simuleringen avslutades.</translation>
    </message>
    <message>
        <source>The simulation is not running.</source>
        <translation>Simuleringen körs inte.</translation>
    </message>
    <message>
        <source>A scenario is running already.</source>
        <translation>Ett scenario körs redan.</translation>
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
        <translation>Filen har fel, så den visas som text tills de är rättade. Rader med fel kunde inte visas på de andra sidorna.</translation>
    </message>
    <message>
        <source>%1 — PLC Code</source>
        <translation>%1 — PLC-kod</translation>
    </message>
    <message>
        <source>Edit Code of Pluto %1</source>
        <translation>Redigera koden för Pluto %1</translation>
    </message>
    <message>
        <source>Ladder</source>
        <translation>Stegdiagram</translation>
    </message>
    <message>
        <source>Show this code as ladder networks</source>
        <translation>Visa koden som stegdiagramnätverk</translation>
    </message>
</context>
<context>
    <name>rs::ui::UnitCommands</name>
    <message>
        <source>New &amp;Pluto...</source>
        <translation>Ny &amp;Pluto …</translation>
    </message>
    <message>
        <source>Add a Pluto unit to the project</source>
        <translation>Lägg till en Pluto-enhet i projektet</translation>
    </message>
    <message>
        <source>New &amp;Sequence...</source>
        <translation>Ny s&amp;ekvens …</translation>
    </message>
    <message>
        <source>&amp;Remove Pluto...</source>
        <translation>&amp;Ta bort Pluto …</translation>
    </message>
    <message>
        <source>Re&amp;manent Variables...</source>
        <translation>Re&amp;manenta variabler …</translation>
    </message>
    <message>
        <source>&amp;Import Variable Names (CSV)...</source>
        <translation>&amp;Importera variabelnamn (CSV) …</translation>
    </message>
    <message>
        <source>E&amp;xport Variable Names (CSV)...</source>
        <translation>E&amp;xportera variabelnamn (CSV) …</translation>
    </message>
    <message>
        <source>New Pluto</source>
        <translation>Ny Pluto</translation>
    </message>
    <message>
        <source>The project has 32 units, the most a bus can have.</source>
        <translation>Projektet har 32 enheter, det största antal en buss kan ha.</translation>
    </message>
    <message>
        <source>New Pluto %1</source>
        <translation>Ny Pluto %1</translation>
    </message>
    <message>
        <source>New Sequence</source>
        <translation>Ny sekvens</translation>
    </message>
    <message>
        <source>Pluto %1 has all nine sequences.</source>
        <translation>Pluto %1 har alla nio sekvenser.</translation>
    </message>
    <message>
        <source>Sequence number for Pluto %1 (1-9):</source>
        <translation>Sekvensnummer för Pluto %1 (1-9):</translation>
    </message>
    <message>
        <source>New Sequence %1 of Pluto %2</source>
        <translation>Ny sekvens %1 i Pluto %2</translation>
    </message>
    <message>
        <source>Remove Pluto</source>
        <translation>Ta bort Pluto</translation>
    </message>
    <message>
        <source>Remove %1 with its code, names and descriptions from the project? Edit &gt; Undo brings it back.</source>
        <translation>Ta bort %1 med dess kod, namn och beskrivningar från projektet? Redigera &gt; Ångra tar tillbaka den.</translation>
    </message>
    <message>
        <source>Remove Pluto %1</source>
        <translation>Ta bort Pluto %1</translation>
    </message>
    <message>
        <source>Set Remanent Variables of Pluto %1</source>
        <translation>Ställ in remanenta variabler för Pluto %1</translation>
    </message>
    <message>
        <source>Remanent Variables</source>
        <translation>Remanenta variabler</translation>
    </message>
    <message>
        <source>Import Variable Names to Pluto %1</source>
        <translation>Importera variabelnamn till Pluto %1</translation>
    </message>
    <message numerus="yes">
        <source>Imported %n variable(s).</source>
        <translation>
            <numerusform>Importerade %n variabel.</numerusform>
            <numerusform>Importerade %n variabler.</numerusform>
        </translation>
    </message>
    <message>
        <source>Export Variable Names</source>
        <translation>Exportera variabelnamn</translation>
    </message>
    <message>
        <source>Wrote %1</source>
        <translation>Skrev %1</translation>
    </message>
</context>
<context>
    <name>rs::ui::UnitPage</name>
    <message>
        <source>&amp;Remanent Variables...</source>
        <translation>&amp;Remanenta variabler …</translation>
    </message>
    <message>
        <source>This unit has code but no &apos;! id_pluto&apos; declaration. Any change below writes one.</source>
        <translation>Enheten har kod men ingen &apos;! id_pluto&apos;-deklaration. Varje ändring nedan skriver en.</translation>
    </message>
    <message>
        <source>Variables on the bus and at power off</source>
        <translation>Variabler på bussen och vid strömavbrott</translation>
    </message>
    <message>
        <source>Export variables:</source>
        <translation>Exportvariabler:</translation>
    </message>
    <message>
        <source>Remanent variables:</source>
        <translation>Remanenta variabler:</translation>
    </message>
    <message>
        <source>Station %1 of project %2</source>
        <translation>Station %1 i projekt %2</translation>
    </message>
    <message>
        <source>need instruction set 3</source>
        <translation>kräver instruktionsuppsättning 3</translation>
    </message>
    <message>
        <source>%1 of %2 extra telegram pairs (project: %3 of %4)</source>
        <translation>%1 av %2 extra telegrampar (projektet: %3 av %4)</translation>
    </message>
    <message>
        <source>this type has none</source>
        <translation>den här typen har inga</translation>
    </message>
    <message>
        <source>none</source>
        <translation>inga</translation>
    </message>
    <message>
        <source>Change Pluto %1</source>
        <translation>Ändra Pluto %1</translation>
    </message>
    <message numerus="yes">
        <source>This removes %n declaration(s), name(s), description(s) or attribute(s) of the unit that the new type or instruction set cannot have. Change it?</source>
        <translation>
            <numerusform>Detta tar bort %n deklaration, namn, beskrivning eller attribut i enheten som den nya typen eller instruktionsuppsättningen inte kan ha. Ändra den?</numerusform>
            <numerusform>Detta tar bort %n deklarationer, namn, beskrivningar eller attribut i enheten som den nya typen eller instruktionsuppsättningen inte kan ha. Ändra den?</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 of %2</source>
        <translation>%1 av %2</translation>
    </message>
    <message>
        <source>%1 of %2 (%3 of them by block instances)</source>
        <translation>%1 av %2 (varav %3 av blockinstanser)</translation>
    </message>
    <message>
        <source>Resources in use</source>
        <translation>Resurser som används</translation>
    </message>
    <message>
        <source>Timers:</source>
        <translation>Timrar:</translation>
    </message>
    <message>
        <source>Memories:</source>
        <translation>Minnen:</translation>
    </message>
    <message>
        <source>Registers:</source>
        <translation>Register:</translation>
    </message>
    <message>
        <source>Program signature:</source>
        <translation>Programsignatur:</translation>
    </message>
    <message>
        <source>Review</source>
        <translation>Granskning</translation>
    </message>
    <message>
        <source>&amp;Advanced Settings...</source>
        <translation>&amp;Avancerade inställningar...</translation>
    </message>
    <message>
        <source>CAN bus cycle time:</source>
        <translation>CAN-bussens cykeltid:</translation>
    </message>
    <message>
        <source>%1 ms</source>
        <translation>%1 ms</translation>
    </message>
    <message>
        <source>the unit&apos;s default</source>
        <translation>enhetens standardvärde</translation>
    </message>
    <message>
        <source>Set CAN Bus Cycle Time of Pluto %1</source>
        <translation>Ställ in CAN-bussens cykeltid för Pluto %1</translation>
    </message>
    <message>
        <source>E&amp;xternal Communication...</source>
        <translation>E&amp;xtern kommunikation...</translation>
    </message>
    <message>
        <source>Gateway data received:</source>
        <translation>Mottagna gatewaydata:</translation>
    </message>
    <message>
        <source>block %1 from gateway %2, packet %3</source>
        <translation>block %1 från gateway %2, paket %3</translation>
    </message>
    <message>
        <source>Set External Communication of Pluto %1</source>
        <translation>Ange extern kommunikation för Pluto %1</translation>
    </message>
</context>
<context>
    <name>rs::ui::UnitSettingsForm</name>
    <message>
        <source>Instruction set &amp;2</source>
        <translation>Instruktionsuppsättning &amp;2</translation>
    </message>
    <message>
        <source>Instruction set &amp;3</source>
        <translation>Instruktionsuppsättning &amp;3</translation>
    </message>
    <message>
        <source>Instruction set 3 needs Pluto OS 3.0 or later. It adds the off-delay timer, multiplication and division with constants, double registers (32 bits), &quot;not positive edge&quot; and &quot;not negative edge&quot;, register bits and a larger address range.</source>
        <translation>Instruktionsuppsättning 3 kräver Pluto OS 3.0 eller senare. Den lägger till frånslagsfördröjd timer, multiplikation och division med konstanter, dubbelregister (32 bitar), &quot;inte positiv flank&quot; och &quot;inte negativ flank&quot;, registerbitar och ett större adressområde.</translation>
    </message>
    <message>
        <source>IDFIX number</source>
        <translation>IDFIX-nummer</translation>
    </message>
    <message>
        <source>No IDFIX</source>
        <translation>Ingen IDFIX</translation>
    </message>
    <message>
        <source>12 hexadecimal digits, e.g. 000034AD4AE1</source>
        <translation>12 hexadecimala siffror, t.ex. 000034AD4AE1</translation>
    </message>
    <message>
        <source>For your own notes; not downloaded to the unit</source>
        <translation>För dina egna anteckningar; laddas inte ned till enheten</translation>
    </message>
    <message>
        <source>&amp;Station number:</source>
        <translation>&amp;Stationsnummer:</translation>
    </message>
    <message>
        <source>Pluto &amp;type:</source>
        <translation>Pluto-&amp;typ:</translation>
    </message>
    <message>
        <source>Instruction set:</source>
        <translation>Instruktionsuppsättning:</translation>
    </message>
    <message>
        <source>&amp;IDFIX:</source>
        <translation>&amp;IDFIX:</translation>
    </message>
    <message>
        <source>&amp;Description:</source>
        <translation>&amp;Beskrivning:</translation>
    </message>
    <message numerus="yes">
        <source>The IDFIX number has %n of its 12 hexadecimal digits. Choose &quot;No IDFIX&quot; if the unit has no identifier circuit.</source>
        <translation>
            <numerusform>IDFIX-numret har %n av sina 12 hexadecimala siffror. Välj &quot;Ingen IDFIX&quot; om enheten inte har någon identifieringskrets.</numerusform>
            <numerusform>IDFIX-numret har %n av sina 12 hexadecimala siffror. Välj &quot;Ingen IDFIX&quot; om enheten inte har någon identifieringskrets.</numerusform>
        </translation>
    </message>
    <message>
        <source>The %1 runs instruction set 2 only.</source>
        <translation>%1 kör endast instruktionsuppsättning 2.</translation>
    </message>
    <message>
        <source>IDFIX-PROG</source>
        <translation>IDFIX-PROG</translation>
    </message>
    <message>
        <source>A programmable identifier circuit: the number given here is the one written to it (Write IDFIX, on the unit).</source>
        <translation>En programmerbar identitetskrets: numret som anges här är det som skrivs till den (Skriv IDFIX, på enheten).</translation>
    </message>
</context>
<context>
    <name>rs::ui::VariableTableModel</name>
    <message>
        <source>Safety Inputs</source>
        <translation>Säkerhetsingångar</translation>
    </message>
    <message>
        <source>Safety Outputs</source>
        <translation>Säkerhetsutgångar</translation>
    </message>
    <message>
        <source>NonSafety Outputs</source>
        <translation>Icke säkra utgångar</translation>
    </message>
    <message>
        <source>Global Memories</source>
        <translation>Globala minnen</translation>
    </message>
    <message>
        <source>Memories</source>
        <translation>Minnen</translation>
    </message>
    <message>
        <source>Registers</source>
        <translation>Register</translation>
    </message>
    <message>
        <source>Double Registers</source>
        <translation>Dubbelregister</translation>
    </message>
    <message>
        <source>System Memories</source>
        <translation>Systemminnen</translation>
    </message>
    <message>
        <source>System Registers</source>
        <translation>Systemregister</translation>
    </message>
    <message>
        <source>AS-i Slaves</source>
        <translation>AS-i-slavar</translation>
    </message>
    <message>
        <source>Used in the code of the unit</source>
        <translation>Används i enhetens kod</translation>
    </message>
    <message>
        <source>[G] Global variable: visible to the other Plutos on the bus.</source>
        <translation>[G] Global variabel: synlig för de andra Plutoenheterna på bussen.</translation>
    </message>
    <message>
        <source>[E] Exported variable: made visible to the other Plutos on the bus.</source>
        <translation>[E] Exporterad variabel: görs synlig för de andra Plutoenheterna på bussen.</translation>
    </message>
    <message>
        <source>[R] Remanent variable: keeps its value when the power is off.</source>
        <translation>[R] Remanent variabel: behåller sitt värde när strömmen är bruten.</translation>
    </message>
    <message>
        <source>The manuals&apos; name of this system variable</source>
        <translation>Manualernas namn på den här systemvariabeln</translation>
    </message>
    <message>
        <source>Status</source>
        <translation>Status</translation>
    </message>
    <message>
        <source>Variable</source>
        <translation>Variabel</translation>
    </message>
    <message>
        <source>Attributes</source>
        <translation>Attribut</translation>
    </message>
    <message>
        <source>Symbolic Name</source>
        <translation>Symboliskt namn</translation>
    </message>
    <message>
        <source>Description</source>
        <translation>Beskrivning</translation>
    </message>
    <message>
        <source>Remove Name of %1</source>
        <translation>Ta bort namnet på %1</translation>
    </message>
    <message>
        <source>Name %1 %2</source>
        <translation>Ge %1 namnet %2</translation>
    </message>
    <message>
        <source>Describe %1</source>
        <translation>Beskriv %1</translation>
    </message>
    <message>
        <source>%1 F</source>
        <comment>a forced value</comment>
        <translation>%1 F</translation>
    </message>
    <message>
        <source>Forced to %1 in the simulation; release it in the Forces list.</source>
        <translation>Forcerad till %1 i simuleringen; häv forceringen i listan Forceringar.</translation>
    </message>
    <message>
        <source>The value after the last scan of the simulation</source>
        <translation>Värdet efter simuleringens senaste cykel</translation>
    </message>
    <message>
        <source>used</source>
        <comment>a variable the code reads or writes</comment>
        <translation>används</translation>
    </message>
</context>
<context>
    <name>rs::ui::VariablesPage</name>
    <message>
        <source>Filter by variable, name or description</source>
        <translation>Filtrera på variabel, namn eller beskrivning</translation>
    </message>
    <message>
        <source>Variable attributes: [G] global, visible to the other Plutos on the bus; [E] exported; [R] remanent, kept at power off.</source>
        <translation>Variabelattribut: [G] global, synlig för de andra Plutoenheterna på bussen; [E] exporterad; [R] remanent, behålls vid strömavbrott.</translation>
    </message>
    <message>
        <source>&amp;Remanent Variables...</source>
        <translation>&amp;Remanenta variabler …</translation>
    </message>
    <message>
        <source>&amp;Import CSV...</source>
        <translation>&amp;Importera CSV …</translation>
    </message>
    <message>
        <source>E&amp;xport CSV...</source>
        <translation>E&amp;xportera CSV …</translation>
    </message>
    <message>
        <source>%1 — Variables</source>
        <translation>%1 — Variabler</translation>
    </message>
    <message>
        <source>Export variables need instruction set 3.</source>
        <translation>Exportvariabler kräver instruktionsuppsättning 3.</translation>
    </message>
    <message>
        <source>Export variables: %1 of %2 extra telegram pairs (project: %3 of %4)</source>
        <translation>Exportvariabler: %1 av %2 extra telegrampar (projektet: %3 av %4)</translation>
    </message>
    <message>
        <source>Export %1</source>
        <translation>Exportera %1</translation>
    </message>
    <message>
        <source>Stop Exporting %1</source>
        <translation>Sluta exportera %1</translation>
    </message>
    <message>
        <source>&amp;Export Variable [E]</source>
        <translation>&amp;Exportera variabel [E]</translation>
    </message>
    <message>
        <source>&amp;Import Variable Names from CSV...</source>
        <translation>&amp;Importera variabelnamn från CSV …</translation>
    </message>
    <message>
        <source>E&amp;xport Variable Names to CSV...</source>
        <translation>E&amp;xportera variabelnamn till CSV …</translation>
    </message>
</context>
<context>
    <name>rs::ui::WatchView</name>
    <message>
        <source>Symbolic name or address, e.g. Q0.2</source>
        <translation>Symboliskt namn eller adress, t.ex. Q0.2</translation>
    </message>
    <message>
        <source>&amp;Watch</source>
        <translation>&amp;Bevaka</translation>
    </message>
    <message>
        <source>Variable</source>
        <translation>Variabel</translation>
    </message>
    <message>
        <source>Symbolic Name</source>
        <translation>Symboliskt namn</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>Värde</translation>
    </message>
    <message>
        <source>Type a value to set an input or force any other variable</source>
        <translation>Skriv ett värde för att sätta en ingång eller forcera en annan variabel</translation>
    </message>
    <message>
        <source>Type a symbolic name or an address.</source>
        <translation>Skriv ett symboliskt namn eller en adress.</translation>
    </message>
    <message>
        <source>%1 F</source>
        <comment>a forced value</comment>
        <translation>%1 F</translation>
    </message>
    <message>
        <source>Forced</source>
        <translation>Forcerad</translation>
    </message>
    <message>
        <source>“%1” is not a number.</source>
        <translation>”%1” är inte ett tal.</translation>
    </message>
    <message>
        <source>&amp;Release Force</source>
        <translation>&amp;Häv forcering</translation>
    </message>
    <message>
        <source>Stop &amp;Watching</source>
        <translation>Sluta &amp;bevaka</translation>
    </message>
    <message>
        <source>A channel is open (0) or closed (1).</source>
        <translation>En kanal är öppen (0) eller sluten (1).</translation>
    </message>
</context>
<context>
    <name>rs::ui::WaveformPanel</name>
    <message>
        <source>Add a variable to plot</source>
        <translation>Lägg till en variabel att rita</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>Ta bort</translation>
    </message>
    <message>
        <source>Stop plotting the chosen variable</source>
        <translation>Sluta rita den valda variabeln</translation>
    </message>
    <message>
        <source>Zoom in: show less time (Ctrl+wheel)</source>
        <translation>Zooma in: visa kortare tid (Ctrl+hjul)</translation>
    </message>
    <message>
        <source>Zoom out: show more time (Ctrl+wheel)</source>
        <translation>Zooma ut: visa längre tid (Ctrl+hjul)</translation>
    </message>
    <message>
        <source>Fit</source>
        <translation>Anpassa</translation>
    </message>
    <message>
        <source>Show the whole recording</source>
        <translation>Visa hela inspelningen</translation>
    </message>
    <message>
        <source>Export VCD...</source>
        <translation>Exportera VCD …</translation>
    </message>
    <message>
        <source>Write the recording as a Value Change Dump, for GTKWave</source>
        <translation>Skriv inspelningen som en Value Change Dump, för GTKWave</translation>
    </message>
    <message>
        <source>Export VCD</source>
        <translation>Exportera VCD</translation>
    </message>
    <message>
        <source>Nothing is recorded yet: start the simulation or run a scenario.</source>
        <translation>Inget är inspelat än: starta simuleringen eller kör ett scenario.</translation>
    </message>
    <message>
        <source>Value Change Dumps (*.vcd);;All files (*)</source>
        <translation>Value Change Dumps (*.vcd);;Alla filer (*)</translation>
    </message>
    <message>
        <source>Remove All</source>
        <translation>Ta bort alla</translation>
    </message>
    <message>
        <source>Stop plotting every variable, also those a scenario added</source>
        <translation>Sluta rita alla variabler, även de som ett scenario lade till</translation>
    </message>
</context>
<context>
    <name>rs::ui::WaveformView</name>
    <message>
        <source>Add variables to plot them over the simulation&apos;s time.</source>
        <translation>Lägg till variabler för att rita dem över simuleringens tid.</translation>
    </message>
</context>
<context>
    <name>rs::ui::WelcomePage</name>
    <message>
        <source>&lt;h2&gt;No project is open&lt;/h2&gt;&lt;p&gt;Start a new project, open one, or look at the example from the manual.&lt;/p&gt;</source>
        <translation>&lt;h2&gt;Inget projekt är öppet&lt;/h2&gt;&lt;p&gt;Starta ett nytt projekt, öppna ett, eller titta på exemplet från manualen.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&lt;b&gt;&amp;Recent projects&lt;/b&gt;</source>
        <translation>&lt;b&gt;&amp;Senaste projekt&lt;/b&gt;</translation>
    </message>
</context>
</TS>
