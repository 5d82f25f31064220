<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de">
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
        <source>The page to show: text:N, the program text of unit N.</source>
        <translation>Die anzuzeigende Seite: text:N, der Programmtext der Einheit N.</translation>
    </message>
    <message>
        <source>give at most one project file</source>
        <translation>höchstens eine Projektdatei angeben</translation>
    </message>
    <message>
        <source>unknown page &apos;%1&apos;; the pages so far are text:N, the program text of unit N</source>
        <translation>unbekannte Seite &apos;%1&apos;; bisher gibt es die Seiten text:N, der Programmtext der Einheit N</translation>
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
</context>
<context>
    <name>rs::ui::MainWindow</name>
    <message>
        <source>Pluto projects (*.sps);;All files (*)</source>
        <translation>Pluto-Projekte (*.sps);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>untitled.sps</source>
        <translation>unbenannt.sps</translation>
    </message>
    <message>
        <source>&amp;New</source>
        <translation>&amp;Neu</translation>
    </message>
    <message>
        <source>Start a new project</source>
        <translation>Ein neues Projekt beginnen</translation>
    </message>
    <message>
        <source>&amp;Open...</source>
        <translation>&amp;Öffnen...</translation>
    </message>
    <message>
        <source>Open a project file</source>
        <translation>Eine Projektdatei öffnen</translation>
    </message>
    <message>
        <source>&amp;Save</source>
        <translation>&amp;Speichern</translation>
    </message>
    <message>
        <source>Save the project</source>
        <translation>Das Projekt speichern</translation>
    </message>
    <message>
        <source>Save &amp;As...</source>
        <translation>Speichern &amp;unter...</translation>
    </message>
    <message>
        <source>Save the project under a new name</source>
        <translation>Das Projekt unter einem neuen Namen speichern</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
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
        <source>Open &amp;Example Project</source>
        <translation>&amp;Beispielprojekt öffnen</translation>
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
        <source>File</source>
        <translation>Datei</translation>
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
        <source>Save Project As</source>
        <translation>Projekt speichern unter</translation>
    </message>
    <message>
        <source>Save Project</source>
        <translation>Projekt speichern</translation>
    </message>
    <message>
        <source>Could not save “%1”.</source>
        <translation>„%1“ konnte nicht gespeichert werden.</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>%1 gespeichert</translation>
    </message>
    <message numerus="yes">
        <source>Not formatted: the text has %n error(s).</source>
        <translation>
            <numerusform>Nicht formatiert: Der Text enthält %n Fehler.</numerusform>
            <numerusform>Nicht formatiert: Der Text enthält %n Fehler.</numerusform>
        </translation>
    </message>
    <message>
        <source>The text is already formatted.</source>
        <translation>Der Text ist bereits formatiert.</translation>
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
        <source>&lt;h3&gt;Rungsmith %1&lt;/h3&gt;&lt;p&gt;An IDE for Pluto safety PLCs: write and check programs in the Pluto text language.&lt;/p&gt;&lt;p&gt;Built with Qt %2 and QScintilla %3.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;Rungsmith %1&lt;/h3&gt;&lt;p&gt;Eine Entwicklungsumgebung für Pluto-Sicherheitssteuerungen: Programme in der Pluto-Textsprache schreiben und prüfen.&lt;/p&gt;&lt;p&gt;Erstellt mit Qt %2 und QScintilla %3.&lt;/p&gt;</translation>
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
        <source>&amp;Clear Menu</source>
        <translation>Menü &amp;leeren</translation>
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
</TS>
