"""Studies built on the models: charts, scenes, figures."""
