<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="en">
<context>
    <name>BlockDocumentation</name>
    <message numerus="yes">
        <source>All %n expectation(s) of the scenario held.</source>
        <translation>
            <numerusform>The scenario&apos;s one expectation held.</numerusform>
            <numerusform>All %n expectations of the scenario held.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n expectation(s) of the scenario failed: the diagram shows what the block did, not what the example expects.</source>
        <translation>
            <numerusform>%n expectation of the scenario failed: the diagram shows what the block did, not what the example expects.</numerusform>
            <numerusform>%n expectations of the scenario failed: the diagram shows what the block did, not what the example expects.</numerusform>
        </translation>
    </message>
    <message>
        <source>Library %1, version %2. Block version %3.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A system block: the simulator carries out its instruction %1, which the language cannot say.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pins</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pin</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Kind</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>When not bound</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>default %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>must be bound</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>may stay open</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Timing diagram</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No timing diagram: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The pins of the example project %1 while its scenario %2 runs, from power on.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>States</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>DiagCode holds the state as its 16-bit pattern (16#8000 reads -32768 in a register). The outputs each state switches on:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The outputs each state switches on:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>State</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Meaning</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Transitions</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Each scan takes at most one transition: the first of the state&apos;s list whose condition holds. The outputs then follow the new state. In the conditions * is AND, + is OR and / is NOT, as in the program.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>In state</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Condition</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Next state</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>always</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>any</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The other lines of the block&apos;s body, which the conditions and outputs use:</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>BlockText</name>
    <message>
        <source>input</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>output</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>bit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>register</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>double register</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>constant</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>default %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>must be bound</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>may stay open</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>library %1, version %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A system block: the simulator carries out its instruction %1.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>CommandLine</name>
    <message>
        <source>IDE for Pluto safety PLCs.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The project to open. Without it, the bundled example opens.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save a picture of the main window to OUT.png and exit.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>give at most one project file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the example</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 has no unit %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cannot write %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Draw with the light or dark palette, or the system&apos;s, this time.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>unknown theme &apos;%1&apos;; use light, dark or system</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Run the scenario in the simulator first, so the window shows the live state it ends in.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 has no sequence %2 in unit %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 has no gateway %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The page to show: ladder:N (the code of unit N as ladder), text:N (as text), ladder:N.S or text:N.S (its sequence S), io:N (its I/O options), asi:N (its AS-i options), variables:N, unit:N, gateway:N (the gateway with node address N), project, or properties (the project&apos;s properties and their proofs).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Prove the project&apos;s properties first (Build &gt; Prove All), so the window shows their results.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>unknown page &apos;%1&apos;; the pages are ladder:N, text:N, io:N, asi:N, variables:N and unit:N for unit N, ladder:N.S and text:N.S for its sequence S, gateway:N for gateway N, project and properties</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 does not read, so it has no properties page</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is a PL110 program: its pages are ladder:N (from rung N), text:N and variables:N</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 has no rung %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is a PL110 program; proofs are for Pluto projects</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>ElementKinds</name>
    <message>
        <source>Contact (NO)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Contact (NC)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Positive Edge (P)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Negative Edge (N)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not Positive Edge (/P)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not Negative Edge (/N)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>On-Delay Timer (TON)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pulse Timer (TPS)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Off-Delay Timer (TOF)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Comparison</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Coil</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Set Latch</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reset Latch</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Toggle Latch</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Jump</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sequence Reset</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Arithmetic</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Preset (time such as 2s50, or a register):</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Register:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Target register:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Step (number, or +n / -n relative):</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sequence (such as S0.1):</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Variable:</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>InstanceVariableText</name>
    <message>
        <source>Private variable #%1 of block %2 (line %3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pin %1 of block %2 (line %3)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>LadderActions</name>
    <message>
        <source>%1 (key %2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Text</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Show this code as text</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>After</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Insert in series after the selection</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Before</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Insert in series before the selection</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Parallel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Insert in a parallel branch around the selection</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Delete</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Delete the selected element</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;New Network</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A new network below the selected one</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Expand All</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Show the rungs of every network</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Collapse All</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Show only the comments of the networks</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Edit Network</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Gather the next edits of this network until Update</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Update</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Keep the edits of the network as one step</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Undo Network</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Drop the edits of the network</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Zoom In</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Zoom in</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Zoom Out</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Zoom out</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>100%</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Actual size</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Print...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Print the networks of this page</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PDF...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export the networks of this page as PDF</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>P&amp;roperties...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Toggle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Force...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Move Left</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Move Right</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Move Up</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Move Down</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Select Enclosing Group</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Select Network</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>New &amp;Config Option...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cu&amp;t Network(s)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Copy Network(s)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Paste Network(s)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Delete Network(s)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Network Co&amp;mment...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>New &amp;Step</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>New Se&amp;quence...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Function...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A new network holding a function block of the libraries</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>F</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Update Block</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Make Block...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Block Documentation...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Expand</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Collapse</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Edit Network</source>
        <comment>tool bar</comment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Undo Network</source>
        <comment>tool bar</comment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>New Network</source>
        <comment>tool bar</comment>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>ProjectComparison</name>
    <message numerus="yes">
        <source>%1 has %n error(s), so its behaviour cannot be compared. Build &gt; Compile lists them.</source>
        <translation>
            <numerusform>%1 has %n error, so its behaviour cannot be compared. Build &gt; Compile lists it.</numerusform>
            <numerusform>%1 has %n errors, so its behaviour cannot be compared. Build &gt; Compile lists them.</numerusform>
        </translation>
    </message>
    <message>
        <source>The project</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>ProjectMerging</name>
    <message>
        <source>Merge Project</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open the project to merge first (File &gt; Open); its units are then added to %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Add the units of this project to %1:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 cannot be merged into %2: every unit must keep its station and every symbolic name must be one project&apos;s only.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is merged into %2. Each name both used stays only in the units that define it; elsewhere its variable is written as its address.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is merged into %2.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>QObject</name>
    <message>
        <source>Option on</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Option off</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Added since validation on %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Changed since validation on %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>QPlatformTheme</name>
    <message>
        <source>OK</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save All</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Yes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Yes to &amp;All</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;No</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>N&amp;o to All</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Abort</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Retry</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ignore</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Close</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Discard</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Help</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Apply</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reset</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Restore Defaults</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>UnitCaption</name>
    <message>
        <source>Pluto %1 — %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pluto %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rs::ladder::Layout</name>
    <message>
        <source>step %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rs::pl110::Area</name>
    <message>
        <source>Digital inputs: I1-I8 on the terminals, the rest from expansion modules</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Digital outputs: Q1-Q8 are the relays, the rest go to expansion modules</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Markers</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Bistable relays: each energisation of the coil changes the contact</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Timers: the contact and the value in units of the time base</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Counters: the contact and the value</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Variables, kept by the battery</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Special markers: status, clocks, scan times and settings</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Analogue inputs, scaled by RANGE</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Analogue output, 0-10 V</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Timer presets</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Counter presets</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>EEPROM words, kept without power</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rs::ui::AdvancedSettingsDialog</name>
    <message>
        <source>&amp;Set the CAN bus cycle time:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Advanced Settings of Pluto %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>These settings have influence on the system response time. Do not change these values without a good knowledge of the function of the system. The hardware manual describes them.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> ms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Unset, the unit keeps its default. The simulator sends a unit&apos;s variables to the other units after every scan by default, and with a cycle time set, once per cycle time.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rs::ui::AsiOptionsPage</name>
    <message>
        <source>Bus Master</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Monitor only</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Monitor / Slave</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Monitor / Slave with 3 extra virtual slaves</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>AS-i bus not used</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Undefined</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Safe Input</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Nonsafe Std</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Nonsafe B</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Nonsafe A</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Combined Transaction B</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Combined Transaction A</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Analog</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Safe Output</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pluto as Safe Input</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No channel monitoring</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Channel monitoring</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Chan mon &amp; debounce filter</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Simultaneously</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Simultaneously &amp; debounce</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>AS-i general options</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>AS-i bus working mode</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Set AS-i bus working mode</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ASi &amp;slave address:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Set AS-i slave address</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Optimize for</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Short stop time (worst case, when error)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Disturbance immunity</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Disturbance immunity is not recommended when fewer than 20 slaves are used: the worst case stop time grows by 10 ms.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Set AS-i optimisation</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>AS-i slaves</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Slave No</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Type of Slave</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Model</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Param</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Profile/ID1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Channel Monitoring</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Time limit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reading the slaves from the bus, teaching safety codes, the code tables and changing a slave&apos;s address need a Pluto on a real AS-i bus, and are not in Rungsmith. A slave the code uses but this table does not define is a warning when compiling; the simulator gives each safe input slave two channels that follow its channel monitoring.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 — AS-i Options</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>How the unit works on its AS-i bus, and what each slave address holds (manual Part 1, 7.1).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 of %2 slaves are Safe Output or Pluto as Safe Input, the most a Pluto takes.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 takes the whole address: a B slave only goes beside an A/B slave.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 monitors its channels itself.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Set AS-i slave %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rs::ui::AsiProfileDialog</name>
    <message>
        <source>%1 (Outputs)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 (Safe slave)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 (Standard slave)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>AS-i Profile</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;I/O configuration:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>I&amp;D code:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ID&amp;2:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ID&amp;1:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Examples from the manual: S-0.B… a safe slave; S-7.B… a safe slave with outputs; S-7.0… a standard non-safe slave with 4 inputs and 4 outputs. The slave&apos;s own manual gives its profile.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Profile for %1 = %2</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rs::ui::BlockChooserDialog</name>
    <message>
        <source>Insert Function Block</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Type to filter by name or description</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Find:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Documentation...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The project&apos;s libraries hold no blocks. Add a library on the project page (Function libraries).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The block&apos;s documentation: states, transitions and a timing diagram</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rs::ui::BlockDocumentationDialog</name>
    <message>
        <source>%1 — Block Documentation</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rs::ui::BlockPinsDialog</name>
    <message>
        <source>%1 Pins</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Documentation...</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rs::ui::BusStatusView</name>
    <message>
        <source>Pluto %1: E0=No Error</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pluto %1: Er%2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Station</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pluto</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>State</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Code</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Missing</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ok, running</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ok, stopped</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>E0=No Error</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Er%1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Signature</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The program signature of the unit&apos;s compiled code, as rungsmith-cli signature prints it; it changes exactly when what the unit does changes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>G%1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Gateway %1 (%2)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rs::ui::CompareDialog</name>
    <message>
        <source>unit added</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>unit removed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>type changed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ID code changed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>I/O options changed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>exported and remanent variables changed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>names and descriptions changed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>comments changed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save Review as &amp;PDF...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Changes Since Validation</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Compare With</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 as it is now, against the version validated on %2 by %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 as it is now (new), against %2 (old)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Enter or a double click opens a network in the ladder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Comparing...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pluto %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pluto %1 %2 network %3: added</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pluto %1 %2 network %3: removed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pluto %1 %2 network %3: changed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No network, unit or option differs.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No change in behaviour; only the text changed.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No change in behaviour.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pluto %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Behaviour changed in %1 (project signature %2, was %3).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>There is nothing to save yet.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save Review as PDF</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PDF files (*.pdf)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rs::ui::CompileOutput</name>
    <message>
        <source>Compiling %1...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Compiling %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Wrote %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Build &gt; Compile (F7) checks the project and writes the compiled file.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>error: the compiled file was not written: %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rs::ui::CompileOutputModel</name>
    <message>
        <source>Pluto %1, line %2:%3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pluto %1, settings</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pluto %1, %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Project</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>error: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>warning: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Line %1 of the project file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Place</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Message</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rs::ui::CompileRun</name>
    <message>
        <source>Compiling</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Compiling %1...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Compile</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Compiled without errors. Save the project to write the compiled file.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Checked without errors. The compiled file is not written, as the project has unsaved changes.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rs::ui::ConfigOptionDialog</name>
    <message>
        <source>&amp;Enabled</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Config Option</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a memory, such as M%1.5</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Description:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Memory:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Describe the option: the description is what the check box says.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Only memories can be options (manual 11.6).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A config option is a check box on its network: it sets the memory when checked and resets it when not, so that one program serves machines with and without an option (manual 11.6).</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rs::ui::CsvExportDialog</name>
    <message>
        <source>Export Variable Names from Pluto %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>none</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Semicolon (;)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Comma (,)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Browse...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Variables:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Global and local</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>G&amp;lobal only</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>L&amp;ocal only</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Prefix for names:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sort by:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Variable</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Symbolic &amp;name</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Separator:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;File:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Export</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CSV files (*.csv);;All files (*)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rs::ui::CsvImportDialog</name>
    <message>
        <source>semicolons</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>tabs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>commas</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Import Variable Names to Pluto %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>none</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Browse...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;File:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Remove prefix from names:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Line</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Variable</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Symbolic Name</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Description</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Left out because</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Import</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CSV files (*.csv *.txt);;All files (*)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Choose a CSV file with the columns Variable, Symbolic Name and Description. Nothing changes before you press Import.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fields separated by %1. %2 to change, %3 unchanged, %4 left out.</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%n variable(s)</source>
        <translation>
            <numerusform>%n variable</numerusform>
            <numerusform>%n variables</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n row(s)</source>
        <translation>
            <numerusform>%n row</numerusform>
            <numerusform>%n rows</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>rs::ui::ElementDialog</name>
    <message>
        <source>Value:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Negated (passes power when false)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Output Properties</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Element Properties</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>such as &gt;= 5, = R0.2, += 2, ++</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Type:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>New &amp;Variable...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Comment:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>New Variable</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Address:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Symbolic &amp;name:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Write an address such as I%1.0, Q%1.2 or M%1.5.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Give the variable a name.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Name %1 %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rs::ui::ExternalCommDialog</name>
    <message>
        <source>External Communication of Pluto %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Which gateway data this unit receives: each External Comm Block takes one Data to Pluto packet of one gateway. A block that receives nothing for its timeout is cleared, and the Ext blocks of the code read it as not valid. The timeout must be greater than the gateway&apos;s cycle time (Gateway manual 4.5.1).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Block</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Gateway</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Packet</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Timeout</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Block &amp;%1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Gateway %1 (%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> ms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No timeout</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Gateway %1 (not in the project)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The project has no gateway: add one with Project &gt; New Gateway first.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rs::ui::ForcesView</name>
    <message>
        <source>&amp;Release</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Release &amp;All</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Variable</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Symbolic Name</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Forced To</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Release the chosen force: the program writes the variable again</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rs::ui::GatewayCommands</name>
    <message>
        <source>New &amp;Gateway...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Add a Pluto Gateway to the project&apos;s bus</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remove Gate&amp;way...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>New Gateway</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Every gateway node address 0-15 is in use.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A Pluto Gateway is a node of the Pluto bus that passes the Plutos&apos; data to a fieldbus. The Ethernet gateways (GATE-E1, GATE-E2) serve Modbus TCP while simulating.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Type:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Node address:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>New Gateway %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remove Gateway</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remove gateway %1 with its settings from the project? Units that receive its data keep their setting. Edit &gt; Undo brings it back.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remove Gateway %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rs::ui::GatewayPage</name>
    <message>
        <source>%1 (user block)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 Global data</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Remove Gateway...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Gateway</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Type:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Node address:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Set Gateway %1 Type</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Data to Pluto</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Packet &amp;%1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Enable Data to Pluto Packet %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Disable Data to Pluto Packet %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Enabled:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> ms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Cycle time:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Set Gateway %1 Cycle Time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No timeout</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>T&amp;imeout:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Set Gateway %1 Timeout</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Expected nodes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Set Gateway %1 Expected Nodes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Additional data areas</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Area</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pluto</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>IO-type</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Set Additional Data Area %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Gateway %1 (%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A node of the Pluto bus that passes the Plutos&apos; data to a fieldbus and takes data to them back (Gateway manual). Project %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>0 or %1-%2 ms on %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>0-%1 ms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not used</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pluto %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rs::ui::GatewayView</name>
    <message>
        <source>Data</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Hex</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Bits 31..0</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Modbus TCP is not served.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Serving Modbus TCP on %1; no client is connected.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Serving Modbus TCP on %1; clients: %2.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Gateway %1 (%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Node status</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Additional data %1 (Pluto %2, IO-type %3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Data to Pluto %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>valid; register 0 = %1, register 1 = %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not valid</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rs::ui::IoOptionsPage</name>
    <message>
        <source>Failsafe inputs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Failsafe inputs / non-failsafe outputs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Analogue inputs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Safety outputs: test pulses</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Undefined</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Input</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Output</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Light button</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Analogue 0-10 V</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Analogue 4-20 mA</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Counter, up</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Counter, up/down</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Static</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A_Pulse</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>B_Pulse</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>C_Pulse</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Signal</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Options</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Type of signal</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Signal shape</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No_Test_Pulse</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Non_Inv</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No_Filt</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>X_Talk</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The configuration must match the wiring. Q0..Q3 are not listed: they can be used in one way only.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 — I/O Options</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Choose from the lists what each terminal is wired for; combinations the unit cannot take are not offered.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Set I/O Options of %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Used by block</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rs::ui::LadderPage</name>
    <message>
        <source>%1 — PLC Code</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 — Sequence %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The project changed, so the network&apos;s edits were dropped.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Step %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not done: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Insert %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A network starts with its output: insert a coil, latch, jump or arithmetic box first, then its contacts.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Change Element</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Change Output</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Delete Element</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Delete Output</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>This sequence has no step yet.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>New network: insert its output first (L coil, S set, R reset, J jump ...).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Options stand at the start of the PLC code: open the PLC Code page.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>New Config Option</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Change Config Option</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Enable Option</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Disable Option</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%n network(s) copied.</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>The clipboard holds no networks.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The clipboard holds no networks: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>Paste %n Network(s)</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Delete %n Network(s)</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>Insert the network&apos;s output before its comment.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Comment Network %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Step Comment</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Comment of step %1:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Comment Step %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>New Step of Sequence %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Step %1 added: insert the output of its first network.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Edit Network %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Network %1 updated.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The edits of network %1 were dropped.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not moved: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Move Element</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export PDF</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PDF documents (*.pdf)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Exported to %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Network %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No networks in this code.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>This code has %1 lines, more than the ladder page draws (%2).
Its text page (F6) shows and edits it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Could not export to %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Could not export to %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Network %1 is in edit mode: Update (%2) keeps its edits as one step, Undo (%3) drops them.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No networks yet. Press %1, or right-click &gt; New Network, then insert the network&apos;s output (L coil, S set, R reset, J jump ...) and its contacts.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Simulating: a click or %1 on an input toggles it; a right click or %2 forces any element&apos;s variable. Editing ends the simulation.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Keys: %1 insert the toolbar&apos;s elements; %2 %3 %4 before, after, parallel; %5 properties; %6 delete; %7 new network; %8 edit mode.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Made by %1 version %2; the library has version %3 (Update Block).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Insert Block %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No library of the project has this block: add its library on the project page to bind its pins.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Change Block Pins</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Select a block made by another version of its block to update it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Update Block %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Select a block network whose block a library of the project has.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Make Block takes networks of one step.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A block cannot hold a block: leave block networks out of the selection.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save the project first: its blocks go to a library beside it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Make Block</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The block could not be written: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The library %1 is not among the project&apos;s libraries.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Make Block %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Block %1 is in %2; the F list offers it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Comment of network %1:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not copied: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Copy Element</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 did not run: its step is not active</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is true</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is false</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is on</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is off</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is open</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is on through %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is off: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is forced on; its rung is off: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is on; its rung is off: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is forced off; its rung is on</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is off; its rung is on</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is forced off; its rung is on through %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is off; its rung is on through %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Moving: drop it before or after an element. Release Shift to copy.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Copying: drop it before or after an element. Hold Shift to move.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Password protected, open with permission to configure: a click or %1 on a Config Option&apos;s box checks or unchecks it; nothing else can change.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rs::ui::MainWindow</name>
    <message>
        <source>&amp;Undo</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cu&amp;t</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Copy</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Paste</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Select &amp;All</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Format Document</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Rewrite the text in the canonical layout</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;About Rungsmith</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open &amp;Recent</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Problems</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Line %1, Column %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%n error(s)</source>
        <translation>
            <numerusform>%n error</numerusform>
            <numerusform>%n errors</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n warning(s)</source>
        <translation>
            <numerusform>%n warning</numerusform>
            <numerusform>%n warnings</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Not formatted: the text has %n error(s).</source>
        <translation>
            <numerusform>Not formatted: the text has %n error.</numerusform>
            <numerusform>Not formatted: the text has %n errors.</numerusform>
        </translation>
    </message>
    <message>
        <source>Formatted.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>About Rungsmith</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The project reads without errors now; its pages are back.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Save Project</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save Project &amp;As...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Close Project</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pr&amp;eferences...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>New &amp;Pluto...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>New &amp;Sequence...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Remove Pluto...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Compile</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Check the project and write the compiled file (.hps)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Export</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Project</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Build</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Main</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Projects</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Output</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Code With Errors</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The code of Pluto %1 has errors, so it cannot be read into the project.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Keep editing to fix them, or discard the changes since the code last read without errors.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Keep Editing</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Undo %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Redo %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export Program &amp;Text...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Import Variable Names to Pluto...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>E&amp;xport Variable Names from Pluto...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Remanent Variables...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Ladder or Text</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Show the code as ladder networks or as text</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;h3&gt;Rungsmith %1&lt;/h3&gt;&lt;p&gt;An IDE for Pluto safety PLCs: projects, units, I/O options, variables and the program as ladder and as text, checked, compiled and simulated.&lt;/p&gt;&lt;p&gt;Built with Qt %2 and QScintilla %3.&lt;/p&gt;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Compile</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 has changes that are not saved.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The compiled file (.hps) is written beside the project and must come from the saved file. Save first, or only check the changes without writing the compiled file.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Save and Compile</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>C&amp;heck Only</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Mark as &amp;Validated...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Record this version&apos;s program signatures as the validated baseline</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is marked as validated.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Compare &amp;With...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>What differs between another version of the project and this one, network by network</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Compare With</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Rungsmith projects (*.sps)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Compare With Va&amp;lidated</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>What changed since the project was marked as validated</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Merge Project (&amp;ignore conflicts)...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Merge Project...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 (read only)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 (config options only)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>New &amp;Gateway...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remove Gate&amp;way...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Running %1 in the simulator.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Prove All</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Prove every property of the project for every input sequence, or find one that breaks it</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rs::ui::MakeBlockDialog</name>
    <message>
        <source>Make Block</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>What the block does, for its users</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Block &amp;name:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Library file:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Description:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>What the networks read becomes an input, what they write an output; a memory only they use becomes the block&apos;s own. Name the pins as the block&apos;s users will see them. Comments on the statements do not go into the block.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Name</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pin or private variable</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stands for</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>private memory</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The library file is a name of letters, digits and &apos;_&apos; in the project&apos;s folder, such as My_Blocks.rslib.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rs::ui::MarkValidatedDialog</name>
    <message>
        <source>Mark as Validated</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Records this version&apos;s program signatures as the validated baseline: from now on the review says what changed since. It changes nothing the units do.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Validated &amp;by:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Comment:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Mark as Validated</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>The project has %n error(s) and cannot be validated. Build &gt; Compile (F7) lists them.</source>
        <translation>
            <numerusform>The project has %n error and cannot be validated. Build &gt; Compile (F7) lists it.</numerusform>
            <numerusform>The project has %n errors and cannot be validated. Build &gt; Compile (F7) lists them.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>rs::ui::NetworkCommentDialog</name>
    <message>
        <source>Network Comment</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Return starts a new line; Ctrl+Return confirms.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rs::ui::NewProjectDialog</name>
    <message>
        <source>New project</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Include source code in compiled file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>New Project</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>For your own notes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The project name is downloaded to the units and checked when going online. With the source code included, a program uploaded from a unit can be opened again; the file grows and anyone with the password can change the program.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Project &amp;name:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Project &amp;description:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pluto safety PLCs (1 to 32 units on one bus)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pixsys PL110 (one ladder PLC)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Target:</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rs::ui::NewUnitDialog</name>
    <message>
        <source>New Pluto</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Choose the Pluto type and a station number that no other unit of the project has. The station number is part of every address of the unit: inputs of Pluto 1 are I1.0, I1.1, ...</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rs::ui::OpenProjects</name>
    <message>
        <source>Pluto projects (*.sps);;All files (*)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;New Project...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Start a new project</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Open Project...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open a project file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Save Project</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save the project</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save Project &amp;As...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save the project under a new name</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save A&amp;ll</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save every open project</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Close Project</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Close the project</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Program Text...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Write the program in the language alone, for a text editor or the original compiler</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open &amp;Example Project</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Clear Menu</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Opened %1. It has errors: fix them in its text.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Opened %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open Project</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Could not open “%1”.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save Project</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The code of Pluto %1 has errors, so your last changes to it are not part of the project. Save the project without them?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save Project As</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Could not save “%1”.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Unsaved Changes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>“%1” has changes that are not saved. Save them?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export Program Text</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>-program</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Wrote the program text to %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Autosave failed: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Recover Projects</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Rungsmith was not closed properly. These projects have changes that were saved automatically:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Recover</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pass&amp;word Protect...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Protect the project with a password, change its protection or take it off</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>“%1” was changed outside Rungsmith after it was password protected.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Password Protect</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Protected with a password: saving writes the protection.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remove Password Protection</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The password protection is off once the project is saved.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The first change is at line %1: the signature the password made does not cover it. The project opens read only; its protection is evidence of changes, not a lock, and the file stays readable text. The holder of the main password can accept the change once it is reviewed.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open &amp;Read Only</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Accept the Change...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Opened %1 in a PL110 window</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rs::ui::PasswordProtectDialog</name>
    <message>
        <source>&amp;Password protect source file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Change of config options</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Only possible with &amp;main password</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Possible &amp;without password</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Config &amp;options password required</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Password Protect</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The file keeps no password: it keeps a signature only the password can make, so a change made outside Rungsmith shows. Anybody can still open and read the file.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ma&amp;in password:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Repeat:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Config options pa&amp;ssword:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>R&amp;epeat:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Give the main password.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The main password and its repetition differ.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Give the config options password.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The config options password and its repetition differ.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The config options password must differ from the main password, or it would give full permission.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rs::ui::PermissionNote</name>
    <message>
        <source>Password protected, open read only: nothing can change.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Password protected, open with permission to configure: only Config Options can change, on the ladder.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rs::ui::Pl110Document</name>
    <message>
        <source>It is not a PL110 program: its first line is not “$target PL110”.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Untitled</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The program has no file yet: use Save As.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rs::ui::Pl110LadderView</name>
    <message>
        <source>INIT — runs once, before the first scan</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>MAIN — runs every scan</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Rung %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The program has no rungs yet: write them on the Program page.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rs::ui::Pl110NamesPage</name>
    <message>
        <source>&amp;Import CSV...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Name addresses from a CSV file: Variable, Symbolic Name, Description</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>E&amp;xport CSV...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Write the names and descriptions to a CSV file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Address</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Name</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Description</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Value</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Addresses</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Program writes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Modbus (word / bit)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>What it holds</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Names: double-click a cell to change it; the last row names another address.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Memory areas of the PL110 (datasheet, section 2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>yes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>–</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> (read only)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Type an address such as I6, Q4, M10 or VW20</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 rewrites the program text; fix its errors on the Program page first, so that no line is lost.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Naming</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>“%1” is not a PL110 address</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Name %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Import Names</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CSV files (*.csv *.txt);;All files (*)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Importing names</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>Nothing was imported: %n row(s) could not be read.
%1</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Imported %n name(s) from %1</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>CSV, comma-separated (*.csv)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CSV, semicolon-separated, as spreadsheets in Swedish and German expect (*.csv)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export Names</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Exported the names to %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Type a value to set the input or force the variable</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Start the simulation to set values.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>“%1” is not a whole number</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rs::ui::Pl110Simulation</name>
    <message>
        <source>The program changed: the simulation stopped. Start it again to run the new program.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The program has errors; fix them to simulate it.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rs::ui::Pl110WaveformPanel</name>
    <message>
        <source>Add a variable to plot: an address or a name</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export VCD</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is plotted already</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Nothing is recorded yet: start the simulation or run a scenario.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Value Change Dumps (*.vcd);;All files (*)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rs::ui::Pl110Window</name>
    <message>
        <source>error</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>warning</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Ladder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Names and Areas</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Problems</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Scenario Results</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;New PL110 Program</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>New program</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Open...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Save</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save &amp;As...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Close</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Undo %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Redo %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Format Text</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Write the program as the printer writes it: one space around operators, names as declared</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fix the errors first: formatting would drop the lines that do not read.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Format Text</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Program Text</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Simulation</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Start</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Run the program on the simulated clock; click an input&apos;s contact to switch it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>S&amp;top</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Hold the program and the clock; the state stays shown</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Single S&amp;can</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Reset</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Power on again at time 0; inputs set and forces stay</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Run Sce&amp;nario...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Run a scenario file (.scn) from power on and list its results</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Simulation</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Typing</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%n rung(s), no errors</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n error(s): the ladder shows the lines that read</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>%1[*] — PL110 — Rungsmith</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Simulating: %1 s, scan %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stopped at %1 s, scan %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Start the simulation (F5) to switch inputs from the ladder.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 set to %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 forced to %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Set %1 to 1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Force %1 to 1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Set %1 to 0</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Force %1 to 0</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Let go of %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Release %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Show in Program Text</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save PL110 Program As</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PL110 programs (*.sps)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save As</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Close</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save the changes to %1?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open PL110 Program</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PL110 programs (*.sps);;All files (*)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Could not open “%1”.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Run Scenario</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Scenarios (*.scn);;All files (*)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: %2 passed, %3 failed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 did not run: it has errors</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;New Rung...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Write a rung after the selected one: its output, &apos;=&apos; and its condition</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Edit...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Change the selected contact, or the selected rung as its line</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Contact &amp;After...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Contact &amp;Before...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Contact in &amp;Parallel...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Delete</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Delete the selected element; with the output selected, the rung</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Move Rung &amp;Up</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Move Rung Do&amp;wn</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>While simulating: switch the selected contact&apos;s input, or force its variable the other way</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ladder or &amp;Text</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Switch between the ladder and the program text at the same rung</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fix the errors on the Program page first: the ladder&apos;s edits rewrite the text, and lines with errors would be lost.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 was not done: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Column %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>New Rung</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The rung as its line is written: its output, &apos;=&apos; and its condition, for example Q1 = I1 * /I2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Edit Rung</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The rung as its line is written: its output, &apos;=&apos; and its condition, and a comment after &apos;;&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Edit Element</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The element as a rung writes it: a contact such as I3 or /I3, a comparison such as (VW1 &gt;= 10), NOT, P or N; several joined by * and + take its place together</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Contact in Parallel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Contact Before</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Contact After</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A contact such as I3 or /I3, a comparison such as (VW1 &gt;= 10), NOT, P or N, or several joined by * and +</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Delete Rung</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Delete Element</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Move Rung Up</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Move Rung Down</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ladder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Program</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Names and Areas</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>T&amp;oggle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Waveform</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Serve &amp;Modbus RTU</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Answer Modbus RTU requests on a pseudo-terminal, as the PL110&apos;s serial port, from the simulated memory (slave 1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Modbus RTU: %1, slave 1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Plot in &amp;Waveform</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Record the selected contact&apos;s or output&apos;s variable in the waveform</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is plotted in the waveform</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Autosave failed: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>New Rung in &amp;INIT...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Write a rung at the end of INIT, which runs once before the first scan</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>New Rung in INIT</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rs::ui::PlutoLexer</name>
    <message>
        <source>Default</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Comment</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Structured record</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Declaration</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Declaration option</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Directive</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Directive text</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Step header</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Address</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Instruction</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Time constant</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Operator</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Symbolic name</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Invalid text</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rs::ui::PreferencesDialog</name>
    <message>
        <source>Start with ladder diagrams &amp;expanded</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Unconfigured I/O warnings at compile time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Preferences</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ladder colours</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ladder background:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Focused ladder background:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ladder component body:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ladder lines:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ladder lines off:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ladder lines on:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 ms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Update interval in online mode. A shorter interval makes the computer slower.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>System language</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Follow the system</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Light</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Dark</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> min</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A new language shows when Rungsmith starts again.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>General</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Screen update &amp;interval:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Language:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Theme:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Autosave every:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>From %1 to %2 minutes. A crash loses at most this much work.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Theme &amp;Colours</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Draw the ladder in the theme&apos;s colours again</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Theme</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>As the theme draws it; click to choose a colour</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Simulated gateway</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Modbus TCP &amp;address:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Modbus TCP &amp;port:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Where Serve Modbus TCP listens while simulating. 127.0.0.1 lets only this computer connect; 0.0.0.0 the network.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rs::ui::ProblemsView</name>
    <message>
        <source>Location</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Message</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Error</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Warning</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No problems found.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rs::ui::ProgramEditor</name>
    <message>
        <source>Error message</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Warning message</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rs::ui::ProjectDocument</name>
    <message>
        <source>Expand Block Instances</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Untitled</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The project is open read only: nothing in it can change.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The project is open with permission to configure: only its Config Options can change.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>It is a program for the Pixsys PL110, not a Pluto project: File &gt; Open opens it in a PL110 window.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rs::ui::ProjectPage</name>
    <message>
        <source>Add &amp;Standard Library</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Add &amp;User Library...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Remove Library</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No standard library is installed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Function &amp;libraries:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Every library found: the standard ones and those in the project&apos;s folder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A user library in the project&apos;s folder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A standard library</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 (not found)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Add Library %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Add User Library</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Function block libraries (*.rslib)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remove Library %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Include source code in compiled file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Project &amp;name:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Project &amp;description:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>File:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Units:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Include Source Code</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Leave Out Source Code</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Project %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not saved yet</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>None yet. Add one with Project &gt; New Pluto.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Rename Project</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Change Project Description</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Program signature:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Validated:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>on %1 by %2 (signature %3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not yet (Project &gt; Mark as Validated)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Since then:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>computing...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>unknown while the project has errors (Build &gt; Compile shows them)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no change in behaviour since validation on %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>changed since validation on %1 in %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%n network(s) added, changed or removed</source>
        <translation>
            <numerusform>%n network added, changed or removed</numerusform>
            <numerusform>%n networks added, changed or removed</numerusform>
        </translation>
    </message>
    <message>
        <source>Protection:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>changed outside Rungsmith after it was password protected (first at line %1): open read only</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>none (File &gt; Password Protect)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>only with the main password</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>without a password</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>with their own password</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>with full permission</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>with permission to configure</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>read only</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The protection&apos;s public key: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>password protected, key %1 …
Config Options change %2; opened %3</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rs::ui::ProjectTree</name>
    <message>
        <source>Projects</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Project Text</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>I/O Options</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Variables</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PLC Code</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sequence %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>AS-i Options</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Gateway %1 (%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Properties</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rs::ui::ProofResultsView</name>
    <message>
        <source>Line</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Property</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Result</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Scans</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reason</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>proved</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>failed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>unknown</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>covered</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>never covered</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>waiting</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>proving…</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>Proved by induction over %n scan(s)</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>A counterexample of %n scan(s) from power on</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Reached in %n scan(s) from power on</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>Open Counterexample runs it in the simulator</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not proved</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rs::ui::ProofRun</name>
    <message>
        <source>The property has no counterexample to open.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A scenario is running already.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cancelled</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>the time limit of %n s per property ran out</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>no counterexample within %n scans</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>internal error: the prover&apos;s counterexample of %n scans does not replay (%1); please report it</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>internal error: the prover&apos;s witness of %n scans does not replay (%1); please report it</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>The project has %n error(s); compile it (F7) to see them.</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
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
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open Counterexample</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Complete Word</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Insert Example</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stop proving; the properties proved so far keep their results</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Run the chosen property&apos;s counterexample (or witness) in the simulator, with the waveform, stopped at its last scan</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;p&gt;No properties yet. Write one a line, with conditions as in the code (operands, names, &lt;code&gt;/&lt;/code&gt;, &lt;code&gt;*&lt;/code&gt;, &lt;code&gt;+&lt;/code&gt;, parentheses):&lt;/p&gt;&lt;p&gt;&lt;code&gt;always A&lt;/code&gt;, &lt;code&gt;never A&lt;/code&gt;, &lt;code&gt;always A -&amp;gt; B&lt;/code&gt;, &lt;code&gt;always A -&amp;gt; within 20ms B&lt;/code&gt;, &lt;code&gt;always A -&amp;gt; next B&lt;/code&gt;, &lt;code&gt;assume A&lt;/code&gt;, &lt;code&gt;cover A&lt;/code&gt;.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Prove All&lt;/b&gt; proves each for every input sequence, or finds one that breaks it and opens it in the simulator.&lt;/p&gt;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Put a commented example of every kind of line in the text</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 — Properties</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Saved with the project, beside its file, once it has one: its name with the extension .prop.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Saved with the project as %1, which rungsmith-cli prove takes too.</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>The properties have %n error(s), marked in the text: nothing is proved until they read.</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>Write a property first: there is nothing to prove.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Compiling %1...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Property %1 of %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Proving property %1 of %2...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cancelled</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 proved, %2 failed, %3 unknown</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cancelled: %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The properties or the project changed since this proof; Prove All again for results of the text as it is now.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open Witness</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rs::ui::ProtectedOpenDialog</name>
    <message>
        <source>Open with &amp;full permission</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open with permission to &amp;configure</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open in &amp;read only mode</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open Protected Project</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>“%1” is password protected. It opens without a password, but then nothing in it can change.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Takes the main password; everything can change.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Takes no password; only the Config Options can change.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Takes the config options password, or the main one; only the Config Options can change.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Takes no password; nothing can change.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Password:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The password does not open the project with this permission.</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>The password does not open the project with this permission. Try again in %n second(s).</source>
        <translation>
            <numerusform>The password does not open the project with this permission. Try again in %n second.</numerusform>
            <numerusform>The password does not open the project with this permission. Try again in %n seconds.</numerusform>
        </translation>
    </message>
    <message>
        <source>Accept the Change</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rs::ui::RemanentDialog</name>
    <message>
        <source>Remanent Variables of Pluto %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remanent variables keep their value when the power is off. Registers R100-R131 and memories M100-M131 can be remanent in any combination, except that with all the registers no memory can be.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>All</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>None</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Registers</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Memories</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>All 32 registers are remanent, so no memory can be.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rs::ui::ScenarioFileViewer</name>
    <message>
        <source>&amp;Open in Editor</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 (read-only)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1, line %2</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rs::ui::ScenarioResultsView</name>
    <message>
        <source>%1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: %2 passed, %3 failed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Double-click to show line %1 of %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: cancelled at t = %2 s, %3 passed, %4 failed so far</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rs::ui::SignatureLabel</name>
    <message>
        <source>Changes exactly when what the program does changes; formatting, comments, names and descriptions leave it as it is</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>computing...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>none while the project has errors (Build &gt; Compile shows them)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rs::ui::SimulationControls</name>
    <message>
        <source>t = %1 s  (%2 scans)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Simulate</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Simulate</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Si&amp;mulation Mode</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Run the project in the simulator and show its live state; editing ends it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Start</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Run the program on the simulated clock</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>S&amp;top</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Hold the program and the clock; the state stays shown</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Single S&amp;can</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Run one scan of every unit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Reset</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Power on again at time 0; forces stay</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Run Sce&amp;nario...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Run a scenario file (.scn) and list its results</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Real time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>10x</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>As fast as possible</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>How fast the simulated clock runs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The simulated clock</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>S&amp;peed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not simulating</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rs::ui::SimulationMode</name>
    <message>
        <source>Forces</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Watch</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Waveform</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Bus Status</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Scenarios</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Simulation</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Run Scenario</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Scenarios (*.scn);;All files (*)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Simulating %1. Editing the project ends the simulation.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is not an input: right-click it to force it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Force %1 to &amp;0</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Force %1 to &amp;1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Force %1 to a &amp;Value...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Force</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Value of %1:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Release %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Watch %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stop the scenario; the simulation shows where it got</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Scenario: %1 of %2 s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A scenario is running already.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Scenario %1 cancelled at t = %2 s.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Serve &amp;Modbus TCP</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Gateways</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Answer Modbus TCP clients for the project&apos;s Ethernet gateway while simulating, at the address the preferences give</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Serve Modbus TCP</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cannot serve Modbus TCP on %1:%2: %3. Choose another address or port in the preferences.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Serving Modbus TCP on %1.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rs::ui::SimulationSession</name>
    <message>
        <source>No project is open.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The project&apos;s text has errors; fix them before simulating.</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>The project has %n error(s); compile it (F7) to see them.</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>The project has no Pluto to simulate.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The project changed, so the simulation ended. Start it again to simulate the new version.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The project was closed, so the simulation ended.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The simulation is not running.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A scenario is running already.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rs::ui::TextPage</name>
    <message>
        <source>%1 — Project Text</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>This file has errors, so it is shown as text until they are fixed. Lines with errors could not be shown on the other pages.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 — PLC Code</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Edit Code of Pluto %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ladder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Show this code as ladder networks</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rs::ui::UnitCommands</name>
    <message>
        <source>New &amp;Pluto...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Add a Pluto unit to the project</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>New &amp;Sequence...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Remove Pluto...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Re&amp;manent Variables...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Import Variable Names (CSV)...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>E&amp;xport Variable Names (CSV)...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>New Pluto</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The project has 32 units, the most a bus can have.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>New Pluto %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>New Sequence</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pluto %1 has all nine sequences.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sequence number for Pluto %1 (1-9):</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>New Sequence %1 of Pluto %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remove Pluto</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remove %1 with its code, names and descriptions from the project? Edit &gt; Undo brings it back.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remove Pluto %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Set Remanent Variables of Pluto %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remanent Variables</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Import Variable Names to Pluto %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>Imported %n variable(s).</source>
        <translation>
            <numerusform>Imported %n variable.</numerusform>
            <numerusform>Imported %n variables.</numerusform>
        </translation>
    </message>
    <message>
        <source>Export Variable Names</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Wrote %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rs::ui::UnitPage</name>
    <message>
        <source>&amp;Remanent Variables...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>This unit has code but no &apos;! id_pluto&apos; declaration. Any change below writes one.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Variables on the bus and at power off</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export variables:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remanent variables:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Station %1 of project %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>need instruction set 3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 of %2 extra telegram pairs (project: %3 of %4)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>this type has none</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>none</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Change Pluto %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>This removes %n declaration(s), name(s), description(s) or attribute(s) of the unit that the new type or instruction set cannot have. Change it?</source>
        <translation>
            <numerusform>This removes %n name, declaration, description or attribute of the unit that the new type or instruction set cannot have. Change it?</numerusform>
            <numerusform>This removes %n declarations, names, descriptions or attributes of the unit that the new type or instruction set cannot have. Change it?</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 of %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 of %2 (%3 of them by block instances)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Resources in use</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Timers:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Memories:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Registers:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Program signature:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Review</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Advanced Settings...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CAN bus cycle time:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 ms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the unit&apos;s default</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Set CAN Bus Cycle Time of Pluto %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>E&amp;xternal Communication...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Gateway data received:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>block %1 from gateway %2, packet %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Set External Communication of Pluto %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rs::ui::UnitSettingsForm</name>
    <message>
        <source>Instruction set &amp;2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Instruction set &amp;3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Instruction set 3 needs Pluto OS 3.0 or later. It adds the off-delay timer, multiplication and division with constants, double registers (32 bits), &quot;not positive edge&quot; and &quot;not negative edge&quot;, register bits and a larger address range.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>IDFIX number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No IDFIX</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>12 hexadecimal digits, e.g. 000034AD4AE1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>For your own notes; not downloaded to the unit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Station number:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pluto &amp;type:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Instruction set:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;IDFIX:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Description:</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>The IDFIX number has %n of its 12 hexadecimal digits. Choose &quot;No IDFIX&quot; if the unit has no identifier circuit.</source>
        <translation>
            <numerusform>The IDFIX number has %n of its 12 hexadecimal digits. Choose &quot;No IDFIX&quot; if the unit has no identifier circuit.</numerusform>
            <numerusform>The IDFIX number has %n of its 12 hexadecimal digits. Choose &quot;No IDFIX&quot; if the unit has no identifier circuit.</numerusform>
        </translation>
    </message>
    <message>
        <source>The %1 runs instruction set 2 only.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>IDFIX-PROG</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A programmable identifier circuit: the number given here is the one written to it (Write IDFIX, on the unit).</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rs::ui::VariableTableModel</name>
    <message>
        <source>Safety Inputs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Safety Outputs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>NonSafety Outputs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Global Memories</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Memories</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Registers</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Double Registers</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>System Memories</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>System Registers</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>AS-i Slaves</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Used in the code of the unit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>[G] Global variable: visible to the other Plutos on the bus.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>[E] Exported variable: made visible to the other Plutos on the bus.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>[R] Remanent variable: keeps its value when the power is off.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The manuals&apos; name of this system variable</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Status</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Variable</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Attributes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Symbolic Name</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Description</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remove Name of %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Name %1 %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Describe %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 F</source>
        <comment>a forced value</comment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Forced to %1 in the simulation; release it in the Forces list.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The value after the last scan of the simulation</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>used</source>
        <comment>a variable the code reads or writes</comment>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rs::ui::VariablesPage</name>
    <message>
        <source>Filter by variable, name or description</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Variable attributes: [G] global, visible to the other Plutos on the bus; [E] exported; [R] remanent, kept at power off.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Remanent Variables...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Import CSV...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>E&amp;xport CSV...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 — Variables</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export variables need instruction set 3.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export variables: %1 of %2 extra telegram pairs (project: %3 of %4)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stop Exporting %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Export Variable [E]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Import Variable Names from CSV...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>E&amp;xport Variable Names to CSV...</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rs::ui::WatchView</name>
    <message>
        <source>Symbolic name or address, e.g. Q0.2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Watch</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Variable</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Symbolic Name</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Value</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Type a value to set an input or force any other variable</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Type a symbolic name or an address.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 F</source>
        <comment>a forced value</comment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Forced</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>“%1” is not a number.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Release Force</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stop &amp;Watching</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A channel is open (0) or closed (1).</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rs::ui::WaveformPanel</name>
    <message>
        <source>Add a variable to plot</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remove</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stop plotting the chosen variable</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Zoom in: show less time (Ctrl+wheel)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Zoom out: show more time (Ctrl+wheel)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Show the whole recording</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export VCD...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Write the recording as a Value Change Dump, for GTKWave</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export VCD</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Nothing is recorded yet: start the simulation or run a scenario.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Value Change Dumps (*.vcd);;All files (*)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remove All</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stop plotting every variable, also those a scenario added</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rs::ui::WaveformView</name>
    <message>
        <source>Add variables to plot them over the simulation&apos;s time.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rs::ui::WelcomePage</name>
    <message>
        <source>&lt;h2&gt;No project is open&lt;/h2&gt;&lt;p&gt;Start a new project, open one, or look at the example from the manual.&lt;/p&gt;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;b&gt;&amp;Recent projects&lt;/b&gt;</source>
        <translation type="unfinished"></translation>
    </message>
</context>
</TS>
