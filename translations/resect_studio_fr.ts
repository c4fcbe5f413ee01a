<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="fr" sourcelanguage="en">
<context>
    <name>resect::AddStrokeCommand</name>
    <message>
        <location filename="../widgets/scenario_commands.cpp" line="+109"/>
        <source>Add stroke</source>
        <translation>Ajouter un geste de coupe</translation>
    </message>
</context>
<context>
    <name>resect::AddSweepCommand</name>
    <message>
        <location line="+34"/>
        <source>Add sweep</source>
        <translation>Ajouter une surface de balayage</translation>
    </message>
</context>
<context>
    <name>resect::ExportRunner</name>
    <message numerus="yes">
        <location filename="../widgets/export_runner.cpp" line="+92"/>
        <source>Exported %n file(s) to %1; the expectations passed.</source>
        <translation>
            <numerusform>%n fichier exporté vers %1 ; les attentes sont satisfaites.</numerusform>
            <numerusform>%n fichiers exportés vers %1 ; les attentes sont satisfaites.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+2"/>
        <source>Exported %n file(s) to %1; some expectations failed.</source>
        <translation>
            <numerusform>%n fichier exporté vers %1 ; certaines attentes ne sont pas satisfaites.</numerusform>
            <numerusform>%n fichiers exportés vers %1 ; certaines attentes ne sont pas satisfaites.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Export to %1 cancelled.</source>
        <translation>Exportation vers %1 annulée.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Export failed: %1</source>
        <translation>Échec de l&apos;exportation : %1</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Exporting the trainer package...</source>
        <translation>Exportation du paquet pour le simulateur d&apos;entraînement...</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Cancel</source>
        <translation>Annuler</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Export for the trainer</source>
        <translation>Exportation pour le simulateur d&apos;entraînement</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>Checking the output folder...</source>
        <translation>Vérification du dossier de destination...</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Meshing %1...</source>
        <translation>Maillage de %1...</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Writing the mesh and surface of %1...</source>
        <translation>Écriture du maillage et de la surface de %1...</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Replaying the strokes on %1...</source>
        <translation>Rejeu des gestes de coupe sur %1...</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Writing the result of %1...</source>
        <translation>Écriture du résultat de %1...</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Writing the scenario and the report...</source>
        <translation>Écriture du scénario et du rapport...</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Writing the manifest...</source>
        <translation>Écriture du manifeste...</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Moving the package into place...</source>
        <translation>Mise en place du paquet...</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Done.</source>
        <translation>Terminé.</translation>
    </message>
</context>
<context>
    <name>resect::Language</name>
    <message>
        <location filename="../widgets/language.cpp" line="+54"/>
        <location line="+31"/>
        <source>unknown language &quot;%1&quot; (available: %2)</source>
        <translation>langue « %1 » inconnue (disponibles : %2)</translation>
    </message>
    <message>
        <location line="-21"/>
        <source>the saved language &quot;%1&quot; is unknown (available: %2); it is ignored</source>
        <translation>la langue enregistrée « %1 » est inconnue (disponibles : %2) ; elle est ignorée</translation>
    </message>
    <message>
        <location line="+42"/>
        <source>the translation %1 is missing or unreadable</source>
        <translation>la traduction %1 est absente ou illisible</translation>
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
        <translation>&amp;Fichier</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Open...</source>
        <translation>&amp;Ouvrir...</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&amp;Quit</source>
        <translation>&amp;Quitter</translation>
    </message>
    <message>
        <location line="+47"/>
        <source>%1: another file is still loading</source>
        <translation>%1 : un autre fichier est encore en cours de chargement</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Loading %1...</source>
        <translation>Chargement de %1...</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Loading and meshing %1...</source>
        <translation>Chargement et maillage de %1...</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Cancel</source>
        <translation>Annuler</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>%1: internal error: %2</source>
        <translation>%1 : erreur interne : %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1: internal error</source>
        <translation>%1 : erreur interne</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>Loading %1 cancelled</source>
        <translation>Chargement de %1 annulé</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Loading %1 failed</source>
        <translation>Échec du chargement de %1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Could not open %1.</source>
        <translation>Impossible d&apos;ouvrir %1.</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>%1 - Resect Studio</source>
        <translation>%1 - Resect Studio</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Open mesh or surface</source>
        <translation>Ouvrir un maillage ou une surface</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Tet meshes (*.vtu *.msh *.node *.ele);;Surfaces (*.obj *.stl *.ply *.off *.glb *.gltf);;All files (*)</source>
        <translation>Maillages tétraédriques (*.vtu *.msh *.node *.ele);;Surfaces (*.obj *.stl *.ply *.off *.glb *.gltf);;Tous les fichiers (*)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Cancelling...</source>
        <translation>Annulation...</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>No mesh</source>
        <translation>Aucun maillage</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1: %2 nodes, %3 tets, min radius ratio %4</source>
        <translation>%1 : %2 nœuds, %3 tétraèdres, rapport des rayons minimal %4</translation>
    </message>
</context>
<context>
    <name>resect::RemoveStrokeCommand</name>
    <message>
        <location filename="../widgets/scenario_commands.cpp" line="-18"/>
        <source>Remove stroke</source>
        <translation>Supprimer le geste de coupe</translation>
    </message>
</context>
<context>
    <name>resect::RemoveSweepCommand</name>
    <message>
        <location line="+35"/>
        <source>Remove sweep</source>
        <translation>Supprimer la surface de balayage</translation>
    </message>
</context>
<context>
    <name>resect::ScenarioDocument</name>
    <message>
        <location filename="../widgets/scenario_document.cpp" line="+80"/>
        <source>untitled</source>
        <translation>sans titre</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>unknown sample &quot;%1&quot; (known: %2)</source>
        <translation>exemple « %1 » inconnu (connus : %2)</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>New %1 scenario</source>
        <translation>Nouveau scénario %1</translation>
    </message>
    <message>
        <location line="+32"/>
        <source>the document has no file name yet (use Save As)</source>
        <translation>le document n&apos;a pas encore de nom de fichier (utilisez Enregistrer sous)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>no file name given</source>
        <translation>aucun nom de fichier indiqué</translation>
    </message>
    <message>
        <location line="+97"/>
        <source>cannot create the autosave folder &quot;%1&quot;</source>
        <translation>impossible de créer le dossier de sauvegarde automatique « %1 »</translation>
    </message>
    <message>
        <location line="+55"/>
        <source>there is no autosave to recover</source>
        <translation>aucune sauvegarde automatique à récupérer</translation>
    </message>
</context>
<context>
    <name>resect::SetCutSettingsCommand</name>
    <message>
        <location filename="../widgets/scenario_commands.cpp" line="-79"/>
        <source>Change cut settings</source>
        <translation>Modifier les paramètres de coupe</translation>
    </message>
</context>
<context>
    <name>resect::SetEffectEnabledCommand</name>
    <message>
        <location line="+100"/>
        <source>Switch effect on</source>
        <translation>Activer l&apos;effet</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Switch effect off</source>
        <translation>Désactiver l&apos;effet</translation>
    </message>
</context>
<context>
    <name>resect::SetTitleCommand</name>
    <message>
        <location line="+52"/>
        <source>Change title</source>
        <translation>Modifier le titre</translation>
    </message>
</context>
<context>
    <name>resect::VtkViewport</name>
    <message>
        <location filename="../widgets/vtk_viewport.cpp" line="+100"/>
        <source>3-D view unavailable: %1.</source>
        <translation>Vue 3D indisponible : %1.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Tet mesh loaded: %1 nodes, %2 tets.</source>
        <translation>Maillage tétraédrique chargé : %1 nœuds, %2 tétraèdres.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Surface loaded: %1 triangles.</source>
        <translation>Surface chargée : %1 triangles.</translation>
    </message>
</context>
</TS>
