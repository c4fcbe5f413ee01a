<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de" sourcelanguage="en">
<context>
    <name>resect::AccuracyChart</name>
    <message>
        <location filename="../widgets/accuracy_chart.cpp" line="+88"/>
        <source>Subdivision</source>
        <translation>Unterteilung</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Hybrid, standard triangulation</source>
        <translation>Hybrid, Standard-Triangulierung</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Hybrid, enhanced triangulation</source>
        <translation>Hybrid, erweiterte Triangulierung</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>Pareto front</source>
        <translation>Pareto-Front</translation>
    </message>
    <message>
        <location line="+214"/>
        <source>%1 on %2</source>
        <translation>%1 auf %2</translation>
    </message>
    <message numerus="yes">
        <location line="+1"/>
        <source>d = %1, snapping %2, %n relaxation step(s)</source>
        <translation>
            <numerusform>d = %1, Einrasten %2, %n Relaxationsschritt</numerusform>
            <numerusform>d = %1, Einrasten %2, %n Relaxationsschritte</numerusform>
        </translation>
    </message>
    <message>
        <location line="+1"/>
        <source>on</source>
        <translation>an</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>off</source>
        <translation>aus</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cut-face error: max %1, mean %2 mean edge lengths</source>
        <translation>Fehler der Schnittfacetten: max. %1, Mittel %2 mittlere Kantenlängen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Tets: %1 (%2 added); worst radius ratio %3</source>
        <translation>Tetraeder: %1 (%2 hinzugefügt); schlechtestes Radienverhältnis %3</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Stable time step: %1 s</source>
        <translation>Stabiler Zeitschritt: %1 s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cut: %1 ms; simulation: %2 ms per simulated second</source>
        <translation>Schnitt: %1 ms; Simulation: %2 ms pro simulierter Sekunde</translation>
    </message>
    <message>
        <location line="+68"/>
        <source>Cut time (ms, log scale)</source>
        <translation>Schnittzeit (ms, logarithmische Skala)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Simulation cost (ms per simulated second, log scale)</source>
        <translation>Simulationsaufwand (ms pro simulierter Sekunde, logarithmische Skala)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Cut-face error, max (mean edge lengths)</source>
        <translation>Fehler der Schnittfacetten, max. (mittlere Kantenlängen)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Run the study to see what accuracy costs.</source>
        <translation>Führen Sie die Studie aus, um zu sehen, was Genauigkeit kostet.</translation>
    </message>
    <message>
        <location line="+52"/>
        <source>Zoomed: double-click to show all</source>
        <translation>Vergrößert: Doppelklick zeigt alles</translation>
    </message>
</context>
<context>
    <name>resect::AccuracyPanel</name>
    <message>
        <location filename="../widgets/accuracy_panel.cpp" line="+35"/>
        <source>Tiny (seconds)</source>
        <translation>Winzig (Sekunden)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Quick (minutes)</source>
        <translation>Schnell (Minuten)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>How many settings the study tries and how often it repeats each cut</source>
        <translation>Wie viele Einstellungen die Studie ausprobiert und wie oft sie jeden Schnitt wiederholt</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Simulation cost</source>
        <translation>Simulationsaufwand</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Cut time</source>
        <translation>Schnittzeit</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The cost on the horizontal axis: compute time per simulated second of the cut tissue, or the time of the cut itself</source>
        <translation>Der Aufwand auf der horizontalen Achse: Rechenzeit pro simulierter Sekunde des geschnittenen Gewebes oder die Zeit des Schnitts selbst</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Run</source>
        <translation>Ausführen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Cut copies of the tissue with every method and setting of the preset</source>
        <translation>Kopien des Gewebes mit jeder Methode und Einstellung der Voreinstellung schneiden</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>Adopt</source>
        <translation>Übernehmen</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Use the selected point&apos;s method, d, snapping and relaxation as the scenario&apos;s cut settings</source>
        <translation>Methode, d, Einrasten und Relaxation des gewählten Punkts als Schnitteinstellungen des Szenarios verwenden</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Preset:</source>
        <translation>Voreinstellung:</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Cost:</source>
        <translation>Aufwand:</translation>
    </message>
    <message>
        <location line="+99"/>
        <source>Custom</source>
        <translation>Benutzerdefiniert</translation>
    </message>
    <message>
        <location line="+36"/>
        <source>Starting the study...</source>
        <translation>Studie wird gestartet...</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>Running: %1</source>
        <translation>Läuft: %1</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Study cancelled: another document was opened.</source>
        <translation>Studie abgebrochen: ein anderes Dokument wurde geöffnet.</translation>
    </message>
    <message numerus="yes">
        <location line="+11"/>
        <source>Study finished: %n row(s).</source>
        <translation>
            <numerusform>Studie abgeschlossen: %n Zeile.</numerusform>
            <numerusform>Studie abgeschlossen: %n Zeilen.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+2"/>
        <source>Study cancelled after %n row(s).</source>
        <translation>
            <numerusform>Studie nach %n Zeile abgebrochen.</numerusform>
            <numerusform>Studie nach %n Zeilen abgebrochen.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Study failed: %1</source>
        <translation>Studie fehlgeschlagen: %1</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Cancelling...</source>
        <translation>Wird abgebrochen...</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Click a point of the chart to see its settings; drag a rectangle to zoom, double-click to show all.</source>
        <translation>Klicken Sie einen Punkt des Diagramms an, um seine Einstellungen zu sehen; ziehen Sie ein Rechteck zum Vergrößern, Doppelklick zeigt alles.</translation>
    </message>
    <message numerus="yes">
        <location line="+4"/>
        <source>%1, d = %2, snapping %3, %n relaxation step(s): error max %4 mean edge lengths, %5 tets, cut %6 ms, simulation %7 ms per simulated second</source>
        <translation>
            <numerusform>%1, d = %2, Einrasten %3, %n Relaxationsschritt: Fehler max. %4 mittlere Kantenlängen, %5 Tetraeder, Schnitt %6 ms, Simulation %7 ms pro simulierter Sekunde</numerusform>
            <numerusform>%1, d = %2, Einrasten %3, %n Relaxationsschritte: Fehler max. %4 mittlere Kantenlängen, %5 Tetraeder, Schnitt %6 ms, Simulation %7 ms pro simulierter Sekunde</numerusform>
        </translation>
    </message>
    <message>
        <location line="+4"/>
        <source>on</source>
        <translation>an</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>off</source>
        <translation>aus</translation>
    </message>
    <message numerus="yes">
        <location line="+19"/>
        <source>Ready: %1 (%n tet(s)).</source>
        <translation>
            <numerusform>Bereit: %1 (%n Tetraeder).</numerusform>
            <numerusform>Bereit: %1 (%n Tetraeder).</numerusform>
        </translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Open a scenario with a tissue to run the study.</source>
        <translation>Öffnen Sie ein Szenario mit einem Gewebe, um die Studie auszuführen.</translation>
    </message>
</context>
<context>
    <name>resect::AuthoringPanel</name>
    <message>
        <location filename="../widgets/authoring_panel.cpp" line="+20"/>
        <source>Pull loop: click on the tissue where the loop should cut deepest; drag to turn its opening. The loop is pulled from behind the tissue towards you.</source>
        <translation>Schlinge ziehen: Klicken Sie auf das Gewebe, wo die Schlinge am tiefsten schneiden soll; ziehen Sie, um ihre Öffnung zu drehen. Die Schlinge wird von hinter dem Gewebe zu Ihnen hin gezogen.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Recording: drag the electrode forward across the view with the left button.</source>
        <translation>Aufzeichnung: Ziehen Sie die Elektrode mit der linken Maustaste vorwärts durch die Ansicht.</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Draw sweep</source>
        <translation>Schnittfläche zeichnen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Click the points of the start curve; hold the button to drag a point into place. Drag any point to move it.</source>
        <translation>Klicken Sie die Punkte der Startkurve an; halten Sie die Maustaste gedrückt, um einen Punkt an seinen Platz zu ziehen. Ziehen Sie einen beliebigen Punkt, um ihn zu verschieben.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>End curve</source>
        <translation>Endkurve</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Draw the end curve: click, in order, where each point of the start curve ends its path.</source>
        <translation>Endkurve zeichnen: Klicken Sie der Reihe nach dorthin, wo jeder Punkt der Startkurve seinen Weg beendet.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Record stroke</source>
        <translation>Schnittbewegung aufzeichnen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Drag the electrode across the view with the left button.</source>
        <translation>Ziehen Sie die Elektrode mit der linken Maustaste durch die Ansicht.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Pull loop</source>
        <translation>Schlinge ziehen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Click on the tissue where the loop should cut deepest (drag to turn its opening): the loop is pulled from behind the tissue towards you, as a resectoscope&apos;s loop electrode, and takes off what lies inside it.</source>
        <translation>Klicken Sie auf das Gewebe, wo die Schlinge am tiefsten schneiden soll (ziehen, um ihre Öffnung zu drehen): Die Schlinge wird wie die Schlingenelektrode eines Resektoskops von hinter dem Gewebe zu Ihnen hin gezogen und trägt ab, was in ihr liegt.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Finish</source>
        <translation>Fertigstellen</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Use the drawn sweep surface.</source>
        <translation>Die gezeichnete Schnittfläche verwenden.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Clear</source>
        <translation>Löschen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Remove the drawn curves and the recorded stroke.</source>
        <translation>Die gezeichneten Kurven und die aufgezeichnete Schnittbewegung entfernen.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Play stroke</source>
        <translation>Schnittbewegung abspielen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Replay the last recorded stroke.</source>
        <translation>Die zuletzt aufgezeichnete Schnittbewegung erneut abspielen.</translation>
    </message>
    <message>
        <location line="+51"/>
        <location line="+86"/>
        <source>Draw a sweep surface or record a stroke.</source>
        <translation>Zeichnen Sie eine Schnittfläche oder zeichnen Sie eine Schnittbewegung auf.</translation>
    </message>
    <message>
        <location line="-11"/>
        <source>Sweep surface handed on.</source>
        <translation>Schnittfläche übergeben.</translation>
    </message>
    <message>
        <location line="+32"/>
        <source>Stroke recorded: %1 poses over %2 s.</source>
        <translation>Schnittbewegung aufgezeichnet: %1 Posen über %2 s.</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>The sweep surface is valid: drag points to adjust it, or press Finish.</source>
        <translation>Die Schnittfläche ist gültig: Ziehen Sie Punkte, um sie anzupassen, oder klicken Sie auf „Fertigstellen“.</translation>
    </message>
</context>
<context>
    <name>resect::CutPanel</name>
    <message>
        <location filename="../widgets/cut_panel.cpp" line="+38"/>
        <source>%1 → %2</source>
        <translation>%1 → %2</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Method</source>
        <translation>Methode</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Hybrid</source>
        <translation>Hybrid</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Subdivision</source>
        <translation>Unterteilung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cutting method</source>
        <translation>Schnittmethode</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Enhanced (symmetric)</source>
        <translation>Erweitert (symmetrisch)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Standard</source>
        <translation>Standard</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Face triangulation</source>
        <translation>Triangulierung der Seitenflächen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Cut-node threshold d as a fraction of the mean edge length (the paper: 0.2)</source>
        <translation>Schwellenwert d für Schnittknoten als Bruchteil der mittleren Kantenlänge (im Artikel: 0,2)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Threshold d</source>
        <translation>Schwellenwert d</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Snap cut nodes onto the sweep</source>
        <translation>Schnittknoten auf der Schnittfläche einrasten</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Relaxation steps</source>
        <translation>Relaxationsschritte</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Spring weight</source>
        <translation>Federgewicht</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Particle weight</source>
        <translation>Partikelgewicht</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Relaxation damping</source>
        <translation>Relaxationsdämpfung</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Relaxation rings</source>
        <translation>Relaxationsringe</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Mesh improvement</source>
        <translation>Netzverbesserung</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Improve mesh after cut</source>
        <translation>Netz nach dem Schnitt verbessern</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>After every cut, improve the tets around it: collapse short edges and move nodes of bad tets, measured against the tissue as created</source>
        <translation>Nach jedem Schnitt die Tetraeder um ihn verbessern: kurze Kanten zusammenziehen und Knoten schlechter Tetraeder verschieben, gemessen am Gewebe im Ausgangszustand</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Tets whose radius ratio is below this factor times the worst of the tissue as created are improved (0: off; from 0 to %1)</source>
        <translation>Tetraeder, deren Radienverhältnis unter diesem Faktor mal dem schlechtesten des Gewebes im Ausgangszustand liegt, werden verbessert (0: aus; von 0 bis %1)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Quality factor</source>
        <translation>Qualitätsfaktor</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Edges shorter than this factor times the shortest edge of the tissue as created are collapsed (0: off; from 0 to %1)</source>
        <translation>Kanten, die kürzer als dieser Faktor mal die kürzeste Kante des Gewebes im Ausgangszustand sind, werden zusammengezogen (0: aus; von 0 bis %1)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Short-edge factor</source>
        <translation>Faktor für kurze Kanten</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Edges shorter than this factor times the mean edge length (the unit of d) are collapsed where quality allows, so that repeated cuts do not keep adding tets (0: off; from 0 to %1)</source>
        <translation>Kanten, die kürzer als dieser Faktor mal die mittlere Kantenlänge (die Einheit von d) sind, werden zusammengezogen, wo die Qualität es erlaubt, damit wiederholte Schnitte nicht immer mehr Tetraeder erzeugen (0: aus; von 0 bis %1)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Coarsening factor</source>
        <translation>Vergröberungsfaktor</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Preview</source>
        <translation>Vorschau</translation>
    </message>
    <message>
        <location line="+16"/>
        <location line="+260"/>
        <source>Inspect the worst tet</source>
        <translation>Schlechtesten Tetraeder prüfen</translation>
    </message>
    <message>
        <location line="-258"/>
        <source>Shows the tet that limits the time step most in the quality dock&apos;s tet inspector; click again for the next</source>
        <translation>Zeigt den Tetraeder, der den Zeitschritt am stärksten begrenzt, im Tetraeder-Inspektor des Qualitätsfensters; erneut klicken für den nächsten</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Tets</source>
        <translation>Tetraeder</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Added tets</source>
        <translation>Hinzugefügte Tetraeder</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cut edges</source>
        <translation>Geschnittene Kanten</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cut nodes</source>
        <translation>Schnittknoten</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Snapped nodes</source>
        <translation>Eingerastete Knoten</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Decomposed tets</source>
        <translation>Zerlegte Tetraeder</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Separated tets</source>
        <translation>Abgetrennte Tetraeder</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Collapsed edges</source>
        <translation>Zusammengezogene Kanten</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Smoothed nodes</source>
        <translation>Geglättete Knoten</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Removed tets</source>
        <translation>Entfernte Tetraeder</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Pieces</source>
        <translation>Teile</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Resected chips</source>
        <translation>Resezierte Späne</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Resected volume (mm³)</source>
        <translation>Reseziertes Volumen (mm³)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Resected mass (g)</source>
        <translation>Resezierte Masse (g)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Min radius ratio</source>
        <translation>Min. Radienverhältnis</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Stable time step (s)</source>
        <translation>Stabiler Zeitschritt (s)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Intersect / select / decompose (ms)</source>
        <translation>Verschneiden / Auswählen / Zerlegen (ms)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Snap / relax / update (ms)</source>
        <translation>Einrasten / Relaxieren / Aktualisieren (ms)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Surface cut (ms)</source>
        <translation>Oberflächenschnitt (ms)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Mesh improvement (ms)</source>
        <translation>Netzverbesserung (ms)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Total (ms)</source>
        <translation>Gesamt (ms)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Apply cut</source>
        <translation>Schnitt &amp;anwenden</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Discard</source>
        <translation>&amp;Verwerfen</translation>
    </message>
    <message>
        <location line="+76"/>
        <source>The last edit was undone: %1</source>
        <translation>Die letzte Änderung wurde rückgängig gemacht: %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The tissue or its cuts fail: %1</source>
        <translation>Das Gewebe oder seine Schnitte scheitern: %1</translation>
    </message>
    <message>
        <location line="+61"/>
        <source>No pending cut. Draw a sweep or record a stroke to preview a cut.</source>
        <translation>Kein ausstehender Schnitt. Zeichnen Sie eine Schnittfläche oder zeichnen Sie eine Schnittbewegung auf, um eine Vorschau des Schnitts zu sehen.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The cut fails, it cannot be applied: %1</source>
        <translation>Der Schnitt scheitert und kann nicht angewendet werden: %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Computing the preview...</source>
        <translation>Vorschau wird berechnet...</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Preview of the pending cut (not applied yet).</source>
        <translation>Vorschau des ausstehenden Schnitts (noch nicht angewendet).</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>%1 (%2 refused)</source>
        <translation>%1 (%2 abgelehnt)</translation>
    </message>
    <message>
        <location line="+15"/>
        <location line="+3"/>
        <source>%1 / %2 / %3</source>
        <translation>%1 / %2 / %3</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>This cut makes the stable time step %1 times smaller (%2 s → %3 s): an explicit simulation needs that many more steps, and the tets that cause it are tiny or flat.</source>
        <translation>Dieser Schnitt macht den stabilen Zeitschritt %1-mal kleiner (%2 s → %3 s): Eine explizite Simulation braucht entsprechend mehr Schritte, und die verursachenden Tetraeder sind winzig oder flach.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Snapping refused every cut node (%1 refused): the cut nodes stay where the sweep crossed the edges, as with subdivision, which leaves small and flat tets.</source>
        <translation>Das Einrasten hat jeden Schnittknoten abgelehnt (%1 abgelehnt): Die Schnittknoten bleiben, wo die Schnittfläche die Kanten kreuzt, wie bei der Unterteilung, was kleine und flache Tetraeder hinterlässt.</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Tets that limit the time step, worst first: %1.</source>
        <translation>Tetraeder, die den Zeitschritt begrenzen, schlechtester zuerst: %1.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Warning: %1</source>
        <translation>Warnung: %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Inspect the next (%1 of %2)</source>
        <translation>Den nächsten prüfen (%1 von %2)</translation>
    </message>
</context>
<context>
    <name>resect::CutPreview</name>
    <message>
        <location filename="../widgets/cut_preview.cpp" line="+82"/>
        <source>There is no cut to apply: draw a sweep or record a stroke first.</source>
        <translation>Es gibt keinen Schnitt zum Anwenden: Zeichnen Sie zuerst eine Schnittfläche oder zeichnen Sie eine Schnittbewegung auf.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The cut cannot be applied: %1</source>
        <translation>Der Schnitt kann nicht angewendet werden: %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The preview of the cut is not ready yet: apply it once it is shown.</source>
        <translation>Die Vorschau des Schnitts ist noch nicht fertig: Wenden Sie ihn an, sobald sie angezeigt wird.</translation>
    </message>
    <message>
        <location line="+74"/>
        <source>Internal error: %1</source>
        <translation>Interner Fehler: %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Internal error</source>
        <translation>Interner Fehler</translation>
    </message>
</context>
<context>
    <name>resect::DisplayToolBar</name>
    <message>
        <location filename="../widgets/display_toolbar.cpp" line="+29"/>
        <source>Display</source>
        <translation>Darstellung</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Display</source>
        <translation>&amp;Darstellung</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Quality</source>
        <translation>Qualität</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Colour the tets by the quality overlay (Quality dock)</source>
        <translation>Tetraeder nach der Qualitätseinfärbung färben (Qualitätsfenster)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Pieces</source>
        <translation>Teile</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Colour every piece the cuts made, resected chips included, in its own colour</source>
        <translation>Jedes Teil, das die Schnitte erzeugt haben, resezierte Späne eingeschlossen, in eigener Farbe färben</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Cut faces</source>
        <translation>Schnittflächen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Draw the faces the cuts made in their own colour (and texture on the surface)</source>
        <translation>Die von den Schnitten erzeugten Flächen in eigener Farbe zeichnen (und mit Textur auf der Oberfläche)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Last cut</source>
        <translation>Letzter Schnitt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Outline the tets the last cut produced or changed</source>
        <translation>Die Tetraeder umranden, die der letzte Schnitt erzeugt oder verändert hat</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>How the pieces a cut took off the anchored tissue are drawn</source>
        <translation>Wie die Teile gezeichnet werden, die ein Schnitt vom fixierten Gewebe abgetrennt hat</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Show resected pieces</source>
        <translation>Resezierte Teile zeigen</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Dim resected pieces</source>
        <translation>Resezierte Teile abblenden</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Hide resected pieces</source>
        <translation>Resezierte Teile ausblenden</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Shown</source>
        <translation>Gezeigt</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Dimmed</source>
        <translation>Abgeblendet</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Hidden</source>
        <translation>Ausgeblendet</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Move the pieces apart from the tissue&apos;s centre (display only: the tissue is not changed)</source>
        <translation>Die Teile vom Mittelpunkt des Gewebes auseinanderrücken (nur Darstellung: das Gewebe bleibt unverändert)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Explode pieces</source>
        <translation>Teile auseinanderziehen</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Colour:</source>
        <translation>Farbe:</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Resected:</source>
        <translation>Reseziert:</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Explode:</source>
        <translation>Auseinander:</translation>
    </message>
</context>
<context>
    <name>resect::DocumentOpener</name>
    <message>
        <location filename="../widgets/document_opener.cpp" line="+57"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
</context>
<context>
    <name>resect::EffectParameterEditor</name>
    <message>
        <location filename="../widgets/effect_parameter_editor.cpp" line="+56"/>
        <source>Springs</source>
        <translation>Federn</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Springs on the edges (distance term)</source>
        <translation>Federn auf den Kanten (Abstandsterm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Volume</source>
        <translation>Volumen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Volume preservation of every tet</source>
        <translation>Volumenerhaltung jedes Tetraeders</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Area</source>
        <translation>Fläche</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Area preservation of the boundary triangles</source>
        <translation>Flächenerhaltung der Randdreiecke</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>x </source>
        <translation>x </translation>
    </message>
    <message>
        <location line="+0"/>
        <source>y </source>
        <translation>y </translation>
    </message>
    <message>
        <location line="+0"/>
        <source>z </source>
        <translation>z </translation>
    </message>
    <message>
        <location line="+12"/>
        <source>m/s²</source>
        <translation>m/s²</translation>
    </message>
    <message>
        <location line="+2"/>
        <source> m/s²</source>
        <translation> m/s²</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The length of the acceleration; its direction is kept</source>
        <translation>Der Betrag der Beschleunigung; ihre Richtung bleibt erhalten</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Magnitude</source>
        <translation>Betrag</translation>
    </message>
    <message>
        <location line="+10"/>
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Radius of the loop&apos;s wire: surface nodes closer to the tool&apos;s curve are pushed out</source>
        <translation>Radius des Schlingendrahts: Oberflächenknoten, die der Werkzeugkurve näher sind, werden hinausgedrückt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Wire radius</source>
        <translation>Drahtradius</translation>
    </message>
    <message>
        <location line="+9"/>
        <source> 1/s</source>
        <translation> 1/s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Mass-proportional damping f = -c m v: kinetic energy decays with the time constant 1/(2c)</source>
        <translation>Massenproportionale Dämpfung f = -c m v: Die kinetische Energie klingt mit der Zeitkonstante 1/(2c) ab</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Coefficient</source>
        <translation>Koeffizient</translation>
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
    <name>resect::FixedRegionEditor</name>
    <message>
        <location filename="../widgets/fixed_region_editor.cpp" line="+35"/>
        <source>Add base box</source>
        <translation>Basisquader hinzufügen</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>A box around the bottom %1 % of the tissue&apos;s height</source>
        <translation>Ein Quader um die unteren %1 % der Gewebehöhe</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Place in view</source>
        <translation>In der Ansicht platzieren</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Draws the boxes in the view: drag a face&apos;s handle to move that face (red x, green y, blue z); drag elsewhere to turn the view</source>
        <translation>Zeichnet die Quader in der Ansicht: Ziehen Sie den Griff einer Seite, um diese Seite zu verschieben (rot x, grün y, blau z); anderswo ziehen dreht die Ansicht</translation>
    </message>
    <message>
        <location line="+49"/>
        <source>Box %1 (mm)</source>
        <translation>Quader %1 (mm)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>min</source>
        <translation>min</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>max</source>
        <translation>max</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>Remove</source>
        <translation>Entfernen</translation>
    </message>
    <message>
        <location line="+49"/>
        <source>A box can be added once the tissue is loaded.</source>
        <translation>Ein Quader kann hinzugefügt werden, sobald das Gewebe geladen ist.</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>1 node of the uncut tissue</source>
        <translation>1 Knoten des ungeschnittenen Gewebes</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 nodes of the uncut tissue</source>
        <translation>%1 Knoten des ungeschnittenen Gewebes</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Anchored nodes: not derived yet</source>
        <translation>Fixierte Knoten: noch nicht ermittelt</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>No fixed region: nothing is anchored.</source>
        <translation>Kein fixierter Bereich: nichts ist verankert.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>1 node anchored</source>
        <translation>1 Knoten verankert</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 nodes anchored</source>
        <translation>%1 Knoten verankert</translation>
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
        <location filename="../app/studio/main_window.cpp" line="+349"/>
        <location line="+11"/>
        <location line="+213"/>
        <location line="+59"/>
        <source>Resect Studio</source>
        <translation>Resect Studio</translation>
    </message>
    <message>
        <location line="-418"/>
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <location line="-28"/>
        <source>Simulation paused while a cut is previewed: apply or discard the cut, then play.</source>
        <translation>Simulation pausiert, solange ein Schnitt in der Vorschau ist: Wenden Sie den Schnitt an oder verwerfen Sie ihn, dann abspielen.</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Exported the mesh to %1</source>
        <translation>Netz nach %1 exportiert</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+322"/>
        <source>The mesh was not exported.</source>
        <translation>Das Netz wurde nicht exportiert.</translation>
    </message>
    <message>
        <location line="-308"/>
        <source>&amp;New from sample</source>
        <translation>&amp;Neu aus Beispiel</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Polyp</source>
        <translation>&amp;Polyp</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Myoma</source>
        <translation>&amp;Myom</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&amp;Open...</source>
        <translation>Ö&amp;ffnen...</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Import anatomy...</source>
        <translation>Anatomie &amp;importieren...</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Open &amp;recent</source>
        <translation>&amp;Zuletzt geöffnet</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Save</source>
        <translation>&amp;Speichern</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Save &amp;as...</source>
        <translation>Speichern &amp;unter...</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Export for the trainer...</source>
        <translation>&amp;Export für den Trainer...</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Export &amp;mesh as...</source>
        <translation>&amp;Netz exportieren als...</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>&amp;Edit</source>
        <translation>&amp;Bearbeiten</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Undo</source>
        <translation>&amp;Rückgängig</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Redo</source>
        <translation>&amp;Wiederholen</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>&amp;Cut</source>
        <translation>&amp;Schnitt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Apply pending cut</source>
        <translation>Ausstehenden Schnitt &amp;anwenden</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>&amp;Discard pending cut</source>
        <translation>Ausstehenden Schnitt &amp;verwerfen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Simulation</source>
        <translation>Si&amp;mulation</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Play / pause</source>
        <translation>&amp;Abspielen / Pause</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>&amp;Step</source>
        <translation>&amp;Schritt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Reset</source>
        <translation>&amp;Zurücksetzen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;View</source>
        <translation>&amp;Ansicht</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Reset camera</source>
        <translation>&amp;Kamera zurücksetzen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Show &amp;tet mesh</source>
        <translation>&amp;Tetraedernetz anzeigen</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Show high-resolution &amp;surface</source>
        <translation>Hochaufgelöste &amp;Oberfläche anzeigen</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Display &amp;toolbar</source>
        <translation>Darstellungs-&amp;Werkzeugleiste</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&amp;Language</source>
        <translation>S&amp;prache</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>System default</source>
        <translation>Systemstandard</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Cut</source>
        <translation>Schnitt</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Simulation</source>
        <translation>Simulation</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Accuracy vs time</source>
        <translation>Genauigkeit vs. Zeit</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Quality</source>
        <translation>Qualität</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Authoring</source>
        <translation>Erstellung</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>%1 has unsaved changes. Save them?</source>
        <translation>%1 hat ungespeicherte Änderungen. Speichern?</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>Could not create the scenario.</source>
        <translation>Das Szenario konnte nicht erstellt werden.</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>Mesh read: %1</source>
        <translation>Netz gelesen: %1</translation>
    </message>
    <message>
        <location line="+14"/>
        <location line="+10"/>
        <source>The scenario was not saved.</source>
        <translation>Das Szenario wurde nicht gespeichert.</translation>
    </message>
    <message>
        <location line="-7"/>
        <location line="+10"/>
        <source>Saved %1</source>
        <translation>%1 gespeichert</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Save scenario</source>
        <translation>Szenario speichern</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+8"/>
        <source>Scenarios (*.json)</source>
        <translation>Szenarien (*.json)</translation>
    </message>
    <message>
        <location line="-1"/>
        <source>Open scenario or anatomy</source>
        <translation>Szenario oder Anatomie öffnen</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Import anatomy</source>
        <translation>Anatomie importieren</translation>
    </message>
    <message>
        <location line="+13"/>
        <location line="+7"/>
        <location line="+73"/>
        <source>The scenario was not exported.</source>
        <translation>Das Szenario wurde nicht exportiert.</translation>
    </message>
    <message>
        <location line="-80"/>
        <source>An export is already running.</source>
        <translation>Ein Export läuft bereits.</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>The export could not be started.</source>
        <translation>Der Export konnte nicht gestartet werden.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Exporting to %1...</source>
        <translation>Export nach %1...</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Export for the trainer: choose or create an empty folder</source>
        <translation>Export für den Trainer: leeren Ordner wählen oder anlegen</translation>
    </message>
    <message>
        <location line="+115"/>
        <source>1 piece</source>
        <translation>1 Teil</translation>
    </message>
    <message numerus="yes">
        <location line="+0"/>
        <source>%n pieces</source>
        <translation>
            <numerusform>%n Teil</numerusform>
            <numerusform>%n Teile</numerusform>
        </translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1: %2 nodes, %3 tets, %4, min radius ratio %5, stable dt %6 s</source>
        <translation>%1: %2 Knoten, %3 Tetraeder, %4, min. Radienverhältnis %5, stabiler Zeitschritt %6 s</translation>
    </message>
    <message numerus="yes">
        <location line="-71"/>
        <source>Exported %n file(s) to %1</source>
        <translation>
            <numerusform>%n Datei nach %1 exportiert</numerusform>
            <numerusform>%n Dateien nach %1 exportiert</numerusform>
        </translation>
    </message>
    <message>
        <location line="-84"/>
        <source>Surfaces (*.obj *.stl *.ply *.off *.glb *.gltf *.dae *.3ds *.fbx);;All files (*)</source>
        <translation>Oberflächen (*.obj *.stl *.ply *.off *.glb *.gltf *.dae *.3ds *.fbx);;Alle Dateien (*)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Surfaces (*.obj *.stl *.ply *.off *.glb *.gltf *.dae *.3ds *.fbx)</source>
        <translation>Oberflächen (*.obj *.stl *.ply *.off *.glb *.gltf *.dae *.3ds *.fbx)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>All files (*)</source>
        <translation>Alle Dateien (*)</translation>
    </message>
    <message>
        <location line="+38"/>
        <source>Export mesh as</source>
        <translation>Netz exportieren als</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>There is no tet mesh on show.</source>
        <translation>Es wird kein Tetraedernetz angezeigt.</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>A mesh export is already running.</source>
        <translation>Ein Netzexport läuft bereits.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Exporting the mesh to %1...</source>
        <translation>Netz wird nach %1 exportiert...</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Export finished</source>
        <translation>Export abgeschlossen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The trainer package is ready: the manifest lists every file with its SHA-256.</source>
        <translation>Das Trainer-Paket ist fertig: Das Manifest führt jede Datei mit ihrer SHA-256-Prüfsumme auf.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Open folder</source>
        <translation>Ordner öffnen</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Resect Studio did not close properly. Recover the unsaved changes to %1?</source>
        <translation>Resect Studio wurde nicht ordnungsgemäß beendet. Die ungespeicherten Änderungen an %1 wiederherstellen?</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>an untitled scenario</source>
        <translation>ein unbenanntes Szenario</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The autosave could not be recovered.</source>
        <translation>Die automatische Sicherung konnte nicht wiederhergestellt werden.</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>%1[*] - Resect Studio</source>
        <translation>%1[*] - Resect Studio</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Clear list</source>
        <translation>Liste leeren</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Loading...</source>
        <translation>Wird geladen...</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>No tissue</source>
        <translation>Kein Gewebe</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Loading and meshing the tissue...</source>
        <translation>Gewebe wird geladen und vernetzt...</translation>
    </message>
    <message>
        <location line="+10"/>
        <location line="+6"/>
        <source>Cancelling...</source>
        <translation>Wird abgebrochen...</translation>
    </message>
    <message>
        <location line="+44"/>
        <source>The language changes when Resect Studio is started again.</source>
        <translation>Die Sprache ändert sich beim nächsten Start von Resect Studio.</translation>
    </message>
    <message>
        <location line="-60"/>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <location line="-505"/>
        <source>The tissue could not be loaded.</source>
        <translation>Das Gewebe konnte nicht geladen werden.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The tissue or its cuts fail: %1</source>
        <translation>Das Gewebe oder seine Schnitte scheitern: %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The last edit was undone: %1</source>
        <translation>Die letzte Änderung wurde rückgängig gemacht: %1</translation>
    </message>
    <message>
        <location line="+273"/>
        <source>Could not open %1.</source>
        <translation>%1 konnte nicht geöffnet werden.</translation>
    </message>
</context>
<context>
    <name>resect::MeshFiles</name>
    <message>
        <location filename="../widgets/mesh_files.cpp" line="+33"/>
        <source>Tet meshes (%1)</source>
        <translation>Tetraedernetze (%1)</translation>
    </message>
</context>
<context>
    <name>resect::QualityCurve</name>
    <message>
        <location filename="../widgets/quality_curve.cpp" line="+120"/>
        <source>The tissue as created: worst radius ratio %1</source>
        <translation>Das Gewebe im Ausgangszustand: schlechtestes Radienverhältnis %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>After cut %1: worst radius ratio %2 (%3 × the input&apos;s)</source>
        <translation>Nach Schnitt %1: schlechtestes Radienverhältnis %2 (%3 × das der Eingabe)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Pending: not applied yet</source>
        <translation>Ausstehend: noch nicht angewendet</translation>
    </message>
    <message>
        <location line="+48"/>
        <source>Cut</source>
        <translation>Schnitt</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Worst radius ratio / input&apos;s</source>
        <translation>Schlechtestes Radienverhältnis / das der Eingabe</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>No tissue.</source>
        <translation>Kein Gewebe.</translation>
    </message>
    <message>
        <location line="+32"/>
        <source>No cuts yet.</source>
        <translation>Noch keine Schnitte.</translation>
    </message>
</context>
<context>
    <name>resect::QualityHistogram</name>
    <message>
        <location filename="../widgets/quality_histogram.cpp" line="+173"/>
        <source>before</source>
        <translation>vorher</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>after</source>
        <translation>nachher</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>log scale</source>
        <translation>logarithmische Skala</translation>
    </message>
</context>
<context>
    <name>resect::QualityMeasure</name>
    <message>
        <location filename="../widgets/quality_colors.cpp" line="+31"/>
        <source>None</source>
        <translation>Keine</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Radius ratio</source>
        <translation>Radienverhältnis</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Min. dihedral (°)</source>
        <translation>Min. Diederwinkel (°)</translation>
    </message>
</context>
<context>
    <name>resect::QualityPanel</name>
    <message>
        <location filename="../widgets/quality_panel.cpp" line="+45"/>
        <source>Display</source>
        <translation>Darstellung</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Surface</source>
        <translation>Oberfläche</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Wireframe</source>
        <translation>Drahtgitter</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Shrunk tets</source>
        <translation>Geschrumpfte Tetraeder</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Mode</source>
        <translation>Modus</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Colour by</source>
        <translation>Einfärben nach</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Auto</source>
        <translation>Auto</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Set the colour range to the range of the data</source>
        <translation>Den Farbbereich auf den Wertebereich der Daten setzen</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Range</source>
        <translation>Bereich</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Only tets worse than</source>
        <translation>Nur Tetraeder schlechter als</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Filter</source>
        <translation>Filter</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Clip</source>
        <translation>Abschneiden</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>x</source>
        <translation>x</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>y</source>
        <translation>y</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>z</source>
        <translation>z</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>view direction</source>
        <translation>Blickrichtung</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Clipping</source>
        <translation>Clipping</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Inspect tets by clicking</source>
        <translation>Tetraeder per Klick untersuchen</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Logarithmic counts</source>
        <translation>Logarithmische Anzahlen</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Histogram</source>
        <translation>Histogramm</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Summary</source>
        <translation>Übersicht</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The worst radius ratio of the tissue after each cut, relative to the tissue as created (a pending cut: hollow)</source>
        <translation>Das schlechteste Radienverhältnis des Gewebes nach jedem Schnitt, relativ zum Gewebe im Ausgangszustand (ein ausstehender Schnitt: hohl)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Per cut</source>
        <translation>Je Schnitt</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Tet</source>
        <translation>Tetraeder</translation>
    </message>
</context>
<context>
    <name>resect::QualitySummaryTable</name>
    <message>
        <location filename="../widgets/quality_summary_table.cpp" line="+26"/>
        <source>before</source>
        <translation>vorher</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>after</source>
        <translation>nachher</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Nodes</source>
        <translation>Knoten</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Edges</source>
        <translation>Kanten</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Tets</source>
        <translation>Tetraeder</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Min. radius ratio</source>
        <translation>Min. Radienverhältnis</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>tet_minAR (radius ratio / 3)</source>
        <translation>tet_minAR (Radienverhältnis / 3)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Volume ratio Vmax/Vmin</source>
        <translation>Volumenverhältnis Vmax/Vmin</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Edge ratio lmax/lmin</source>
        <translation>Kantenverhältnis lmax/lmin</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Min. dihedral (°)</source>
        <translation>Min. Diederwinkel (°)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Max. dihedral (°)</source>
        <translation>Max. Diederwinkel (°)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Stable dt (s)</source>
        <translation>Stabiles dt (s)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Overlap (mm)</source>
        <translation>Überlappung (mm)</translation>
    </message>
</context>
<context>
    <name>resect::ScenarioCommand</name>
    <message>
        <location filename="../widgets/scenario_commands.cpp" line="+83"/>
        <source>Change cut settings</source>
        <translation>Schnitteinstellungen ändern</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>Add stroke</source>
        <translation>Schnittbewegung hinzufügen</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Remove stroke</source>
        <translation>Schnittbewegung entfernen</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Add sweep</source>
        <translation>Schnittfläche hinzufügen</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Remove sweep</source>
        <translation>Schnittfläche entfernen</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>Switch effect on</source>
        <translation>Effekt einschalten</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Switch effect off</source>
        <translation>Effekt ausschalten</translation>
    </message>
    <message>
        <location line="+50"/>
        <source>Change effect parameters</source>
        <translation>Effektparameter ändern</translation>
    </message>
    <message>
        <location line="+35"/>
        <source>Change fixed regions</source>
        <translation>Fixierte Bereiche ändern</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>Change title</source>
        <translation>Titel ändern</translation>
    </message>
</context>
<context>
    <name>resect::ScenarioDocument</name>
    <message>
        <location filename="../widgets/scenario_document.cpp" line="+81"/>
        <source>untitled</source>
        <translation>unbenannt</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>unknown sample &quot;%1&quot; (known: %2)</source>
        <translation>unbekanntes Beispiel „%1“ (bekannt: %2)</translation>
    </message>
    <message>
        <location line="+47"/>
        <source>New %1 scenario</source>
        <translation>Neues Szenario %1</translation>
    </message>
    <message>
        <location line="-27"/>
        <source>%1: no such file</source>
        <translation>%1: Datei nicht vorhanden</translation>
    </message>
    <message>
        <location line="+53"/>
        <source>the document has no file name yet (use Save As)</source>
        <translation>das Dokument hat noch keinen Dateinamen (Speichern unter verwenden)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>no file name given</source>
        <translation>kein Dateiname angegeben</translation>
    </message>
    <message>
        <location line="+103"/>
        <source>cannot create the autosave folder &quot;%1&quot;</source>
        <translation>der Ordner für die automatische Sicherung „%1“ kann nicht angelegt werden</translation>
    </message>
    <message>
        <location line="+55"/>
        <source>there is no autosave to recover</source>
        <translation>es gibt keine automatische Sicherung zum Wiederherstellen</translation>
    </message>
    <message>
        <location line="+248"/>
        <source>Remove the last fixed region</source>
        <translation>Den letzten fixierten Bereich entfernen</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Fix a region</source>
        <translation>Einen Bereich fixieren</translation>
    </message>
</context>
<context>
    <name>resect::SimulationController</name>
    <message>
        <location filename="../widgets/simulation_controller.cpp" line="+166"/>
        <source>The simulation has no usable time step.</source>
        <translation>Die Simulation hat keinen verwendbaren Zeitschritt.</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>The simulation diverged at t = %1 s: %2</source>
        <translation>Die Simulation ist bei t = %1 s divergiert: %2</translation>
    </message>
</context>
<context>
    <name>resect::SimulationPanel</name>
    <message>
        <location filename="../widgets/simulation_panel.cpp" line="+27"/>
        <source>Deformation (mass-spring)</source>
        <translation>Verformung (Masse-Feder)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Gravity</source>
        <translation>Schwerkraft</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Fixed regions</source>
        <translation>Fixierte Bereiche</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Tool contact</source>
        <translation>Instrumentenkontakt</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Damping</source>
        <translation>Dämpfung</translation>
    </message>
    <message>
        <location line="+15"/>
        <location line="+157"/>
        <source>Play</source>
        <translation>Abspielen</translation>
    </message>
    <message>
        <location line="-155"/>
        <source>Step</source>
        <translation>Schritt</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Reset</source>
        <translation>Zurücksetzen</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Effects in the scenario</source>
        <translation>Effekte im Szenario</translation>
    </message>
    <message>
        <location line="+36"/>
        <source>Cost</source>
        <translation>Aufwand</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Simulated time</source>
        <translation>Simulierte Zeit</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Time step</source>
        <translation>Zeitschritt</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Per step</source>
        <translation>Pro Schritt</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Real time</source>
        <translation>Echtzeit</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>The last edit was undone: %1</source>
        <translation>Die letzte Bearbeitung wurde rückgängig gemacht: %1</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>Fixed regions: the tissue is not loaded yet, so its base cannot be anchored. Try again once it is shown.</source>
        <translation>Fixierte Bereiche: Das Gewebe ist noch nicht geladen, daher kann seine Basis nicht verankert werden. Versuchen Sie es erneut, sobald es angezeigt wird.</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>Pause</source>
        <translation>Pause</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>No tissue to simulate.</source>
        <translation>Kein Gewebe zum Simulieren.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Running.</source>
        <translation>Läuft.</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Paused.</source>
        <translation>Pausiert.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 s (%2 steps)</source>
        <translation>%1 s (%2 Schritte)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 s (stable: %2 s)</source>
        <translation>%1 s (stabil: %2 s)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1: %2 ms</source>
        <translation>%1: %2 ms</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>integrator: %1 ms</source>
        <translation>Integrator: %1 ms</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 ms per simulated second</source>
        <translation>%1 ms pro simulierter Sekunde</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>implicit, 1 iteration a step</source>
        <translation>implizit, 1 Iteration pro Schritt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>implicit, %1 iterations a step</source>
        <translation>implizit, %1 Iterationen pro Schritt</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1x real time (%2)</source>
        <translation>%1-fache Echtzeit (%2)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not measured yet (%1)</source>
        <translation>noch nicht gemessen (%1)</translation>
    </message>
</context>
<context>
    <name>resect::StrokeRecorder</name>
    <message>
        <location filename="../widgets/stroke_recorder.cpp" line="+333"/>
        <source>Move forward along the pull to continue the stroke: no pose is taken behind its end (the stroke would cut through itself).</source>
        <translation>Bewegen Sie die Maus in Zugrichtung vorwärts, um die Schnittbewegung fortzusetzen: Hinter ihrem Ende wird keine Pose aufgenommen (die Schnittbewegung würde sich selbst durchschneiden).</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>There is no tissue to pull the loop through.</source>
        <translation>Es gibt kein Gewebe, durch das die Schlinge gezogen werden kann.</translation>
    </message>
    <message>
        <location line="+81"/>
        <source>The loop cannot be pulled here: it needs a tool with a loop curve and a tissue behind the cursor.</source>
        <translation>Die Schlinge kann hier nicht gezogen werden: Sie braucht ein Werkzeug mit einer Schlingenkurve und Gewebe hinter dem Mauszeiger.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The stroke is too short to cut: hold the left button and drag the electrode forward across the view.</source>
        <translation>Die Schnittbewegung ist zu kurz zum Schneiden: Halten Sie die linke Maustaste gedrückt und ziehen Sie die Elektrode vorwärts durch die Ansicht.</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>The recorded stroke does not make a usable cut: %1</source>
        <translation>Die aufgezeichnete Schnittbewegung ergibt keinen verwendbaren Schnitt: %1</translation>
    </message>
</context>
<context>
    <name>resect::SweepEditTool</name>
    <message>
        <location filename="../widgets/sweep_edit_tool.cpp" line="+100"/>
        <source>Alt+drag turns the view, Shift+drag pans, the wheel zooms.</source>
        <translation>Alt+Ziehen dreht die Ansicht, Umschalt+Ziehen verschiebt, das Mausrad zoomt.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Click on the tissue to place the first point of the start curve. %1</source>
        <translation>Klicken Sie auf das Gewebe, um den ersten Punkt der Startkurve zu setzen. %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Start curve: click to place point 2; drag a point to move it. %1</source>
        <translation>Startkurve: Klicken Sie, um Punkt 2 zu setzen; ziehen Sie einen Punkt, um ihn zu verschieben. %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Start curve: %1 points. Click to add point %2, or press End curve to draw where the tool ends. %3</source>
        <translation>Startkurve: %1 Punkte. Klicken Sie, um Punkt %2 hinzuzufügen, oder drücken Sie „Endkurve“, um zu zeichnen, wo das Werkzeug endet. %3</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>End curve: click where point %1 of %2 ends its path. %3</source>
        <translation>Endkurve: Klicken Sie dorthin, wo Punkt %1 von %2 seinen Weg beendet. %3</translation>
    </message>
    <message>
        <location line="+84"/>
        <source>The start curve needs at least two points; it has %1.</source>
        <translation>Die Startkurve braucht mindestens zwei Punkte; sie hat %1.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The end curve needs at least two points; it has %1.</source>
        <translation>Die Endkurve braucht mindestens zwei Punkte; sie hat %1.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The start curve has %1 points and the end curve %2; both need the same number of points.</source>
        <translation>Die Startkurve hat %1 Punkte und die Endkurve %2; beide brauchen gleich viele Punkte.</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Points %1 and %2 of the start curve coincide.</source>
        <translation>Die Punkte %1 und %2 der Startkurve fallen zusammen.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Points %1 and %2 of the end curve coincide.</source>
        <translation>Die Punkte %1 und %2 der Endkurve fallen zusammen.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>These curves do not make a usable sweep surface: %1</source>
        <translation>Diese Kurven ergeben keine verwendbare Schnittfläche: %1</translation>
    </message>
</context>
<context>
    <name>resect::TetInspector</name>
    <message>
        <location filename="../widgets/tet_inspector.cpp" line="+25"/>
        <source>Tet</source>
        <translation>Tetraeder</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Node %1</source>
        <translation>Knoten %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Reference volume</source>
        <translation>Referenzvolumen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Current volume</source>
        <translation>Aktuelles Volumen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Radius ratio</source>
        <translation>Radienverhältnis</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Min. dihedral (°)</source>
        <translation>Min. Diederwinkel (°)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Max. dihedral (°)</source>
        <translation>Max. Diederwinkel (°)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Min. edge</source>
        <translation>Min. Kante</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Max. edge</source>
        <translation>Max. Kante</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Scheme</source>
        <translation>Schema</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>original</source>
        <translation>ursprünglich</translation>
    </message>
</context>
<context>
    <name>resect::TissueSession</name>
    <message>
        <location filename="../widgets/tissue_session.cpp" line="+118"/>
        <source>There is no tissue to save.</source>
        <translation>Es gibt kein Gewebe zum Speichern.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The tissue is still being derived from the last edit: save once it is shown.</source>
        <translation>Das Gewebe wird noch aus der letzten Änderung abgeleitet: Speichern Sie, sobald es angezeigt wird.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The document&apos;s tissue or cuts fail: %1</source>
        <translation>Gewebe oder Schnitte des Dokuments scheitern: %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The tissue has not been derived yet.</source>
        <translation>Das Gewebe wurde noch nicht abgeleitet.</translation>
    </message>
    <message>
        <location line="+66"/>
        <location line="+358"/>
        <source>Opening was cancelled.</source>
        <translation>Das Öffnen wurde abgebrochen.</translation>
    </message>
    <message>
        <location line="-265"/>
        <source>Internal error: %1</source>
        <translation>Interner Fehler: %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Internal error</source>
        <translation>Interner Fehler</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>the scenario has no tissue</source>
        <translation>das Szenario hat kein Gewebe</translation>
    </message>
    <message>
        <location line="+93"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location line="+120"/>
        <source>Checking the surface</source>
        <translation>Oberfläche wird geprüft</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Meshing (Delaunay refinement)</source>
        <translation>Vernetzung (Delaunay-Verfeinerung)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Removing slivers (perturbation)</source>
        <translation>Slivers werden entfernt (Perturbation)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Removing slivers (exudation)</source>
        <translation>Slivers werden entfernt (Exsudation)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Matching the volume</source>
        <translation>Volumen wird angeglichen</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Checking element quality</source>
        <translation>Elementqualität wird geprüft</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 — attempt %2 of %3</source>
        <translation>%1 — Versuch %2 von %3</translation>
    </message>
</context>
<context>
    <name>resect::VtkViewport</name>
    <message>
        <location filename="../widgets/vtk_viewport.cpp" line="+114"/>
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
