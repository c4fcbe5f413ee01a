<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="fr" sourcelanguage="en">
<context>
    <name>resect::AccuracyChart</name>
    <message>
        <location filename="../widgets/accuracy_chart.cpp" line="+88"/>
        <source>Subdivision</source>
        <translation>Subdivision</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Hybrid, standard triangulation</source>
        <translation>Hybride, triangulation standard</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Hybrid, enhanced triangulation</source>
        <translation>Hybride, triangulation améliorée</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>Pareto front</source>
        <translation>Front de Pareto</translation>
    </message>
    <message>
        <location line="+214"/>
        <source>%1 on %2</source>
        <translation>%1 sur %2</translation>
    </message>
    <message numerus="yes">
        <location line="+1"/>
        <source>d = %1, snapping %2, %n relaxation step(s)</source>
        <translation>
            <numerusform>d = %1, accrochage %2, %n étape de relaxation</numerusform>
            <numerusform>d = %1, accrochage %2, %n étapes de relaxation</numerusform>
        </translation>
    </message>
    <message>
        <location line="+1"/>
        <source>on</source>
        <translation>activé</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>off</source>
        <translation>désactivé</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cut-face error: max %1, mean %2 mean edge lengths</source>
        <translation>Erreur de la face de coupe : max. %1, moyenne %2 longueurs d&apos;arête moyennes</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Tets: %1 (%2 added); worst radius ratio %3</source>
        <translation>Tétraèdres : %1 (%2 ajoutés) ; pire rapport des rayons %3</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Stable time step: %1 s</source>
        <translation>Pas de temps stable : %1 s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cut: %1 ms; simulation: %2 ms per simulated second</source>
        <translation>Coupe : %1 ms ; simulation : %2 ms par seconde simulée</translation>
    </message>
    <message>
        <location line="+68"/>
        <source>Cut time (ms, log scale)</source>
        <translation>Durée de la coupe (ms, échelle logarithmique)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Simulation cost (ms per simulated second, log scale)</source>
        <translation>Coût de la simulation (ms par seconde simulée, échelle logarithmique)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Cut-face error, max (mean edge lengths)</source>
        <translation>Erreur de la face de coupe, max. (longueurs d&apos;arête moyennes)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Run the study to see what accuracy costs.</source>
        <translation>Lancez l&apos;étude pour voir ce que coûte la précision.</translation>
    </message>
    <message>
        <location line="+52"/>
        <source>Zoomed: double-click to show all</source>
        <translation>Agrandi : double-cliquez pour tout afficher</translation>
    </message>
</context>
<context>
    <name>resect::AccuracyPanel</name>
    <message>
        <location filename="../widgets/accuracy_panel.cpp" line="+35"/>
        <source>Tiny (seconds)</source>
        <translation>Très rapide (secondes)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Quick (minutes)</source>
        <translation>Rapide (minutes)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>How many settings the study tries and how often it repeats each cut</source>
        <translation>Nombre de réglages essayés par l&apos;étude et nombre de répétitions de chaque coupe</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Simulation cost</source>
        <translation>Coût de la simulation</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Cut time</source>
        <translation>Durée de la coupe</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The cost on the horizontal axis: compute time per simulated second of the cut tissue, or the time of the cut itself</source>
        <translation>Le coût sur l&apos;axe horizontal : temps de calcul par seconde simulée du tissu coupé, ou durée de la coupe elle-même</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Run</source>
        <translation>Lancer</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Cut copies of the tissue with every method and setting of the preset</source>
        <translation>Coupe des copies du tissu avec chaque méthode et chaque réglage du préréglage</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cancel</source>
        <translation>Annuler</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>Adopt</source>
        <translation>Adopter</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Use the selected point&apos;s method, d, snapping and relaxation as the scenario&apos;s cut settings</source>
        <translation>Utiliser la méthode, d, l&apos;accrochage et la relaxation du point sélectionné comme paramètres de coupe du scénario</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Preset:</source>
        <translation>Préréglage :</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Cost:</source>
        <translation>Coût :</translation>
    </message>
    <message>
        <location line="+99"/>
        <source>Custom</source>
        <translation>Personnalisé</translation>
    </message>
    <message>
        <location line="+36"/>
        <source>Starting the study...</source>
        <translation>Démarrage de l&apos;étude...</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>Running: %1</source>
        <translation>En cours : %1</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Study cancelled: another document was opened.</source>
        <translation>Étude annulée : un autre document a été ouvert.</translation>
    </message>
    <message numerus="yes">
        <location line="+11"/>
        <source>Study finished: %n row(s).</source>
        <translation>
            <numerusform>Étude terminée : %n ligne.</numerusform>
            <numerusform>Étude terminée : %n lignes.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+2"/>
        <source>Study cancelled after %n row(s).</source>
        <translation>
            <numerusform>Étude annulée après %n ligne.</numerusform>
            <numerusform>Étude annulée après %n lignes.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Study failed: %1</source>
        <translation>Échec de l&apos;étude : %1</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Cancelling...</source>
        <translation>Annulation...</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Click a point of the chart to see its settings; drag a rectangle to zoom, double-click to show all.</source>
        <translation>Cliquez sur un point du graphique pour voir ses réglages ; tracez un rectangle pour agrandir, double-cliquez pour tout afficher.</translation>
    </message>
    <message numerus="yes">
        <location line="+4"/>
        <source>%1, d = %2, snapping %3, %n relaxation step(s): error max %4 mean edge lengths, %5 tets, cut %6 ms, simulation %7 ms per simulated second</source>
        <translation>
            <numerusform>%1, d = %2, accrochage %3, %n étape de relaxation : erreur max. %4 longueurs d&apos;arête moyennes, %5 tétraèdres, coupe %6 ms, simulation %7 ms par seconde simulée</numerusform>
            <numerusform>%1, d = %2, accrochage %3, %n étapes de relaxation : erreur max. %4 longueurs d&apos;arête moyennes, %5 tétraèdres, coupe %6 ms, simulation %7 ms par seconde simulée</numerusform>
        </translation>
    </message>
    <message>
        <location line="+4"/>
        <source>on</source>
        <translation>activé</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>off</source>
        <translation>désactivé</translation>
    </message>
    <message numerus="yes">
        <location line="+19"/>
        <source>Ready: %1 (%n tet(s)).</source>
        <translation>
            <numerusform>Prêt : %1 (%n tétraèdre).</numerusform>
            <numerusform>Prêt : %1 (%n tétraèdres).</numerusform>
        </translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Open a scenario with a tissue to run the study.</source>
        <translation>Ouvrez un scénario contenant un tissu pour lancer l&apos;étude.</translation>
    </message>
</context>
<context>
    <name>resect::AuthoringPanel</name>
    <message>
        <location filename="../widgets/authoring_panel.cpp" line="+20"/>
        <source>Pull loop: click on the tissue where the loop should cut deepest; drag to turn its opening. The loop is pulled from behind the tissue towards you.</source>
        <translation>Tirer l&apos;anse : cliquez sur le tissu là où l&apos;anse doit couper le plus profondément ; faites glisser pour tourner son ouverture. L&apos;anse est tirée de derrière le tissu vers vous.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Recording: drag the electrode forward across the view with the left button.</source>
        <translation>Enregistrement : faites glisser l&apos;électrode vers l&apos;avant à travers la vue avec le bouton gauche.</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Draw sweep</source>
        <translation>Dessiner une surface de balayage</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Click the points of the start curve; hold the button to drag a point into place. Drag any point to move it.</source>
        <translation>Cliquez les points de la courbe de départ ; maintenez le bouton enfoncé pour faire glisser un point à sa place. Faites glisser n&apos;importe quel point pour le déplacer.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>End curve</source>
        <translation>Courbe de fin</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Draw the end curve: click, in order, where each point of the start curve ends its path.</source>
        <translation>Tracer la courbe de fin : cliquez, dans l&apos;ordre, là où chaque point de la courbe de départ termine son trajet.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Record stroke</source>
        <translation>Enregistrer un geste</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Drag the electrode across the view with the left button.</source>
        <translation>Faites glisser l&apos;électrode à travers la vue avec le bouton gauche.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Pull loop</source>
        <translation>Tirer l&apos;anse</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Click on the tissue where the loop should cut deepest (drag to turn its opening): the loop is pulled from behind the tissue towards you, as a resectoscope&apos;s loop electrode, and takes off what lies inside it.</source>
        <translation>Cliquez sur le tissu là où l&apos;anse doit couper le plus profondément (faites glisser pour tourner son ouverture) : l&apos;anse est tirée de derrière le tissu vers vous, comme l&apos;anse électrique d&apos;un résectoscope, et enlève ce qui se trouve à l&apos;intérieur.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Finish</source>
        <translation>Terminer</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Use the drawn sweep surface.</source>
        <translation>Utiliser la surface de balayage dessinée.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Clear</source>
        <translation>Effacer</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Remove the drawn curves and the recorded stroke.</source>
        <translation>Supprimer les courbes dessinées et le geste enregistré.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Play stroke</source>
        <translation>Rejouer le geste</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Replay the last recorded stroke.</source>
        <translation>Rejouer le dernier geste enregistré.</translation>
    </message>
    <message>
        <location line="+51"/>
        <location line="+86"/>
        <source>Draw a sweep surface or record a stroke.</source>
        <translation>Dessinez une surface de balayage ou enregistrez un geste de coupe.</translation>
    </message>
    <message>
        <location line="-11"/>
        <source>Sweep surface handed on.</source>
        <translation>Surface de balayage transmise.</translation>
    </message>
    <message>
        <location line="+32"/>
        <source>Stroke recorded: %1 poses over %2 s.</source>
        <translation>Geste enregistré : %1 poses sur %2 s.</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>The sweep surface is valid: drag points to adjust it, or press Finish.</source>
        <translation>La surface de balayage est valide : faites glisser des points pour l&apos;ajuster, ou appuyez sur Terminer.</translation>
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
        <translation>Méthode</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Hybrid</source>
        <translation>Hybride</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Subdivision</source>
        <translation>Subdivision</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cutting method</source>
        <translation>Méthode de coupe</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Enhanced (symmetric)</source>
        <translation>Améliorée (symétrique)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Standard</source>
        <translation>Standard</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Face triangulation</source>
        <translation>Triangulation des faces</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Cut-node threshold d as a fraction of the mean edge length (the paper: 0.2)</source>
        <translation>Seuil d des nœuds de coupe, en fraction de la longueur d&apos;arête moyenne (dans l&apos;article : 0,2)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Threshold d</source>
        <translation>Seuil d</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Snap cut nodes onto the sweep</source>
        <translation>Accrocher les nœuds de coupe à la surface de balayage</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Relaxation steps</source>
        <translation>Étapes de relaxation</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Spring weight</source>
        <translation>Poids des ressorts</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Particle weight</source>
        <translation>Poids des particules</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Relaxation damping</source>
        <translation>Amortissement de la relaxation</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Relaxation rings</source>
        <translation>Anneaux de relaxation</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Mesh improvement</source>
        <translation>Amélioration du maillage</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Improve mesh after cut</source>
        <translation>Améliorer le maillage après la coupe</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>After every cut, improve the tets around it: collapse short edges and move nodes of bad tets, measured against the tissue as created</source>
        <translation>Après chaque coupe, améliorer les tétraèdres autour d&apos;elle : contracter les arêtes courtes et déplacer les nœuds des mauvais tétraèdres, par rapport au tissu tel que créé</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Tets whose radius ratio is below this factor times the worst of the tissue as created are improved (0: off; from 0 to %1)</source>
        <translation>Les tétraèdres dont le rapport des rayons est inférieur à ce facteur fois le pire du tissu tel que créé sont améliorés (0 : désactivé ; de 0 à %1)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Quality factor</source>
        <translation>Facteur de qualité</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Edges shorter than this factor times the shortest edge of the tissue as created are collapsed (0: off; from 0 to %1)</source>
        <translation>Les arêtes plus courtes que ce facteur fois l&apos;arête la plus courte du tissu tel que créé sont contractées (0 : désactivé ; de 0 à %1)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Short-edge factor</source>
        <translation>Facteur des arêtes courtes</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Edges shorter than this factor times the mean edge length (the unit of d) are collapsed where quality allows, so that repeated cuts do not keep adding tets (0: off; from 0 to %1)</source>
        <translation>Les arêtes plus courtes que ce facteur fois la longueur moyenne des arêtes (l&apos;unité de d) sont contractées là où la qualité le permet, pour que des coupes répétées n&apos;ajoutent pas sans cesse des tétraèdres (0 : désactivé ; de 0 à %1)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Coarsening factor</source>
        <translation>Facteur de déraffinement</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Preview</source>
        <translation>Aperçu</translation>
    </message>
    <message>
        <location line="+16"/>
        <location line="+260"/>
        <source>Inspect the worst tet</source>
        <translation>Inspecter le pire tétraèdre</translation>
    </message>
    <message>
        <location line="-258"/>
        <source>Shows the tet that limits the time step most in the quality dock&apos;s tet inspector; click again for the next</source>
        <translation>Affiche le tétraèdre qui limite le plus le pas de temps dans l&apos;inspecteur du panneau Qualité ; cliquez à nouveau pour le suivant</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Tets</source>
        <translation>Tétraèdres</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Added tets</source>
        <translation>Tétraèdres ajoutés</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cut edges</source>
        <translation>Arêtes coupées</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cut nodes</source>
        <translation>Nœuds de coupe</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Snapped nodes</source>
        <translation>Nœuds accrochés</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Decomposed tets</source>
        <translation>Tétraèdres décomposés</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Separated tets</source>
        <translation>Tétraèdres séparés</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Collapsed edges</source>
        <translation>Arêtes contractées</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Smoothed nodes</source>
        <translation>Nœuds lissés</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Removed tets</source>
        <translation>Tétraèdres supprimés</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Pieces</source>
        <translation>Morceaux</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Resected chips</source>
        <translation>Copeaux réséqués</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Resected volume (mm³)</source>
        <translation>Volume réséqué (mm³)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Resected mass (g)</source>
        <translation>Masse réséquée (g)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Min radius ratio</source>
        <translation>Rapport des rayons min.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Stable time step (s)</source>
        <translation>Pas de temps stable (s)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Intersect / select / decompose (ms)</source>
        <translation>Intersection / sélection / décomposition (ms)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Snap / relax / update (ms)</source>
        <translation>Accrochage / relaxation / mise à jour (ms)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Surface cut (ms)</source>
        <translation>Coupe de la surface (ms)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Mesh improvement (ms)</source>
        <translation>Amélioration du maillage (ms)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Total (ms)</source>
        <translation>Total (ms)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Apply cut</source>
        <translation>&amp;Appliquer la coupe</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Discard</source>
        <translation>A&amp;bandonner</translation>
    </message>
    <message>
        <location line="+76"/>
        <source>The last edit was undone: %1</source>
        <translation>La dernière modification a été annulée : %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The tissue or its cuts fail: %1</source>
        <translation>Le tissu ou ses coupes échouent : %1</translation>
    </message>
    <message>
        <location line="+61"/>
        <source>No pending cut. Draw a sweep or record a stroke to preview a cut.</source>
        <translation>Aucune coupe en attente. Dessinez une surface de balayage ou enregistrez un geste de coupe pour afficher l&apos;aperçu d&apos;une coupe.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The cut fails, it cannot be applied: %1</source>
        <translation>La coupe échoue, elle ne peut pas être appliquée : %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Computing the preview...</source>
        <translation>Calcul de l&apos;aperçu...</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Preview of the pending cut (not applied yet).</source>
        <translation>Aperçu de la coupe en attente (pas encore appliquée).</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>%1 (%2 refused)</source>
        <translation>%1 (%2 refusés)</translation>
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
        <translation>Cette coupe rend le pas de temps stable %1 fois plus petit (%2 s → %3 s) : une simulation explicite demande d&apos;autant plus de pas, et les tétraèdres en cause sont minuscules ou plats.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Snapping refused every cut node (%1 refused): the cut nodes stay where the sweep crossed the edges, as with subdivision, which leaves small and flat tets.</source>
        <translation>L&apos;accrochage a refusé chaque nœud de coupe (%1 refusés) : les nœuds de coupe restent là où la surface de coupe croise les arêtes, comme avec la subdivision, ce qui laisse des tétraèdres petits et plats.</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Tets that limit the time step, worst first: %1.</source>
        <translation>Tétraèdres qui limitent le pas de temps, le pire d&apos;abord : %1.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Warning: %1</source>
        <translation>Attention : %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Inspect the next (%1 of %2)</source>
        <translation>Inspecter le suivant (%1 sur %2)</translation>
    </message>
</context>
<context>
    <name>resect::CutPreview</name>
    <message>
        <location filename="../widgets/cut_preview.cpp" line="+82"/>
        <source>There is no cut to apply: draw a sweep or record a stroke first.</source>
        <translation>Il n&apos;y a aucune coupe à appliquer : dessinez d&apos;abord une surface de balayage ou enregistrez un geste de coupe.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The cut cannot be applied: %1</source>
        <translation>La coupe ne peut pas être appliquée : %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The preview of the cut is not ready yet: apply it once it is shown.</source>
        <translation>L&apos;aperçu de la coupe n&apos;est pas encore prêt : appliquez-la une fois qu&apos;il est affiché.</translation>
    </message>
    <message>
        <location line="+74"/>
        <source>Internal error: %1</source>
        <translation>Erreur interne : %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Internal error</source>
        <translation>Erreur interne</translation>
    </message>
</context>
<context>
    <name>resect::DisplayToolBar</name>
    <message>
        <location filename="../widgets/display_toolbar.cpp" line="+29"/>
        <source>Display</source>
        <translation>Affichage</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Display</source>
        <translation>&amp;Affichage</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Quality</source>
        <translation>Qualité</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Colour the tets by the quality overlay (Quality dock)</source>
        <translation>Colorer les tétraèdres selon la superposition de qualité (panneau Qualité)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Pieces</source>
        <translation>Morceaux</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Colour every piece the cuts made, resected chips included, in its own colour</source>
        <translation>Colorer chaque morceau issu des coupes, copeaux réséqués compris, de sa propre couleur</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Cut faces</source>
        <translation>Faces de coupe</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Draw the faces the cuts made in their own colour (and texture on the surface)</source>
        <translation>Dessiner les faces créées par les coupes dans leur propre couleur (et texture sur la surface)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Last cut</source>
        <translation>Dernière coupe</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Outline the tets the last cut produced or changed</source>
        <translation>Entourer les tétraèdres produits ou modifiés par la dernière coupe</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>How the pieces a cut took off the anchored tissue are drawn</source>
        <translation>Comment sont dessinés les morceaux qu&apos;une coupe a détachés du tissu fixé</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Show resected pieces</source>
        <translation>Afficher les morceaux réséqués</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Dim resected pieces</source>
        <translation>Atténuer les morceaux réséqués</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Hide resected pieces</source>
        <translation>Masquer les morceaux réséqués</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Shown</source>
        <translation>Affichés</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Dimmed</source>
        <translation>Atténués</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Hidden</source>
        <translation>Masqués</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Move the pieces apart from the tissue&apos;s centre (display only: the tissue is not changed)</source>
        <translation>Écarter les morceaux du centre du tissu (affichage seulement : le tissu n&apos;est pas modifié)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Explode pieces</source>
        <translation>Éclater les morceaux</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Colour:</source>
        <translation>Couleur :</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Resected:</source>
        <translation>Réséqués :</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Explode:</source>
        <translation>Éclatement :</translation>
    </message>
</context>
<context>
    <name>resect::DocumentOpener</name>
    <message>
        <location filename="../widgets/document_opener.cpp" line="+57"/>
        <source>%1: %2</source>
        <translation>%1 : %2</translation>
    </message>
</context>
<context>
    <name>resect::EffectParameterEditor</name>
    <message>
        <location filename="../widgets/effect_parameter_editor.cpp" line="+56"/>
        <source>Springs</source>
        <translation>Ressorts</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Springs on the edges (distance term)</source>
        <translation>Ressorts sur les arêtes (terme de distance)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Volume</source>
        <translation>Volume</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Volume preservation of every tet</source>
        <translation>Conservation du volume de chaque tétraèdre</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Area</source>
        <translation>Aire</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Area preservation of the boundary triangles</source>
        <translation>Conservation de l&apos;aire des triangles du bord</translation>
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
        <translation>La norme de l&apos;accélération ; sa direction est conservée</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Magnitude</source>
        <translation>Norme</translation>
    </message>
    <message>
        <location line="+10"/>
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Radius of the loop&apos;s wire: surface nodes closer to the tool&apos;s curve are pushed out</source>
        <translation>Rayon du fil de l&apos;anse : les nœuds de surface plus proches de la courbe de l&apos;outil sont repoussés</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Wire radius</source>
        <translation>Rayon du fil</translation>
    </message>
    <message>
        <location line="+9"/>
        <source> 1/s</source>
        <translation> 1/s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Mass-proportional damping f = -c m v: kinetic energy decays with the time constant 1/(2c)</source>
        <translation>Amortissement proportionnel à la masse f = -c m v : l&apos;énergie cinétique décroît avec la constante de temps 1/(2c)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Coefficient</source>
        <translation>Coefficient</translation>
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
    <name>resect::FixedRegionEditor</name>
    <message>
        <location filename="../widgets/fixed_region_editor.cpp" line="+35"/>
        <source>Add base box</source>
        <translation>Ajouter la boîte de base</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>A box around the bottom %1 % of the tissue&apos;s height</source>
        <translation>Une boîte autour des %1 % inférieurs de la hauteur du tissu</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Place in view</source>
        <translation>Placer dans la vue</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Draws the boxes in the view: drag a face&apos;s handle to move that face (red x, green y, blue z); drag elsewhere to turn the view</source>
        <translation>Dessine les boîtes dans la vue : faites glisser la poignée d&apos;une face pour déplacer cette face (rouge x, vert y, bleu z) ; glisser ailleurs fait tourner la vue</translation>
    </message>
    <message>
        <location line="+49"/>
        <source>Box %1 (mm)</source>
        <translation>Boîte %1 (mm)</translation>
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
        <translation>Supprimer</translation>
    </message>
    <message>
        <location line="+49"/>
        <source>A box can be added once the tissue is loaded.</source>
        <translation>Une boîte peut être ajoutée une fois le tissu chargé.</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>1 node of the uncut tissue</source>
        <translation>1 nœud du tissu non coupé</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 nodes of the uncut tissue</source>
        <translation>%1 nœuds du tissu non coupé</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Anchored nodes: not derived yet</source>
        <translation>Nœuds fixés : pas encore calculés</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>No fixed region: nothing is anchored.</source>
        <translation>Aucune région fixée : rien n&apos;est ancré.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>1 node anchored</source>
        <translation>1 nœud ancré</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 nodes anchored</source>
        <translation>%1 nœuds ancrés</translation>
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
        <translation>&amp;Fichier</translation>
    </message>
    <message>
        <location line="-28"/>
        <source>Simulation paused while a cut is previewed: apply or discard the cut, then play.</source>
        <translation>Simulation en pause pendant l&apos;aperçu d&apos;une coupe : appliquez ou abandonnez la coupe, puis lancez la lecture.</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Exported the mesh to %1</source>
        <translation>Maillage exporté vers %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+322"/>
        <source>The mesh was not exported.</source>
        <translation>Le maillage n&apos;a pas été exporté.</translation>
    </message>
    <message>
        <location line="-308"/>
        <source>&amp;New from sample</source>
        <translation>&amp;Nouveau à partir d&apos;un exemple</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Polyp</source>
        <translation>&amp;Polype</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Myoma</source>
        <translation>&amp;Myome</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&amp;Open...</source>
        <translation>&amp;Ouvrir...</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Import anatomy...</source>
        <translation>&amp;Importer une anatomie...</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Open &amp;recent</source>
        <translation>Ouvrir un fichier &amp;récent</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Save</source>
        <translation>&amp;Enregistrer</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Save &amp;as...</source>
        <translation>Enregistrer &amp;sous...</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Export for the trainer...</source>
        <translation>E&amp;xporter pour le simulateur d&apos;entraînement...</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Export &amp;mesh as...</source>
        <translation>Exporter le &amp;maillage sous...</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Quit</source>
        <translation>&amp;Quitter</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>&amp;Edit</source>
        <translation>É&amp;dition</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Undo</source>
        <translation>&amp;Annuler</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Redo</source>
        <translation>&amp;Rétablir</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>&amp;Cut</source>
        <translation>&amp;Coupe</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Apply pending cut</source>
        <translation>&amp;Appliquer la coupe en attente</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>&amp;Discard pending cut</source>
        <translation>A&amp;bandonner la coupe en attente</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Simulation</source>
        <translation>&amp;Simulation</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Play / pause</source>
        <translation>&amp;Lecture / pause</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>&amp;Step</source>
        <translation>&amp;Avancer d&apos;un pas</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Reset</source>
        <translation>&amp;Réinitialiser</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;View</source>
        <translation>&amp;Affichage</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Reset camera</source>
        <translation>&amp;Réinitialiser la caméra</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Show &amp;tet mesh</source>
        <translation>Afficher le maillage &amp;tétraédrique</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Show high-resolution &amp;surface</source>
        <translation>Afficher la &amp;surface haute résolution</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Display &amp;toolbar</source>
        <translation>&amp;Barre d&apos;affichage</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&amp;Language</source>
        <translation>&amp;Langue</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>System default</source>
        <translation>Langue du système</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Cut</source>
        <translation>Coupe</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Simulation</source>
        <translation>Simulation</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Accuracy vs time</source>
        <translation>Précision et temps</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Quality</source>
        <translation>Qualité</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Authoring</source>
        <translation>Création</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>%1 has unsaved changes. Save them?</source>
        <translation>%1 contient des modifications non enregistrées. Les enregistrer ?</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>Could not create the scenario.</source>
        <translation>Impossible de créer le scénario.</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>Mesh read: %1</source>
        <translation>Maillage lu : %1</translation>
    </message>
    <message>
        <location line="+14"/>
        <location line="+10"/>
        <source>The scenario was not saved.</source>
        <translation>Le scénario n&apos;a pas été enregistré.</translation>
    </message>
    <message>
        <location line="-7"/>
        <location line="+10"/>
        <source>Saved %1</source>
        <translation>%1 enregistré</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Save scenario</source>
        <translation>Enregistrer le scénario</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+8"/>
        <source>Scenarios (*.json)</source>
        <translation>Scénarios (*.json)</translation>
    </message>
    <message>
        <location line="-1"/>
        <source>Open scenario or anatomy</source>
        <translation>Ouvrir un scénario ou une anatomie</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Import anatomy</source>
        <translation>Importer une anatomie</translation>
    </message>
    <message>
        <location line="+13"/>
        <location line="+7"/>
        <location line="+73"/>
        <source>The scenario was not exported.</source>
        <translation>Le scénario n&apos;a pas été exporté.</translation>
    </message>
    <message>
        <location line="-80"/>
        <source>An export is already running.</source>
        <translation>Une exportation est déjà en cours.</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>The export could not be started.</source>
        <translation>L&apos;exportation n&apos;a pas pu démarrer.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Exporting to %1...</source>
        <translation>Exportation vers %1...</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Export for the trainer: choose or create an empty folder</source>
        <translation>Export pour le simulateur : choisir ou créer un dossier vide</translation>
    </message>
    <message>
        <location line="+115"/>
        <source>1 piece</source>
        <translation>1 morceau</translation>
    </message>
    <message numerus="yes">
        <location line="+0"/>
        <source>%n pieces</source>
        <translation>
            <numerusform>%n morceau</numerusform>
            <numerusform>%n morceaux</numerusform>
        </translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1: %2 nodes, %3 tets, %4, min radius ratio %5, stable dt %6 s</source>
        <translation>%1 : %2 nœuds, %3 tétraèdres, %4, rapport des rayons min. %5, pas de temps stable %6 s</translation>
    </message>
    <message numerus="yes">
        <location line="-71"/>
        <source>Exported %n file(s) to %1</source>
        <translation>
            <numerusform>%n fichier exporté vers %1</numerusform>
            <numerusform>%n fichiers exportés vers %1</numerusform>
        </translation>
    </message>
    <message>
        <location line="-84"/>
        <source>Surfaces (*.obj *.stl *.ply *.off *.glb *.gltf *.dae *.3ds *.fbx);;All files (*)</source>
        <translation>Surfaces (*.obj *.stl *.ply *.off *.glb *.gltf *.dae *.3ds *.fbx);;Tous les fichiers (*)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Surfaces (*.obj *.stl *.ply *.off *.glb *.gltf *.dae *.3ds *.fbx)</source>
        <translation>Surfaces (*.obj *.stl *.ply *.off *.glb *.gltf *.dae *.3ds *.fbx)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>All files (*)</source>
        <translation>Tous les fichiers (*)</translation>
    </message>
    <message>
        <location line="+38"/>
        <source>Export mesh as</source>
        <translation>Exporter le maillage sous</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>There is no tet mesh on show.</source>
        <translation>Aucun maillage tétraédrique n&apos;est affiché.</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>A mesh export is already running.</source>
        <translation>Un export de maillage est déjà en cours.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Exporting the mesh to %1...</source>
        <translation>Export du maillage vers %1...</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Export finished</source>
        <translation>Export terminé</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The trainer package is ready: the manifest lists every file with its SHA-256.</source>
        <translation>Le paquet pour le simulateur est prêt : le manifeste liste chaque fichier avec son SHA-256.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Open folder</source>
        <translation>Ouvrir le dossier</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Resect Studio did not close properly. Recover the unsaved changes to %1?</source>
        <translation>Resect Studio ne s&apos;est pas fermé correctement. Récupérer les modifications non enregistrées de %1 ?</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>an untitled scenario</source>
        <translation>un scénario sans titre</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The autosave could not be recovered.</source>
        <translation>La sauvegarde automatique n&apos;a pas pu être récupérée.</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>%1[*] - Resect Studio</source>
        <translation>%1[*] - Resect Studio</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Clear list</source>
        <translation>Effacer la liste</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Loading...</source>
        <translation>Chargement...</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>No tissue</source>
        <translation>Aucun tissu</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Loading and meshing the tissue...</source>
        <translation>Chargement et maillage du tissu...</translation>
    </message>
    <message>
        <location line="+10"/>
        <location line="+6"/>
        <source>Cancelling...</source>
        <translation>Annulation en cours...</translation>
    </message>
    <message>
        <location line="+44"/>
        <source>The language changes when Resect Studio is started again.</source>
        <translation>La langue changera au prochain démarrage de Resect Studio.</translation>
    </message>
    <message>
        <location line="-60"/>
        <source>Cancel</source>
        <translation>Annuler</translation>
    </message>
    <message>
        <location line="-505"/>
        <source>The tissue could not be loaded.</source>
        <translation>Le tissu n&apos;a pas pu être chargé.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The tissue or its cuts fail: %1</source>
        <translation>Le tissu ou ses coupes échouent : %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The last edit was undone: %1</source>
        <translation>La dernière modification a été annulée : %1</translation>
    </message>
    <message>
        <location line="+273"/>
        <source>Could not open %1.</source>
        <translation>Impossible d&apos;ouvrir %1.</translation>
    </message>
</context>
<context>
    <name>resect::MeshFiles</name>
    <message>
        <location filename="../widgets/mesh_files.cpp" line="+33"/>
        <source>Tet meshes (%1)</source>
        <translation>Maillages tétraédriques (%1)</translation>
    </message>
</context>
<context>
    <name>resect::QualityCurve</name>
    <message>
        <location filename="../widgets/quality_curve.cpp" line="+120"/>
        <source>The tissue as created: worst radius ratio %1</source>
        <translation>Le tissu tel que créé : pire rapport des rayons %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>After cut %1: worst radius ratio %2 (%3 × the input&apos;s)</source>
        <translation>Après la coupe %1 : pire rapport des rayons %2 (%3 × celui de l&apos;entrée)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Pending: not applied yet</source>
        <translation>En attente : pas encore appliquée</translation>
    </message>
    <message>
        <location line="+48"/>
        <source>Cut</source>
        <translation>Coupe</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Worst radius ratio / input&apos;s</source>
        <translation>Pire rapport des rayons / celui de l&apos;entrée</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>No tissue.</source>
        <translation>Aucun tissu.</translation>
    </message>
    <message>
        <location line="+32"/>
        <source>No cuts yet.</source>
        <translation>Aucune coupe pour l&apos;instant.</translation>
    </message>
</context>
<context>
    <name>resect::QualityHistogram</name>
    <message>
        <location filename="../widgets/quality_histogram.cpp" line="+173"/>
        <source>before</source>
        <translation>avant</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>after</source>
        <translation>après</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>log scale</source>
        <translation>échelle logarithmique</translation>
    </message>
</context>
<context>
    <name>resect::QualityMeasure</name>
    <message>
        <location filename="../widgets/quality_colors.cpp" line="+31"/>
        <source>None</source>
        <translation>Aucune</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Radius ratio</source>
        <translation>Rapport des rayons</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Min. dihedral (°)</source>
        <translation>Angle dièdre min. (°)</translation>
    </message>
</context>
<context>
    <name>resect::QualityPanel</name>
    <message>
        <location filename="../widgets/quality_panel.cpp" line="+45"/>
        <source>Display</source>
        <translation>Affichage</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Surface</source>
        <translation>Surface</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Wireframe</source>
        <translation>Fil de fer</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Shrunk tets</source>
        <translation>Tétraèdres réduits</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Mode</source>
        <translation>Mode</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Colour by</source>
        <translation>Couleur selon</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Auto</source>
        <translation>Auto</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Set the colour range to the range of the data</source>
        <translation>Régler la plage de couleurs sur l&apos;étendue des données</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Range</source>
        <translation>Plage</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Only tets worse than</source>
        <translation>Seulement les tétraèdres pires que</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Filter</source>
        <translation>Filtre</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Clip</source>
        <translation>Découper</translation>
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
        <translation>direction de vue</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Clipping</source>
        <translation>Découpage</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Inspect tets by clicking</source>
        <translation>Inspecter les tétraèdres par clic</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Logarithmic counts</source>
        <translation>Effectifs en échelle logarithmique</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Histogram</source>
        <translation>Histogramme</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Summary</source>
        <translation>Résumé</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The worst radius ratio of the tissue after each cut, relative to the tissue as created (a pending cut: hollow)</source>
        <translation>Le pire rapport des rayons du tissu après chaque coupe, relatif au tissu tel que créé (une coupe en attente : creuse)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Per cut</source>
        <translation>Par coupe</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Tet</source>
        <translation>Tétraèdre</translation>
    </message>
</context>
<context>
    <name>resect::QualitySummaryTable</name>
    <message>
        <location filename="../widgets/quality_summary_table.cpp" line="+26"/>
        <source>before</source>
        <translation>avant</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>after</source>
        <translation>après</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Nodes</source>
        <translation>Nœuds</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Edges</source>
        <translation>Arêtes</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Tets</source>
        <translation>Tétraèdres</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Min. radius ratio</source>
        <translation>Rapport des rayons min.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>tet_minAR (radius ratio / 3)</source>
        <translation>tet_minAR (rapport des rayons / 3)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Volume ratio Vmax/Vmin</source>
        <translation>Rapport des volumes Vmax/Vmin</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Edge ratio lmax/lmin</source>
        <translation>Rapport des arêtes lmax/lmin</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Min. dihedral (°)</source>
        <translation>Angle dièdre min. (°)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Max. dihedral (°)</source>
        <translation>Angle dièdre max. (°)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Stable dt (s)</source>
        <translation>dt stable (s)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Overlap (mm)</source>
        <translation>Chevauchement (mm)</translation>
    </message>
</context>
<context>
    <name>resect::ScenarioCommand</name>
    <message>
        <location filename="../widgets/scenario_commands.cpp" line="+83"/>
        <source>Change cut settings</source>
        <translation>Modifier les paramètres de coupe</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>Add stroke</source>
        <translation>Ajouter un geste de coupe</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Remove stroke</source>
        <translation>Supprimer le geste de coupe</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Add sweep</source>
        <translation>Ajouter une surface de balayage</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Remove sweep</source>
        <translation>Supprimer la surface de balayage</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>Switch effect on</source>
        <translation>Activer l&apos;effet</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Switch effect off</source>
        <translation>Désactiver l&apos;effet</translation>
    </message>
    <message>
        <location line="+50"/>
        <source>Change effect parameters</source>
        <translation>Modifier les paramètres des effets</translation>
    </message>
    <message>
        <location line="+35"/>
        <source>Change fixed regions</source>
        <translation>Modifier les régions fixées</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>Change title</source>
        <translation>Modifier le titre</translation>
    </message>
</context>
<context>
    <name>resect::ScenarioDocument</name>
    <message>
        <location filename="../widgets/scenario_document.cpp" line="+81"/>
        <source>untitled</source>
        <translation>sans titre</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>unknown sample &quot;%1&quot; (known: %2)</source>
        <translation>exemple « %1 » inconnu (connus : %2)</translation>
    </message>
    <message>
        <location line="+47"/>
        <source>New %1 scenario</source>
        <translation>Nouveau scénario %1</translation>
    </message>
    <message>
        <location line="-27"/>
        <source>%1: no such file</source>
        <translation>%1 : fichier introuvable</translation>
    </message>
    <message>
        <location line="+53"/>
        <source>the document has no file name yet (use Save As)</source>
        <translation>le document n&apos;a pas encore de nom de fichier (utilisez Enregistrer sous)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>no file name given</source>
        <translation>aucun nom de fichier indiqué</translation>
    </message>
    <message>
        <location line="+103"/>
        <source>cannot create the autosave folder &quot;%1&quot;</source>
        <translation>impossible de créer le dossier de sauvegarde automatique « %1 »</translation>
    </message>
    <message>
        <location line="+55"/>
        <source>there is no autosave to recover</source>
        <translation>aucune sauvegarde automatique à récupérer</translation>
    </message>
    <message>
        <location line="+248"/>
        <source>Remove the last fixed region</source>
        <translation>Supprimer la dernière région fixée</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Fix a region</source>
        <translation>Fixer une région</translation>
    </message>
</context>
<context>
    <name>resect::SimulationController</name>
    <message>
        <location filename="../widgets/simulation_controller.cpp" line="+166"/>
        <source>The simulation has no usable time step.</source>
        <translation>La simulation n&apos;a pas de pas de temps utilisable.</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>The simulation diverged at t = %1 s: %2</source>
        <translation>La simulation a divergé à t = %1 s : %2</translation>
    </message>
</context>
<context>
    <name>resect::SimulationPanel</name>
    <message>
        <location filename="../widgets/simulation_panel.cpp" line="+27"/>
        <source>Deformation (mass-spring)</source>
        <translation>Déformation (masses-ressorts)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Gravity</source>
        <translation>Gravité</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Fixed regions</source>
        <translation>Régions fixes</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Tool contact</source>
        <translation>Contact de l&apos;instrument</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Damping</source>
        <translation>Amortissement</translation>
    </message>
    <message>
        <location line="+15"/>
        <location line="+157"/>
        <source>Play</source>
        <translation>Lecture</translation>
    </message>
    <message>
        <location line="-155"/>
        <source>Step</source>
        <translation>Avancer d&apos;un pas</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Reset</source>
        <translation>Réinitialiser</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Effects in the scenario</source>
        <translation>Effets du scénario</translation>
    </message>
    <message>
        <location line="+36"/>
        <source>Cost</source>
        <translation>Coût</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Simulated time</source>
        <translation>Temps simulé</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Time step</source>
        <translation>Pas de temps</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Per step</source>
        <translation>Par pas</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Real time</source>
        <translation>Temps réel</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>The last edit was undone: %1</source>
        <translation>La dernière modification a été annulée : %1</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>Fixed regions: the tissue is not loaded yet, so its base cannot be anchored. Try again once it is shown.</source>
        <translation>Régions fixées : le tissu n&apos;est pas encore chargé, sa base ne peut donc pas être ancrée. Réessayez une fois qu&apos;il est affiché.</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>Pause</source>
        <translation>Pause</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>No tissue to simulate.</source>
        <translation>Aucun tissu à simuler.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Running.</source>
        <translation>En cours.</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Paused.</source>
        <translation>En pause.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 s (%2 steps)</source>
        <translation>%1 s (%2 pas)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 s (stable: %2 s)</source>
        <translation>%1 s (stable : %2 s)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1: %2 ms</source>
        <translation>%1 : %2 ms</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>integrator: %1 ms</source>
        <translation>intégrateur : %1 ms</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 ms per simulated second</source>
        <translation>%1 ms par seconde simulée</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>implicit, 1 iteration a step</source>
        <translation>implicite, 1 itération par pas</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>implicit, %1 iterations a step</source>
        <translation>implicite, %1 itérations par pas</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1x real time (%2)</source>
        <translation>%1x le temps réel (%2)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not measured yet (%1)</source>
        <translation>pas encore mesuré (%1)</translation>
    </message>
</context>
<context>
    <name>resect::StrokeRecorder</name>
    <message>
        <location filename="../widgets/stroke_recorder.cpp" line="+333"/>
        <source>Move forward along the pull to continue the stroke: no pose is taken behind its end (the stroke would cut through itself).</source>
        <translation>Avancez dans le sens du tirage pour continuer le geste : aucune pose n&apos;est prise derrière sa fin (le geste se couperait lui-même).</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>There is no tissue to pull the loop through.</source>
        <translation>Il n&apos;y a pas de tissu à travers lequel tirer l&apos;anse.</translation>
    </message>
    <message>
        <location line="+81"/>
        <source>The loop cannot be pulled here: it needs a tool with a loop curve and a tissue behind the cursor.</source>
        <translation>L&apos;anse ne peut pas être tirée ici : il faut un outil avec une courbe d&apos;anse et un tissu derrière le curseur.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The stroke is too short to cut: hold the left button and drag the electrode forward across the view.</source>
        <translation>Le geste est trop court pour couper : maintenez le bouton gauche et faites glisser l&apos;électrode vers l&apos;avant à travers la vue.</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>The recorded stroke does not make a usable cut: %1</source>
        <translation>Le geste enregistré ne donne pas une coupe utilisable : %1</translation>
    </message>
</context>
<context>
    <name>resect::SweepEditTool</name>
    <message>
        <location filename="../widgets/sweep_edit_tool.cpp" line="+100"/>
        <source>Alt+drag turns the view, Shift+drag pans, the wheel zooms.</source>
        <translation>Alt+glisser fait tourner la vue, Maj+glisser la déplace, la molette zoome.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Click on the tissue to place the first point of the start curve. %1</source>
        <translation>Cliquez sur le tissu pour placer le premier point de la courbe de départ. %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Start curve: click to place point 2; drag a point to move it. %1</source>
        <translation>Courbe de départ : cliquez pour placer le point 2 ; faites glisser un point pour le déplacer. %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Start curve: %1 points. Click to add point %2, or press End curve to draw where the tool ends. %3</source>
        <translation>Courbe de départ : %1 points. Cliquez pour ajouter le point %2, ou appuyez sur « Courbe de fin » pour tracer où l&apos;outil termine. %3</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>End curve: click where point %1 of %2 ends its path. %3</source>
        <translation>Courbe de fin : cliquez là où le point %1 sur %2 termine son trajet. %3</translation>
    </message>
    <message>
        <location line="+84"/>
        <source>The start curve needs at least two points; it has %1.</source>
        <translation>La courbe de départ nécessite au moins deux points ; elle en a %1.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The end curve needs at least two points; it has %1.</source>
        <translation>La courbe de fin nécessite au moins deux points ; elle en a %1.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The start curve has %1 points and the end curve %2; both need the same number of points.</source>
        <translation>La courbe de départ a %1 points et la courbe de fin %2 ; les deux doivent avoir le même nombre de points.</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Points %1 and %2 of the start curve coincide.</source>
        <translation>Les points %1 et %2 de la courbe de départ coïncident.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Points %1 and %2 of the end curve coincide.</source>
        <translation>Les points %1 et %2 de la courbe de fin coïncident.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>These curves do not make a usable sweep surface: %1</source>
        <translation>Ces courbes ne donnent pas une surface de balayage utilisable : %1</translation>
    </message>
</context>
<context>
    <name>resect::TetInspector</name>
    <message>
        <location filename="../widgets/tet_inspector.cpp" line="+25"/>
        <source>Tet</source>
        <translation>Tétraèdre</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Node %1</source>
        <translation>Nœud %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Reference volume</source>
        <translation>Volume de référence</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Current volume</source>
        <translation>Volume actuel</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Radius ratio</source>
        <translation>Rapport des rayons</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Min. dihedral (°)</source>
        <translation>Angle dièdre min. (°)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Max. dihedral (°)</source>
        <translation>Angle dièdre max. (°)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Min. edge</source>
        <translation>Arête min.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Max. edge</source>
        <translation>Arête max.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Scheme</source>
        <translation>Schéma</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>original</source>
        <translation>d&apos;origine</translation>
    </message>
</context>
<context>
    <name>resect::TissueSession</name>
    <message>
        <location filename="../widgets/tissue_session.cpp" line="+118"/>
        <source>There is no tissue to save.</source>
        <translation>Il n&apos;y a pas de tissu à enregistrer.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The tissue is still being derived from the last edit: save once it is shown.</source>
        <translation>Le tissu est encore en cours de calcul depuis la dernière modification : enregistrez une fois qu&apos;il est affiché.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The document&apos;s tissue or cuts fail: %1</source>
        <translation>Le tissu ou les coupes du document échouent : %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The tissue has not been derived yet.</source>
        <translation>Le tissu n&apos;a pas encore été calculé.</translation>
    </message>
    <message>
        <location line="+66"/>
        <location line="+358"/>
        <source>Opening was cancelled.</source>
        <translation>L&apos;ouverture a été annulée.</translation>
    </message>
    <message>
        <location line="-265"/>
        <source>Internal error: %1</source>
        <translation>Erreur interne : %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Internal error</source>
        <translation>Erreur interne</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>the scenario has no tissue</source>
        <translation>le scénario n&apos;a pas de tissu</translation>
    </message>
    <message>
        <location line="+93"/>
        <source>%1: %2</source>
        <translation>%1 : %2</translation>
    </message>
    <message>
        <location line="+120"/>
        <source>Checking the surface</source>
        <translation>Vérification de la surface</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Meshing (Delaunay refinement)</source>
        <translation>Maillage (raffinement de Delaunay)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Removing slivers (perturbation)</source>
        <translation>Suppression des slivers (perturbation)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Removing slivers (exudation)</source>
        <translation>Suppression des slivers (exsudation)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Matching the volume</source>
        <translation>Ajustement du volume</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Checking element quality</source>
        <translation>Vérification de la qualité des éléments</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 — attempt %2 of %3</source>
        <translation>%1 — tentative %2 sur %3</translation>
    </message>
</context>
<context>
    <name>resect::VtkViewport</name>
    <message>
        <location filename="../widgets/vtk_viewport.cpp" line="+114"/>
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
