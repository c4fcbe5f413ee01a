<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de" sourcelanguage="en">
<context>
    <name>resect::AddStrokeCommand</name>
    <message>
        <location filename="../widgets/scenario_commands.cpp" line="+109"/>
        <source>Add stroke</source>
        <translation>Schnittbewegung hinzufügen</translation>
    </message>
</context>
<context>
    <name>resect::AddSweepCommand</name>
    <message>
        <location line="+34"/>
        <source>Add sweep</source>
        <translation>Sweep-Fläche hinzufügen</translation>
    </message>
</context>
<context>
    <name>resect::ExportRunner</name>
    <message numerus="yes">
        <location filename="../widgets/export_runner.cpp" line="+92"/>
        <source>Exported %n file(s) to %1; the expectations passed.</source>
        <translation>
            <numerusform>%n Datei nach %1 exportiert; die Erwartungen sind erfüllt.</numerusform>
            <numerusform>%n Dateien nach %1 exportiert; die Erwartungen sind erfüllt.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+2"/>
        <source>Exported %n file(s) to %1; some expectations failed.</source>
        <translation>
            <numerusform>%n Datei nach %1 exportiert; einige Erwartungen sind nicht erfüllt.</numerusform>
            <numerusform>%n Dateien nach %1 exportiert; einige Erwartungen sind nicht erfüllt.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Export to %1 cancelled.</source>
        <translation>Export nach %1 abgebrochen.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Export failed: %1</source>
        <translation>Export fehlgeschlagen: %1</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Exporting the trainer package...</source>
        <translation>Trainer-Paket wird exportiert...</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Export for the trainer</source>
        <translation>Export für den Trainer</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>Checking the output folder...</source>
        <translation>Zielordner wird geprüft...</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Meshing %1...</source>
        <translation>%1 wird vernetzt...</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Writing the mesh and surface of %1...</source>
        <translation>Netz und Oberfläche von %1 werden geschrieben...</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Replaying the strokes on %1...</source>
        <translation>Schnittbewegungen an %1 werden nachgespielt...</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Writing the result of %1...</source>
        <translation>Ergebnis von %1 wird geschrieben...</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Writing the scenario and the report...</source>
        <translation>Szenario und Bericht werden geschrieben...</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Writing the manifest...</source>
        <translation>Manifest wird geschrieben...</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Moving the package into place...</source>
        <translation>Paket wird an seinen Platz verschoben...</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Done.</source>
        <translation>Fertig.</translation>
    </message>
</context>
<context>
    <name>resect::Language</name>
    <message>
        <location filename="../widgets/language.cpp" line="+54"/>
        <location line="+31"/>
        <source>unknown language &quot;%1&quot; (available: %2)</source>
        <translation>unbekannte Sprache „%1“ (verfügbar: %2)</translation>
    </message>
    <message>
        <location line="-21"/>
        <source>the saved language &quot;%1&quot; is unknown (available: %2); it is ignored</source>
        <translation>die gespeicherte Sprache „%1“ ist unbekannt (verfügbar: %2); sie wird ignoriert</translation>
    </message>
    <message>
        <location line="+42"/>
        <source>the translation %1 is missing or unreadable</source>
        <translation>die Übersetzung %1 fehlt oder ist nicht lesbar</translation>
    </message>
</context>
<context>
    <name>resect::MainWindow</name>
    <message>
        <location filename="../app/studio/main_window.cpp" line="+54"/>
        <location line="+66"/>
        <location line="+44"/>
        <source>Resect Studio</source>
        <translation>Resect Studio</translation>
    </message>
    <message>
        <location line="-105"/>
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Open...</source>
        <translation>Ö&amp;ffnen...</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <location line="+47"/>
        <source>%1: another file is still loading</source>
        <translation>%1: Eine andere Datei wird noch geladen</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Loading %1...</source>
        <translation>%1 wird geladen...</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Loading and meshing %1...</source>
        <translation>%1 wird geladen und vernetzt...</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>%1: internal error: %2</source>
        <translation>%1: interner Fehler: %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1: internal error</source>
        <translation>%1: interner Fehler</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>Loading %1 cancelled</source>
        <translation>Laden von %1 abgebrochen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Loading %1 failed</source>
        <translation>Laden von %1 fehlgeschlagen</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Could not open %1.</source>
        <translation>%1 konnte nicht geöffnet werden.</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>%1 - Resect Studio</source>
        <translation>%1 - Resect Studio</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Open mesh or surface</source>
        <translation>Netz oder Oberfläche öffnen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Tet meshes (*.vtu *.msh *.node *.ele);;Surfaces (*.obj *.stl *.ply *.off *.glb *.gltf);;All files (*)</source>
        <translation>Tetraedernetze (*.vtu *.msh *.node *.ele);;Oberflächen (*.obj *.stl *.ply *.off *.glb *.gltf);;Alle Dateien (*)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Cancelling...</source>
        <translation>Wird abgebrochen...</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>No mesh</source>
        <translation>Kein Netz</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1: %2 nodes, %3 tets, min radius ratio %4</source>
        <translation>%1: %2 Knoten, %3 Tetraeder, kleinstes Radienverhältnis %4</translation>
    </message>
</context>
<context>
    <name>resect::RemoveStrokeCommand</name>
    <message>
        <location filename="../widgets/scenario_commands.cpp" line="-18"/>
        <source>Remove stroke</source>
        <translation>Schnittbewegung entfernen</translation>
    </message>
</context>
<context>
    <name>resect::RemoveSweepCommand</name>
    <message>
        <location line="+35"/>
        <source>Remove sweep</source>
        <translation>Sweep-Fläche entfernen</translation>
    </message>
</context>
<context>
    <name>resect::ScenarioDocument</name>
    <message>
        <location filename="../widgets/scenario_document.cpp" line="+80"/>
        <source>untitled</source>
        <translation>unbenannt</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>unknown sample &quot;%1&quot; (known: %2)</source>
        <translation>unbekanntes Beispiel „%1“ (bekannt: %2)</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>New %1 scenario</source>
        <translation>Neues Szenario %1</translation>
    </message>
    <message>
        <location line="+32"/>
        <source>the document has no file name yet (use Save As)</source>
        <translation>das Dokument hat noch keinen Dateinamen (Speichern unter verwenden)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>no file name given</source>
        <translation>kein Dateiname angegeben</translation>
    </message>
    <message>
        <location line="+97"/>
        <source>cannot create the autosave folder &quot;%1&quot;</source>
        <translation>der Ordner für die automatische Sicherung „%1“ kann nicht angelegt werden</translation>
    </message>
    <message>
        <location line="+55"/>
        <source>there is no autosave to recover</source>
        <translation>es gibt keine automatische Sicherung zum Wiederherstellen</translation>
    </message>
</context>
<context>
    <name>resect::SetCutSettingsCommand</name>
    <message>
        <location filename="../widgets/scenario_commands.cpp" line="-79"/>
        <source>Change cut settings</source>
        <translation>Schnitteinstellungen ändern</translation>
    </message>
</context>
<context>
    <name>resect::SetEffectEnabledCommand</name>
    <message>
        <location line="+100"/>
        <source>Switch effect on</source>
        <translation>Effekt einschalten</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Switch effect off</source>
        <translation>Effekt ausschalten</translation>
    </message>
</context>
<context>
    <name>resect::SetTitleCommand</name>
    <message>
        <location line="+52"/>
        <source>Change title</source>
        <translation>Titel ändern</translation>
    </message>
</context>
<context>
    <name>resect::VtkViewport</name>
    <message>
        <location filename="../widgets/vtk_viewport.cpp" line="+100"/>
        <source>3-D view unavailable: %1.</source>
        <translation>3-D-Ansicht nicht verfügbar: %1.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Tet mesh loaded: %1 nodes, %2 tets.</source>
        <translation>Tetraedernetz geladen: %1 Knoten, %2 Tetraeder.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Surface loaded: %1 triangles.</source>
        <translation>Oberfläche geladen: %1 Dreiecke.</translation>
    </message>
</context>
</TS>
