<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="sv">
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
        <source>The page to show: text:N, the program text of unit N.</source>
        <translation>Sidan som ska visas: text:N, programtexten för enhet N.</translation>
    </message>
    <message>
        <source>give at most one project file</source>
        <translation>ange högst en projektfil</translation>
    </message>
    <message>
        <source>unknown page &apos;%1&apos;; the pages so far are text:N, the program text of unit N</source>
        <translation>okänd sida &apos;%1&apos;; sidorna hittills är text:N, programtexten för enhet N</translation>
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
</context>
<context>
    <name>rs::ui::MainWindow</name>
    <message>
        <source>Pluto projects (*.sps);;All files (*)</source>
        <translation>Pluto-projekt (*.sps);;Alla filer (*)</translation>
    </message>
    <message>
        <source>untitled.sps</source>
        <translation>namnlös.sps</translation>
    </message>
    <message>
        <source>&amp;New</source>
        <translation>&amp;Ny</translation>
    </message>
    <message>
        <source>Start a new project</source>
        <translation>Starta ett nytt projekt</translation>
    </message>
    <message>
        <source>&amp;Open...</source>
        <translation>&amp;Öppna...</translation>
    </message>
    <message>
        <source>Open a project file</source>
        <translation>Öppna en projektfil</translation>
    </message>
    <message>
        <source>&amp;Save</source>
        <translation>&amp;Spara</translation>
    </message>
    <message>
        <source>Save the project</source>
        <translation>Spara projektet</translation>
    </message>
    <message>
        <source>Save &amp;As...</source>
        <translation>Spara s&amp;om...</translation>
    </message>
    <message>
        <source>Save the project under a new name</source>
        <translation>Spara projektet under ett nytt namn</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Avsluta</translation>
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
        <source>Open &amp;Example Project</source>
        <translation>Öppna &amp;exempelprojekt</translation>
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
        <translation>Öppna &amp;senaste</translation>
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
        <source>File</source>
        <translation>Arkiv</translation>
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
        <source>Save Project As</source>
        <translation>Spara projekt som</translation>
    </message>
    <message>
        <source>Save Project</source>
        <translation>Spara projekt</translation>
    </message>
    <message>
        <source>Could not save “%1”.</source>
        <translation>Kunde inte spara ”%1”.</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>Sparade %1</translation>
    </message>
    <message numerus="yes">
        <source>Not formatted: the text has %n error(s).</source>
        <translation>
            <numerusform>Inte formaterad: texten har %n fel.</numerusform>
            <numerusform>Inte formaterad: texten har %n fel.</numerusform>
        </translation>
    </message>
    <message>
        <source>The text is already formatted.</source>
        <translation>Texten är redan formaterad.</translation>
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
        <source>&lt;h3&gt;Rungsmith %1&lt;/h3&gt;&lt;p&gt;An IDE for Pluto safety PLCs: write and check programs in the Pluto text language.&lt;/p&gt;&lt;p&gt;Built with Qt %2 and QScintilla %3.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;Rungsmith %1&lt;/h3&gt;&lt;p&gt;En utvecklingsmiljö för Pluto säkerhets-PLC: skriv och kontrollera program i Plutos textspråk.&lt;/p&gt;&lt;p&gt;Byggd med Qt %2 och QScintilla %3.&lt;/p&gt;</translation>
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
        <source>&amp;Clear Menu</source>
        <translation>&amp;Töm menyn</translation>
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
</TS>
